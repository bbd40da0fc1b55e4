#!/usr/bin/env bash
# aarch64 (issue 35): the tests of every route that differs there, cross-compiled with g++ 12
# (aarch64-linux-gnu-g++) and clang++ 14 (--target=aarch64-linux-gnu, Debian's cross libstdc++
# and glibc under /usr/aarch64-linux-gnu), -O2 and -O3, run under qemu-aarch64 with the same
# assertions as on x86-64:
#  - tests/batch_accuracy.test.cpp: shade_batch's NEON lanes (4 floats, 2 doubles), every mode
#    (exact; stable: float's double-lane route, double's twofold lanes; fast), every stiff and
#    extreme class, against the published bounds and the long-double reference (IEEE binary128 on
#    aarch64: 113 bits);
#  - tests/power.test.cpp: the scalar power kernels, and "constant evaluation and run time give the
#    same bits" (both compilers contract a * b + c into fused instructions by default there);
#  - tests/lanes_power.test.cpp, tests/fast_math.test.cpp: the lanes' powers, fast::rsqrt and the
#    fast kernels on lanes and scalars, against their bounds;
#  - tests/batch.test.cpp (clang++ builds): the batch API at width 4 (tails, layouts, tables,
#    bit-for-bit promises: one kernel serves every layout, so they hold with contraction too).
# Not built here: the RapidCheck property tests (Debian has no aarch64 librapidcheck) and the
# scalar API's bit-for-bit checks that hold only without FMA contraction (docs/compilers.md, "FMA
# contraction"), which aarch64 always has.
# One object per test file and configuration; the host's header-only libraries (doctest, GLM,
# xsimd) through one -isystem folder of links (the host's /usr/include would bring x86 glibc).
set -euo pipefail
sysroot=/usr/aarch64-linux-gnu
out=build/aarch64
mkdir -p "$out/include"
for d in doctest glm xsimd rapidcheck rapidcheck.h; do ln -sfn "/usr/include/$d" "$out/include/$d"; done
start=$SECONDS
# One ninja graph, two jobs at a time: every compile, link and qemu run of the four builds, the NEON
# hand kernel's check, and riscv64, so that each run starts once its build is linked while the other
# core compiles. Ninja 1.11 starts, of the steps that are ready, the one declared first: the clang++
# -O3 build and its long BSDF runs come first, then each build and its run, heaviest files first.
# The fast kernels' three sweeps against the long-double reference (binary128, in software on
# aarch64) run in the g++ -O2 build; the others run every other test case. The BSDF tests run from
# the clang++ -O3 build, in two runs of their own (one: the lobe's sin a and 1 - cos a against long
# double, binary128 in software here), less "pdf integrates to 1", a numerical integral whose
# tolerance is far above any rounding difference (28 % of their time; it runs on x86-64 in steps 10
# and 30).
# riscv64 (docs/compilers.md, "Other targets"), g++ 12 under qemu-riscv64: xsimd 8.1 has no lanes
# there (shade_batch shades one point at a time), so every header is parsed alone, and the scalar
# power kernels give constant evaluation's bits at run time although the target contracts a * b + c
# by default (tests/power.test.cpp).
# The hand-written NEON kernel of the aarch64 instruction counts (docs/batch.md, "aarch64") computes
# shade<F>'s model: benchmarks/insn_count.cpp fails if it leaves its tolerance.
python3 - "$out" "$sysroot" >"$out/build.ninja" <<'EOF'
import glob, os, shlex, shutil, sys
out, sysroot = sys.argv[1:3]
sweeps = ("*fast::pow_unit: within pow_unit_max_rel*,*pow_integer: within*,"
          "*fast::rsqrt: within rsqrt_max_rel over every float*")
lobe = "*within 4 ulps of a long double reference*"
runs = {"clang++-O3": [("clang++-O3-bsdf-lobe", ["-tc=" + lobe]),
                       ("clang++-O3-bsdf", ["-tc=bsdf:*", "-tce=" + lobe + ",*pdf integrates to 1*"]),
                       ("clang++-O3", ["-tce=" + sweeps + ",bsdf:*"])],
        "g++-O2": [("g++-O2", [])],
        "clang++-O2": [("clang++-O2", ["-tce=" + sweeps])],
        "g++-O3": [("g++-O3", ["-tce=" + sweeps])]}
