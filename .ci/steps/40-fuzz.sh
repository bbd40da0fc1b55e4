#!/usr/bin/env bash
# libFuzzer + ASan + UBSan on phong::shade and phong::validate (tests/fuzz/fuzz_shade.cpp) for a
# bounded time, starting from the committed seed corpus (copied: new units are not kept). Any
# check failure or sanitizer report stops the fuzzer with a non-zero status and saves the input
# as crash-* in the printed directory; reproduce with `<binary> <that file>`.
set -euo pipefail
seconds="${PHONG_FUZZ_SECONDS:-60}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tests/fuzz/build.sh "$work/fuzz_shade"
mkdir -p "$work/corpus" "$work/artifacts"
cp tests/fuzz/corpus/* "$work/corpus/"
if ! "$work/fuzz_shade" "$work/corpus" -max_total_time="$seconds" \
     -artifact_prefix="$work/artifacts/" -print_final_stats=1 > "$work/log" 2>&1; then
  tail -n 80 "$work/log"
  mkdir -p build/fuzz-artifacts && cp "$work"/artifacts/* build/fuzz-artifacts/ 2>/dev/null || true
  echo "40-fuzz: FAILED; inputs saved in build/fuzz-artifacts/"
  exit 1
fi
grep -h "^stat::\|^Done" "$work/log" || true
echo "40-fuzz: no finding in ${seconds} s"
