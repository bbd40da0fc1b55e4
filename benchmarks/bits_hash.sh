#!/usr/bin/env bash
# The exact bits of shade<F>, shade_terms<F>, shade_incident<F> and shade_batch<F>, hashed: one
# FNV-1a hash per (entry point, feature set, mode, type) over a fixed pseudo-random scene
# (benchmarks/support/bits_hash.cpp says what is covered). Run it before and after a change that
# must keep every result, and compare the two outputs (diff): any line that differs names the entry
# point, feature set, mode and type whose bits moved.
#
# Usage: benchmarks/bits_hash.sh [compiler [flags...]]
#   default: g++ -O2 (the x86-64 baseline: shade_batch without FMA goes point by point through
#   shade<F>'s route); e.g. `benchmarks/bits_hash.sh g++ -O2 -march=x86-64-v3` for the AVX2 lanes,
#   `benchmarks/bits_hash.sh clang++ -O3`. The hashes are those of that compiler and those flags:
#   compare runs made with the same ones.
# Environment: BITS_HASH_JOBS (default 2) modes compiled in parallel; BITS_HASH_DIR (default
# build/bits_hash) where the executables go; BITS_HASH_MODES (default "0 1 2 3": exact, stable,
# stable twofold, fast) and BITS_HASH_SETS (a bit mask of the feature sets, bit i for the i-th
# run_set in bits_hash.cpp's main; default all) for a quicker subset, whose lines are those of the
# full run.
# Output: the hash lines on stdout, sorted; the compiler line first, as a comment.
set -euo pipefail
cd "$(dirname "$0")/.."
cxx=${1:-g++}
shift || true
flags=("$@")
[[ ${#flags[@]} -gt 0 ]] || flags=(-O2)
dir=${BITS_HASH_DIR:-build/bits_hash}
jobs=${BITS_HASH_JOBS:-2}
mkdir -p "$dir"
src=benchmarks/support/bits_hash.cpp

build() { # mode
  "$cxx" -std=c++20 "${flags[@]}" -Iinclude -DBITS_HASH_MODE="$1" -DBITS_HASH_SETS="${BITS_HASH_SETS:-0xffffffffu}" "$src" \
    -o "$dir/bits_hash_$1"
}
export -f build
export cxx src dir
pids=()
modes=${BITS_HASH_MODES:-0 1 2 3}
for mode in $modes; do
  build "$mode" &
  pids+=($!)
  while (( $(jobs -rp | wc -l) >= jobs )); do wait -n; done
done
status=0
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
(( status == 0 )) || { echo "bits_hash.sh: build failed" >&2; exit 1; }

echo "# $("$cxx" --version | head -1) | ${flags[*]}"
for mode in $modes; do "$dir/bits_hash_$mode"; done | sort
