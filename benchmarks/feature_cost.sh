#!/usr/bin/env bash
# A removed feature costs nothing: instruction counts (valgrind --tool=callgrind, repeatable) of
# phong::shade<F> kernels against hand-written kernels of the same model, and the instruction cost
# of each feature. The kernels are in benchmarks/support/feature_cost.cpp (1024 points x 4 lights,
# extern "C" noinline functions; --toggle-collect counts one kernel and the libm calls it makes).
#
# Usage: benchmarks/feature_cost.sh [build-dir]     (default build/bench; configured and built as needed)
# Writes <build-dir>/feature_cost.tsv (kernel, instructions, per pair) for benchmarks/report.py.
# Exit status 1 when a pair differs by more than 2 % or the pair's outputs are not bit for bit equal.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench}
exe=$build/benchmarks/phong_feature_cost
# Configured if missing, and always brought up to date (a stale binary would count old headers).
[[ -f $build/CMakeCache.txt ]] || cmake --preset bench -B "$build" >/dev/null
cmake --build "$build" --target phong_feature_cost -j2 >/dev/null
command -v valgrind >/dev/null || { echo "feature_cost.sh: valgrind not found (apt-get install valgrind)"; exit 2; }

pairs=4096 # 1024 points x 4 lights
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tsv=$build/feature_cost.tsv
: >"$tsv"

count() { # instructions of kernel $1 (inclusive of its libm calls)
  (cd "$tmp" && valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$1" --toggle-collect="$1" "$OLDPWD/$exe" "$1" >/dev/null 2>&1)
  awk '/^summary:/ {print $2}' "$tmp/cg.$1"
}

echo "Outputs of each pair (compiled with -ffp-contract=off so both round identically):"
"$exe" --check | sed 's/^/  /' || check_failed=1

declare -A ir
for k in $("$exe" --list); do
  ir[$k]=$(count "$k")
  printf '%s\t%s\t%.1f\n' "$k" "${ir[$k]}" "$(echo "${ir[$k]} / $pairs" | bc -l)" >>"$tsv"
done

status=0
echo
echo "A removed feature costs nothing: phong vs a hand-written kernel of the same model (target: within 2 %)"
printf '  %-30s %-30s %12s %12s %8s  %s\n' phong hand "phong Ir" "hand Ir" "diff" verdict
for pair in "fc_phong_diffuse_directional fc_hand_diffuse_directional" "fc_phong_ads fc_hand_ads"; do
  set -- $pair
  diff=$(echo "100 * (${ir[$1]} - ${ir[$2]}) / ${ir[$2]}" | bc -l)
  verdict=PASS
  if (( $(echo "$diff > 2 || $diff < -2" | bc -l) )); then verdict=FAIL; status=1; fi
  printf '  %-30s %-30s %12d %12d %+7.1f%%  %s\n' "$1" "$2" "${ir[$1]}" "${ir[$2]}" "$diff" "$verdict"
  printf 'pair\t%s\t%s\t%.6f\t%s\n' "$1" "$2" "$diff" "$verdict" >>"$tsv" # full digits: the report rounds once
done

echo
echo "Instruction cost of each feature, per (point, light), on top of seed 003's model (fc_phong_ads):"
base=${ir[fc_phong_ads]}
for k in fc_phong_ads_spot_unused fc_phong_ads_spot fc_phong_ads_attenuation fc_phong_ads_two_sided \
         fc_phong_ads_any_kind fc_phong_ads_blinn fc_phong_ads_no_gate fc_phong_ads_scene_ambient \
         fc_phong_ads_stable fc_phong_ambient_diffuse; do
  printf '  %-30s %8.1f per pair  (%+.1f)\n' "$k" "$(echo "${ir[$k]} / $pairs" | bc -l)" "$(echo "(${ir[$k]} - $base) / $pairs" | bc -l)"
done
[[ -z ${check_failed:-} ]] || status=1
exit $status
