// Which AVX-512 instructions share the FMA units: a loop of eight independent 512-bit FMAs, then
// the same loop with four more instructions of one kind, time per iteration relative to the FMAs
// alone. About 1.0: the instruction runs beside the FMAs; about 1.5: it takes an FMA cycle (on
// Zen 4 compares into mask registers, vfpclass, rsqrt14 / rcp14 and masked multiplies do; max,
// min, logic, integer adds and shifts, scalef, blends and moves do not). docs/batch.md uses it
// to count a light loop's multiplier operations.
// Usage: build/bench/benchmarks/phong_multiplier_slots
#include <chrono>
#include <cstdio>

#if defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512VL__) && (defined(__x86_64__) || defined(__i386__))
namespace {

#  define PHONG_FMA8                                                                                                         \
      "vfmadd231ps %%zmm1, %%zmm2, %%zmm10\n\tvfmadd231ps %%zmm1, %%zmm2, %%zmm11\n\t"                                     \
      "vfmadd231ps %%zmm1, %%zmm2, %%zmm12\n\tvfmadd231ps %%zmm1, %%zmm2, %%zmm13\n\t"                                     \
      "vfmadd231ps %%zmm1, %%zmm2, %%zmm14\n\tvfmadd231ps %%zmm1, %%zmm2, %%zmm15\n\t"                                     \
      "vfmadd231ps %%zmm1, %%zmm2, %%zmm16\n\tvfmadd231ps %%zmm1, %%zmm2, %%zmm17\n\t"
#  define PHONG_X4(s) s "\n\t" s "\n\t" s "\n\t" s "\n\t"
#  define PHONG_CLOBBERS "xmm1", "xmm2", "xmm3", "xmm4", "xmm10", "xmm11", "xmm12", "xmm13", "xmm14", "xmm15", "xmm16", "xmm17"
#  define PHONG_TIME(body)                                                                                                   \
      [] {                                                                                                                   \
          const auto t0 = std::chrono::steady_clock::now();                                                                  \
          for (long i = 0; i < 100000000; ++i) __asm__ volatile(body ::: PHONG_CLOBBERS);                                    \
          return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();                               \
      }()

} // namespace

int main()
{
    double best_fma = 1e30;
    for (int r = 0; r < 3; ++r) {
        const double t = PHONG_TIME(PHONG_FMA8);
        best_fma = t < best_fma ? t : best_fma;
    }
    std::printf("time per iteration relative to 8 FMAs alone (about 1.0: beside the FMAs; 1.5: one FMA cycle each)\n");
    const auto row = [&](const char* name, double t) { std::printf("  8 FMAs + 4 %-12s %.2f\n", name, t / best_fma); };
    row("vcmpps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vcmpgt_oqps %%zmm1, %%zmm2, %%k1")));
    row("vpcmpd", PHONG_TIME(PHONG_FMA8 PHONG_X4("vpcmpgtd %%zmm1, %%zmm2, %%k1")));
    row("vfpclassps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vfpclassps $0xff, %%zmm1, %%k1")));
    row("vrsqrt14ps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vrsqrt14ps %%zmm1, %%zmm3")));
    row("vrcp14ps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vrcp14ps %%zmm1, %%zmm3")));
    row("vmulps{z}", PHONG_TIME(PHONG_FMA8 PHONG_X4("vmulps %%zmm1, %%zmm2, %%zmm3%{%%k1%}%{z%}")));
    row("vmaxps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vmaxps %%zmm1, %%zmm2, %%zmm3")));
    row("vaddps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vaddps %%zmm1, %%zmm2, %%zmm3")));
    row("vpternlogd", PHONG_TIME(PHONG_FMA8 PHONG_X4("vpternlogd $0x96, %%zmm1, %%zmm2, %%zmm3")));
    row("vpaddd", PHONG_TIME(PHONG_FMA8 PHONG_X4("vpaddd %%zmm1, %%zmm2, %%zmm3")));
    row("vscalefps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vscalefps %%zmm1, %%zmm2, %%zmm3")));
    row("vblendmps", PHONG_TIME(PHONG_FMA8 PHONG_X4("vblendmps %%zmm1, %%zmm2, %%zmm4%{%%k1%}")));
}
#else
int main()
{
    std::printf("phong_multiplier_slots: needs AVX-512 (F, DQ, VL) on x86\n");
}
#endif
