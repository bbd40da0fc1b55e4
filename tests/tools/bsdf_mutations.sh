#!/usr/bin/env bash
# Which tests catch a wrong constant in phong/bsdf.hpp (docs/bsdf.md, "Mutations"): each mutant is
# one edit of a copy of include/ (sed), then the BSDF unit tests (tests/bsdf.test.cpp, -O1), the
# chi-square test (tests/bsdf_chi2.cpp, -O2, 250000 samples x 20 directions) and the path-traced
# white furnace (benchmarks/demo/pathtrace.cpp) run against it. A mutant a test misses is a hole.
# Usage: tests/tools/bsdf_mutations.sh [build dir = build/mutations]   (about 10 min on 2 cores)
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(realpath -m "${1:-$root/build/mutations}")
mkdir -p "$out"
mutants=(
  "modified Phong normalization (m+2) -> (m+3) in f|s/(shininess + T(2)) \* detail::bsdf::inv_two_pi/(shininess + T(3)) * detail::bsdf::inv_two_pi/g"
  "modified Phong pdf (m+1) -> (m+2)|s/p \* (shininess + T(1)) \* detail::bsdf::inv_two_pi/p * (shininess + T(2)) * detail::bsdf::inv_two_pi/g"
  "sampling exponent 1/(m+1) -> 1/(m+2)|s/(double(m) + 1.0)/(double(m) + 2.0)/; s/detail::log(u) \/ (m + T(1))/detail::log(u) \/ (m + T(2))/"
  "Blinn-Phong normalization (m+4) -> (m+5)|s/((m + T(4)) \/ (detail::exp/((m + T(5)) \/ (detail::exp/"
)
for entry in "${mutants[@]}"; do
  name=${entry%%|*}; edit=${entry#*|}
  rm -rf "$out/include"; cp -r "$root/include" "$out/include"
  sed -i "$edit" "$out/include/phong/bsdf.hpp"
  if cmp -s "$root/include/phong/bsdf.hpp" "$out/include/phong/bsdf.hpp"; then echo "$name: the edit matched nothing"; exit 2; fi
  g++ -std=c++20 -O1 -I"$out/include" -I"$root/tests" "$root/tests/main.cpp" "$root/tests/bsdf.test.cpp" -o "$out/unit" || exit 2
  g++ -std=c++20 -O2 -DNDEBUG -I"$out/include" -I"$root/tests" "$root/tests/bsdf_chi2.cpp" -pthread -o "$out/chi2" || exit 2
  g++ -std=c++20 -O2 -DNDEBUG -I"$out/include" "$root/benchmarks/demo/pathtrace.cpp" -o "$out/pt" || exit 2
  unit=$("$out/unit" -ni -nv 2>&1 | grep -E '^\[doctest\] test cases' | sed 's/.*| *\([0-9]*\) failed.*/\1/')
  failed_cases=$("$out/unit" -ni 2>&1 | awk '/^TEST CASE:/ { sub(/^TEST CASE: */, ""); name = $0 } /ERROR:/ { print name }' | sort -u | tr '\n' ';')
  chi=$("$out/chi2" 250000 20 | tail -1 | sed 's/.*; \([0-9]*\) of.*/\1/')
  if "$out/pt" "$out/images" --spp 8 --size 160x120 >"$out/pt.txt" 2>&1; then furnace=pass; else furnace=FAIL; fi
  echo "$name: unit test cases failed: $unit ($failed_cases); chi-square (model, type, m) failed: $chi of 24; furnace: $furnace"
done
