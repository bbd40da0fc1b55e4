#!/usr/bin/env bash
# -ffast-math builds (docs/compilers.md, "-ffast-math"): g++ and clang++, -O3 -march=native
# -ffast-math, scalar and batch, and shade_batch at the x86-64 baseline (item 4). What each flag
# does to each mode is in docs/compilers.md; here:
#  1. the accuracy table (scalar): the exact and fast modes, and float's stable mode (precision =
#     wider), within their published bounds in every class, no NaN/inf for finite input. Linked with
#     -ffast-math, i.e. with FTZ/DAZ: the one documented exception is attenuation_c0_zero (a light
#     within 1e-19 of the point in float, 1e-154 in double), which the table reports and exempts;
#     the non_finite class is not checked (NaN and inf inputs give unspecified values there);
#  2. shade_batch's exact and fast lanes on every class (tests/batch_accuracy.test.cpp) and the
#     NaN-policy tests (tests/nan_policy.test.cpp) but those of NaN/inf inputs and outputs (the
#     documented -ffinite-math-only exception), compiled with -ffast-math and linked without it
#     (IEEE subnormals: FTZ/DAZ is item 1's exception), and fast::pow_unit inlined into a loop of
#     bases near 1 (tests/fast_math_loops.test.cpp);
#  3. the stable mode's twofold route (double; float with precision = twofold) refuses to compile,
#     naming the flag (tests/nan_policy/fast_math_reject.cpp);
#  4. item 2's batch and loop tests again without -march (SSE2, no FMA instructions), where
#     xsimd's SSE2 kernels and the lanes' Dekker products run (g++'s exact double p99 in
#     tiny_directional is checked on 3000 scenes there: tests/batch_accuracy.test.cpp).
#  5. the BSDFs (tests/bsdf.test.cpp: sampling within 4 ulps, sample's pdf equal to pdf(), the
#     furnace, no NaN or inf at the edges), compiled with -ffast-math and linked without it as in
#     item 2; reciprocity holds within 4 ulps there instead of bit for bit.
#  6. clang++ -ffast-math with one flag taken back (-fno-finite-math-only): clang then drops
#     __FAST_MATH__ but still reassociates. phong's barriers are on in every clang++ build, so the
#     exact and fast modes keep their bounds, scalar (the accuracy table) and lanes (item 2's
#     batch tests). The twofold route cannot see such flags (docs/compilers.md): not run here.
# clang++ uses the long-double reference (Debian's clang++ 14 has no quadmath.h).
# The compilers: g++, clang++ and g++ 11 (Ubuntu 22.04's), which says -ffast-math but not
# -fassociative-math (__FAST_MATH__, no __ASSOCIATIVE_MATH__); PHONG_CI_FAST_MATH=... to choose.
set -euo pipefail
mkdir -p build/fast-math
read -r -a compilers <<<"${PHONG_CI_FAST_MATH:-g++ clang++ g++-11}"
one_compiler() { # items 1 to 5 with compiler $1
  local cxx=$1 out flags libs base args case
  flags=(-std=gnu++20 -O3 -march=native -ffast-math -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests)
  libs=()
  if [[ $cxx == g++* ]]; then flags+=(-DPHONG_HAVE_QUADMATH=1); libs=(-lquadmath); fi
  out=build/fast-math/$cxx
  "$cxx" "${flags[@]}" tests/accuracy_table.cpp -o "$out-table" "${libs[@]}" &
  "$cxx" "${flags[@]}" -c tests/batch_accuracy.test.cpp -o "$out-batch.o" &
  wait
  "$cxx" "${flags[@]}" -c tests/main.cpp -o "$out-main.o" &
  "$cxx" "${flags[@]}" -c tests/nan_policy.test.cpp -o "$out-nan.o" &
  "$cxx" "${flags[@]}" -c tests/fast_math_loops.test.cpp -o "$out-loops.o" &
  wait
  "$cxx" "${flags[@]}" -c tests/bsdf.test.cpp -o "$out-bsdf.o"
  "$cxx" "$out-main.o" "$out-batch.o" "$out-nan.o" "$out-loops.o" -o "$out-tests" "${libs[@]}"
  "$cxx" "$out-main.o" "$out-bsdf.o" -o "$out-bsdf-tests" -pthread
  "$out-bsdf-tests" --no-intro | tail -n 2
  for args in "5000 3" "5000 4 --fast"; do
    # shellcheck disable=SC2086
    if ! "$out-table" $args --bounds >"$out-table.txt"; then grep "ABOVE BOUND" "$out-table.txt"; exit 1; fi
    echo "$cxx -ffast-math: accuracy table ($args): every class within its published bound"
  done
  "$out-tests" --no-intro -tce="*NaN or inf*,*overflowing light sum*" | tail -n 2
  for case in 1 2; do
    if "$cxx" -std=c++20 -fsyntax-only -ffast-math -Iinclude -DPHONG_REJECT_CASE=$case tests/nan_policy/fast_math_reject.cpp 2>"$out-reject.txt"; then
      echo "$cxx -ffast-math: the twofold route compiled (case $case)"; exit 1
    fi
    grep -q -- "-fno-associative-math" "$out-reject.txt"
  done
  echo "$cxx -ffast-math: the stable mode's twofold route refuses the build, naming -fno-associative-math"
  # 4. the x86-64 baseline (SSE2, no FMA): shade_batch point by point (its route there), and with
  #    -DPHONG_SIMD_WITHOUT_FMA on the SSE2 lanes (xsimd's SSE2 kernels and the Dekker products of
  #    the lanes' fma); fast::pow_unit in a loop, as in item 2. g++ 12 and clang++ only: g++ 11 is
  #    here for the macros it shows (items 1 to 3), and CI keeps under 40 minutes.
  [[ $cxx == g++-11 ]] && return 0
  base=(-std=gnu++20 -O3 -ffast-math -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests)
  if [[ $cxx == g++* ]]; then base+=(-DPHONG_HAVE_QUADMATH=1); fi
  "$cxx" "${base[@]}" -c tests/batch_accuracy.test.cpp -o "$out-base-batch.o" &
  "$cxx" "${base[@]}" -DPHONG_SIMD_WITHOUT_FMA -c tests/batch_accuracy.test.cpp -o "$out-base-lanes-batch.o" &
  wait
  "$cxx" "${base[@]}" -c tests/fast_math_loops.test.cpp -o "$out-base-loops.o"
  "$cxx" "$out-main.o" "$out-base-batch.o" "$out-base-loops.o" -o "$out-base-tests" "${libs[@]}"
  "$cxx" "$out-main.o" "$out-base-lanes-batch.o" -o "$out-base-lanes-tests" "${libs[@]}"
  "$out-base-tests" --no-intro | tail -n 2
  "$out-base-lanes-tests" --no-intro | tail -n 2
}
partial() { # item 6 (after clang++'s items: its tests/main.cpp object)
  local flags out
  flags=(-std=gnu++20 -O3 -march=native -ffast-math -fno-finite-math-only -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests)
  out=build/fast-math/clang++-partial
  clang++ "${flags[@]}" tests/accuracy_table.cpp -o "$out-table" &
  clang++ "${flags[@]}" -c tests/batch_accuracy.test.cpp -o "$out-batch.o" &
  wait
  if ! "$out-table" 5000 4 --fast --bounds >"$out-table.txt"; then grep "ABOVE BOUND" "$out-table.txt"; exit 1; fi
  echo "clang++ -ffast-math -fno-finite-math-only: accuracy table, exact and fast: every class within its published bound"
  clang++ build/fast-math/clang++-main.o "$out-batch.o" -o "$out-tests"
  "$out-tests" --no-intro -tc="*exact*,*fast*" | tail -n 2
}
# Two compilers at a time (each has serial parts), each into a log of its own, printed in order.
jobs=("${compilers[@]}")
[[ " ${compilers[*]} " == *" clang++ "* ]] && jobs+=(partial)
status=0
for ((i = 0; i < ${#jobs[@]}; i += 2)); do
  pids=()
  for job in "${jobs[@]:i:2}"; do
    if [[ $job == partial ]]; then partial >build/fast-math/partial.log 2>&1 &
    else one_compiler "$job" >"build/fast-math/$job.log" 2>&1 & fi
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid" || status=1; done
done
for job in "${jobs[@]}"; do cat "build/fast-math/$job.log"; done
if ((status)); then echo "36-fast-math: a build or check failed (its log above)"; exit 1; fi
