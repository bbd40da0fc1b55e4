#!/usr/bin/env bash
# libFuzzer + ASan + UBSan, each target for a bounded time from its committed seed corpus (copied:
# new units are not kept):
#  * fuzz_shade (tests/fuzz/fuzz_shade.cpp): phong::shade and phong::validate, PHONG_FUZZ_SECONDS (60);
#  * fuzz_batch and fuzz_batch_native (tests/fuzz/fuzz_batch.cpp): shade_batch against shade at the
#    baseline ISA and with -march=native, PHONG_FUZZ_BATCH_SECONDS each (30).
# Any check failure or sanitizer report stops the fuzzer with a non-zero status and saves the input
# as crash-* in build/fuzz-artifacts/; reproduce with `<binary> <that file>`.
set -euo pipefail
seconds="${PHONG_FUZZ_SECONDS:-60}"
batch_seconds="${PHONG_FUZZ_BATCH_SECONDS:-30}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tests/fuzz/build.sh "$work/fuzz_shade" &
build_shade=$!
tests/fuzz/build_batch.sh "$work"
wait "$build_shade"

# fuzz <binary> <corpus directory> <seconds>
fuzz() {
  local binary="$1" corpus="$2" time="$3" name
  name="$(basename "$binary")"
  mkdir -p "$work/$name.corpus" "$work/$name.artifacts"
  cp "$corpus"/* "$work/$name.corpus/"
  # A fixed seed: CI explores the same inputs in the same order on every run (PHONG_FUZZ_SEED=0: random).
  if ! "$binary" "$work/$name.corpus" -max_total_time="$time" -seed="${PHONG_FUZZ_SEED:-20261124}" \
       -artifact_prefix="$work/$name.artifacts/" -print_final_stats=1 > "$work/$name.log" 2>&1; then
    tail -n 80 "$work/$name.log"
    mkdir -p build/fuzz-artifacts && cp "$work/$name.artifacts"/* build/fuzz-artifacts/ 2>/dev/null || true
    echo "40-fuzz: $name FAILED; inputs saved in build/fuzz-artifacts/"
    exit 1
  fi
  grep -h "^stat::number_of_executed_units\|^Done\|^fuzz_batch:" "$work/$name.log" || true
  echo "40-fuzz: $name, no finding in $time s"
}
fuzz "$work/fuzz_shade" tests/fuzz/corpus "$seconds"
fuzz "$work/fuzz_batch" tests/fuzz/corpus_batch "$batch_seconds"
fuzz "$work/fuzz_batch_native" tests/fuzz/corpus_batch "$batch_seconds"
