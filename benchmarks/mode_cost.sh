#!/usr/bin/env bash
# What each evaluation mode and number type costs against the lighting a renderer writes inline
# (docs/models.md, 'What each mode costs'): benchmarks/support/mode_cost.cpp's kernels, document
# 003's model, 1024 points x 4 positional lights. Instructions per (point, light) from callgrind
# (repeatable on any machine), and thread CPU time per (point, light), the median of interleaved
# rounds (noisy on a shared machine: read the ratios, not the times).
# Usage: benchmarks/mode_cost.sh [compiler] [flags...]     (default: g++ -O2)
set -euo pipefail
cd "$(dirname "$0")/.."
cxx=${1:-g++}; shift || true
flags=("$@"); ((${#flags[@]})) || flags=(-O2)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
exe=$tmp/mode_cost
"$cxx" -std=c++20 "${flags[@]}" -DNDEBUG -Iinclude -Ibenchmarks/support benchmarks/support/mode_cost.cpp -o "$exe"
pairs=4096
declare -A ir ns
for k in $("$exe" --list); do
  (cd "$tmp" && valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$k" --toggle-collect="$k" "$exe" "$k" >/dev/null 2>&1)
  ir[$k]=$(awk '/^summary:/ {print $2}' "$tmp/cg.$k")
done
while read -r k t; do ns[$k]=$t; done < <("$exe" --time 31)
cpu=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
echo "$cxx ${flags[*]}, $cpu; instructions and ns per (point, light); ratio = phong / the inline lighting of the same type"
echo
echo "| mode | type | shade<F>: instr (ratio) | shade<F>: ns (ratio) | shade_incident<F>: instr (ratio) | shade_incident<F>: ns (ratio) |"
echo "|---|---|--:|--:|--:|--:|"
for T in float double; do
  for m in exact stable fast; do
    s=mc_shade_${m}_$T; i=mc_incident_${m}_$T; a=mc_inline_$T; b=mc_inline_incident_$T
    awk -v m=$m -v T=$T -v si="${ir[$s]}" -v ai="${ir[$a]}" -v ii="${ir[$i]}" -v bi="${ir[$b]}" \
        -v st="${ns[$s]}" -v at="${ns[$a]}" -v it="${ns[$i]}" -v bt="${ns[$b]}" -v p=$pairs \
      'BEGIN { printf "| %s | %s | %.1f (%.2f) | %.2f (%.2f) | %.1f (%.2f) | %.2f (%.2f) |\n", m, T, si/p, si/ai, st, st/at, ii/p, ii/bi, it, it/bt }'
  done
done
for T in float double; do
  a=mc_inline_$T; b=mc_inline_incident_$T
  awk -v T=$T -v ai="${ir[$a]}" -v bi="${ir[$b]}" -v at="${ns[$a]}" -v bt="${ns[$b]}" -v p=$pairs \
    'BEGIN { printf "| inline lighting | %s | %.1f | %.2f | %.1f | %.2f |\n", T, ai/p, at, bi/p, bt }'
done
