#!/usr/bin/env bash
# Issue 27's benchmark: the demo renderers (whitted.cpp, raster.cpp) built with g++ and clang++ at
# -O2 and at -O3 -march=native (NDEBUG, Release), each run once, and the table of lighting time
# per shaded point printed: phong exact and stable, with what the renderer has (shade_incident:
# the shadow rays' l and distance; screen space: directional lights given, no position, surface per
# fragment), over the expert inline lighting (median thread CPU time, methods interleaved in one
# binary), at 1, 2 and 4 lights. Every run also checks its images (within one 8-bit level).
# Usage: benchmarks/demo/four_builds.sh [--all-builds] [--flags "FLAGS"] [--size WxH] [--reps N]
#   (default 640x480, 9 reps)
# --all-builds: eight builds, -O3 without -march and -O2 -march=native added for both compilers.
# --flags: added to every build's flags (e.g. -DPHONG_NO_FORCE_INLINE); builds then go to build/demo-x-...
# Builds go to build/demo-<compiler>-<level>; the renderers' own reports to <build>/demo_renderers.
set -euo pipefail
cd "$(dirname "$0")/../.."
builds=("g++|-O2" "g++|-O3 -march=native" "clang++|-O2" "clang++|-O3 -march=native")
if [[ "${1:-}" == --all-builds ]]; then
  shift
  builds=("g++|-O2" "g++|-O3" "g++|-O2 -march=native" "g++|-O3 -march=native"
          "clang++|-O2" "clang++|-O3" "clang++|-O2 -march=native" "clang++|-O3 -march=native")
fi
extra=
if [[ "${1:-}" == --flags ]]; then
  extra=$2
  shift 2
fi
args=("$@")
declare -A ratio
status=0
for b in "${builds[@]}"; do
  cxx=${b%%|*}
  opt=${b#*|}
  name="demo-${extra:+x-}${cxx//+/x}-$(tr -d ' =-' <<<"$opt")"
  dir="build/$name"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror" -DCMAKE_CXX_FLAGS_RELEASE="$opt -DNDEBUG${extra:+ $extra}" \
    -DPHONG_BUILD_TESTS=OFF -DPHONG_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build "$dir" --target phong_whitted phong_raster -j2 >/dev/null
  for r in whitted raster; do
    log="$dir/demo_renderers/$r.log"
    mkdir -p "$dir/demo_renderers"
    if ! "$dir/benchmarks/demo/phong_$r" "$dir/demo_renderers" "${args[@]}" >"$log" 2>&1; then
      echo "four_builds: $cxx $opt: phong_$r failed its image targets (see $log)"
      status=1
    fi
    while read -r _ renderer lights exact stable; do
      ratio["$b|$renderer|$lights"]="$exact / $stable"
    done < <(grep '^TABLE27 ' "$log")
  done
done
echo
echo "lighting time per shaded point, phong exact / stable over the expert inline (thread CPU time, medians, interleaved)${extra:+; flags: $extra}"
printf '%-26s | %-38s | %-38s\n' "build" "ray tracer (whitted): 1 / 2 / 4 lights" "rasterizer (screen space): 1 / 2 / 4 lights"
for b in "${builds[@]}"; do
  row=()
  for r in whitted raster; do
    cells=()
    for n in 1 2 4; do cells+=("${ratio["$b|$r|$n"]:--}"); done
    row+=("$(IFS=,; echo "${cells[*]}" | sed 's/,/, /g')")
  done
  printf '%-26s | %-38s | %-38s\n' "${b%%|*} ${b#*|}" "${row[0]}" "${row[1]}"
done
echo "(each cell: exact / stable; targets exact <= 1.0, stable <= 1.5)"
exit $status
