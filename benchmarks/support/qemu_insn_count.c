/* A QEMU TCG plugin that counts the guest instructions a program executes (user mode), for
 * docs/batch.md's aarch64 instruction counts (qemu-aarch64 has no performance counters, and
 * Debian's qemu-user ships no plugins of its own, but its binaries load plugins). Each translated
 * block adds its instruction count to a total every time it runs (an inline add, no callback); the
 * total is printed to stderr at exit:  "qemu_insn_count: <n> instructions".
 * Build (host compiler, against QEMU 7.2's plugin API, version 1; the few declarations it needs are
 * written out below, so no QEMU headers are needed):
 *   cc -shared -fPIC -O2 -o build/a64/libinsncount.so benchmarks/support/qemu_insn_count.c
 * Use: qemu-aarch64 -L /usr/aarch64-linux-gnu -plugin build/a64/libinsncount.so ./program
 */
#include <stdint.h>
#include <stdio.h>
#include <stddef.h>

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
typedef struct qemu_info_t qemu_info_t;
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

/* QEMU's plugin API (include/qemu/qemu-plugin.h), resolved from the qemu-aarch64 binary at load. */
extern void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id,
                                                  void (*cb)(qemu_plugin_id_t id, struct qemu_plugin_tb* tb));
extern size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb* tb);
extern void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb* tb, enum qemu_plugin_op op, void* ptr,
                                                     uint64_t imm);
extern void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, void (*cb)(qemu_plugin_id_t id, void* userdata),
                                           void* userdata);

__attribute__((visibility("default"))) int qemu_plugin_version = 1;

static uint64_t executed; /* one guest thread: the programs measured are single-threaded */

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb* tb)
{
    (void)id;
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &executed, qemu_plugin_tb_n_insns(tb));
}

static void on_exit(qemu_plugin_id_t id, void* userdata)
{
    (void)id, (void)userdata;
    fprintf(stderr, "qemu_insn_count: %llu instructions\n", (unsigned long long)executed);
}

__attribute__((visibility("default"))) int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t* info, int argc,
                                                               char** argv)
{
    (void)info, (void)argc, (void)argv;
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
