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
for cxx in g++ clang++; do
  files=(main batch_accuracy.test power.test lanes_power.test fast_math.test)
  if [ "$cxx" = g++ ]; then
    compiler=(aarch64-linux-gnu-g++)
  else
    compiler=(clang++ --target=aarch64-linux-gnu)
    files+=(batch.test) # clang++ only: g++ 12 takes over 3 CPU minutes per build of it, clang++ one
  fi
  for opt in -O2 -O3; do
    # the BSDFs (docs/bsdf.md): clang++ -O3 only, where they run below
    if [ "$cxx$opt" = clang++-O3 ]; then files+=(bsdf.test); fi
    dir=$out/$cxx$opt
    mkdir -p "$dir"
    flags=(-std=gnu++20 "$opt" -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests -isystem "$out/include")
    printf '%s\n' "${files[@]}" |
      xargs -P2 -I{} "${compiler[@]}" "${flags[@]}" -c tests/{}.cpp -o "$dir/{}.o"
    objects=("${files[@]/#/$dir/}")
    "${compiler[@]}" "${objects[@]/%/.o}" -o "$dir/tests"
    echo "aarch64 $cxx $opt: built ($((SECONDS - start)) s)"
  done
done
# The four test binaries under qemu (one thread each), two runs at a time, the longest first so that
# both finish together. The fast kernels' three sweeps against the long-double reference (binary128,
# in software on aarch64) run in the g++ -O2 build; the others run every other test case. The BSDF
# tests run from the clang++ -O3 build, in two runs of their own (their check of the lobe's sin a
# and 1 - cos a against long double takes half of their time), less "pdf integrates to 1", a
# numerical integral whose tolerance is far above any rounding difference (28 % of their time; it
# runs on x86-64 in steps 10 and 30).
sweeps='*fast::pow_unit: within pow_unit_max_rel*,*fast::pow_integer: within*,*fast::rsqrt: within rsqrt_max_rel over every float*'
lobe='*within 4 ulps of a long double reference*'
runs=("clang++-O3-bsdf-lobe|clang++-O3|-tc=$lobe" "clang++-O3-bsdf|clang++-O3|-tc=bsdf:*|-tce=$lobe,*pdf integrates to 1*" "g++-O2|g++-O2"
      "clang++-O2|clang++-O2|-tce=$sweeps" "g++-O3|g++-O3|-tce=$sweeps" "clang++-O3|clang++-O3|-tce=$sweeps,bsdf:*")
run() { # run "NAME|BUILD|doctest options...": the build's tests under qemu, output to NAME.log
  local f
  IFS='|' read -r -a f <<<"$1"
  qemu-aarch64 -L /usr/aarch64-linux-gnu "build/aarch64/${f[1]}/tests" --no-intro "${f[@]:2}" >"build/aarch64/${f[0]}.log" 2>&1
}
export -f run
printf '%s\n' "${runs[@]}" | xargs -P2 -d '\n' -I{} bash -c 'run "$1"' _ {} || status=$?
for r in "${runs[@]}"; do
  echo "aarch64 ${r%%|*}:"
  tail -n 2 "$out/${r%%|*}.log"
done
if [ "${status:-0}" != 0 ]; then grep -B2 -A4 "ERROR" "$out"/*.log | head -n 60; exit 1; fi
echo "aarch64: the tests passed in all four builds ($((SECONDS - start)) s)"
# No call into xsimd in the NEON code (docs/compilers.md, "aarch64": g++ 12 kept xsimd 8.1's bit
# casts and shifts as calls until ext/simd/backend.hpp defined them for neon64).
for config in g++-O2 g++-O3 clang++-O2 clang++-O3; do
  calls=$(aarch64-linux-gnu-objdump -d "$out/$config/tests" | grep -c 'bl[[:space:]].*<_ZN5xsimd' || true)
  [ "$calls" = 0 ] || { echo "aarch64 $config: $calls calls into xsimd"; exit 1; }
done
echo "aarch64: no call into xsimd in the four builds"
# The hand-written NEON kernel of the aarch64 instruction counts (docs/batch.md, "aarch64") computes
# shade<F>'s model: benchmarks/insn_count.cpp fails if it leaves its tolerance (clang++ -O2, ~10 s).
clang++ --target=aarch64-linux-gnu -std=gnu++20 -O2 -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Ibenchmarks \
        -isystem "$out/include" benchmarks/insn_count.cpp -o "$out/phong_insn_count"
for model in phong blinn; do qemu-aarch64 -L "$sysroot" "$out/phong_insn_count" hand exact $model 1024 4 1 check; done
echo "aarch64: all in $((SECONDS - start)) s"
# riscv64 (docs/compilers.md, "Other targets"), g++ 12 (riscv64-linux-gnu-g++) under qemu-riscv64:
# xsimd 8.1 has no lanes there (shade_batch shades one point at a time), so every header is parsed
# alone, and the scalar power kernels give constant evaluation's bits at run time although the
# target contracts a * b + c by default (tests/power.test.cpp).
if command -v riscv64-linux-gnu-g++ >/dev/null; then
  rv=build/riscv64
  mkdir -p "$rv"
  rvflags=(-std=gnu++20 -O2 -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests -isystem "$out/include")
  find include/phong -name '*.hpp' ! -name 'diagnostics_*' | sort |
    xargs -P2 -I{} riscv64-linux-gnu-g++ "${rvflags[@]}" -fsyntax-only -include {} -x c++ /dev/null
  printf '%s\n' main power.test | xargs -P2 -I{} riscv64-linux-gnu-g++ "${rvflags[@]}" -c tests/{}.cpp -o "$rv/{}.o"
  riscv64-linux-gnu-g++ "$rv/main.o" "$rv/power.test.o" -o "$rv/tests"
  qemu-riscv64 -L /usr/riscv64-linux-gnu "$rv/tests" --no-intro | tail -n 2
  echo "riscv64: every header alone and the power kernels' tests pass ($((SECONDS - start)) s)"
fi