common = f"-std=gnu++20 -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests -isystem {out}/include"
clang = "clang++ --target=aarch64-linux-gnu"
aarch64 = f"qemu-aarch64 -L {sysroot}"
print(f"""builddir = {out}
rule cxx
  command = $cxx {common} $opt -MD -MF $out.d -c $in -o $out
  depfile = $out.d
  deps = gcc
  description = $cxx $opt $in
rule link
  command = $cxx $in -o $out
  description = link $out
rule run
  command = $qemu $bin $args >$log 2>&1 && touch $out
  description = run $log
rule parse
  command = riscv64-linux-gnu-g++ {common} -O2 -fsyntax-only -include $in -x c++ /dev/null && touch $out
  description = riscv64 parse $in""")
def program(binary, cxx, sources, opt):  # each (source, name) compiled to name.o beside binary, linked
    objects = []
    for source, name in sources:
        objects.append(f"{os.path.dirname(binary)}/{name}.o")
        print(f"build {objects[-1]}: cxx {source}\n  cxx = {cxx}\n  opt = {opt}")
    print(f"build {binary}: link {' '.join(objects)}\n  cxx = {cxx}")
def run(stamp, qemu, binary, args, log):  # binary under qemu, its output to log
    print(f"build {stamp}: run {binary}\n  qemu = {qemu}\n  bin = {binary}\n  args = {args}\n  log = {log}")
for config in runs:
    files = ["batch_accuracy.test", "fast_math.test", "lanes_power.test", "power.test", "main"]
    if config.startswith("clang"):
        files.insert(0, "batch.test")  # clang++ only: g++ 12 takes over 3 CPU minutes per build of it
    if config == "clang++-O3":
        files.insert(0, "bsdf.test")  # the BSDFs (docs/bsdf.md): built and run here only
    program(f"{out}/{config}/tests", clang if config.startswith("clang") else "aarch64-linux-gnu-g++",
            [(f"tests/{f}.cpp", f) for f in files], "-" + config.split("-")[-1])
    for name, args in runs[config]:
        run(f"{out}/{name}.ok", aarch64, f"{out}/{config}/tests",
            " ".join(["--no-intro"] + [shlex.quote(a) for a in args]), f"{out}/{name}.log")
program(f"{out}/phong_insn_count", f"{clang} -Ibenchmarks", [("benchmarks/insn_count.cpp", "insn_count")], "-O2")
for model in ("phong", "blinn"):
    run(f"{out}/hand-{model}.ok", aarch64, f"{out}/phong_insn_count", f"hand exact {model} 1024 4 1 check",
        f"{out}/hand-{model}.log")
if shutil.which("riscv64-linux-gnu-g++"):
    rv = "build/riscv64"
    for h in sorted(glob.glob("include/phong/**/*.hpp", recursive=True)):
        if not os.path.basename(h).startswith("diagnostics_"):
            print(f"build {rv}/parse/{h.replace('/', '_')}.ok: parse {h}")
    program(f"{rv}/tests", "riscv64-linux-gnu-g++", [(f"tests/{f}.cpp", f) for f in ("power.test", "main")], "-O2")
    run(f"{rv}/tests.ok", "qemu-riscv64 -L /usr/riscv64-linux-gnu", f"{rv}/tests", "--no-intro", f"{rv}/tests.log")
EOF
ninja -f "$out/build.ninja" -j2 -k 0 >"$out/ninja.txt" 2>&1 || status=$?
for log in "$out"/*.log build/riscv64/tests.log; do
  [[ -f $log ]] || continue
  echo "${log%.log}:"
  tail -n 2 "$log"
done
if [ "${status:-0}" != 0 ]; then
  grep -A12 "FAILED" "$out/ninja.txt" | head -n 60
  grep -B2 -A4 "ERROR" "$out"/*.log | head -n 60
  exit 1
fi
echo "aarch64: the tests passed in all four builds, and riscv64's (every header alone, the power kernels) ($((SECONDS - start)) s)"
# No call into xsimd in the NEON code (docs/compilers.md, "aarch64": g++ 12 kept xsimd 8.1's bit
# casts and shifts as calls until ext/simd/backend.hpp defined them for neon64).
for config in g++-O2 g++-O3 clang++-O2 clang++-O3; do
  calls=$(aarch64-linux-gnu-objdump -d "$out/$config/tests" | grep -c 'bl[[:space:]].*<_ZN5xsimd' || true)
  [ "$calls" = 0 ] || { echo "aarch64 $config: $calls calls into xsimd"; exit 1; }
done
echo "aarch64: no call into xsimd in the four builds"
