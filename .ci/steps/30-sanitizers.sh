#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang++ 14, Debug,
# -fno-sanitize-recover=all: the first report fails its test), with libstdc++'s bounds checks
# (-D_GLIBCXX_ASSERTIONS: std::span, std::array, std::vector indexes). Zero reports expected.
# This is also CI's clang++ build: Debug with -Wall -Wextra -Wpedantic -Werror, where clang rejects
# non-constexpr std:: calls in constant evaluation that g++ folds silently (tests/constexpr.test.cpp).
# A plain clang++ Debug build of the same suite (the test-clang workflow, for contributors) would
# compile the same code with the same warnings once more, about 150 s of CI's 15 minutes.
# The preset leaves out phong_batch_native_tests (PHONG_NATIVE_BATCH_TESTS=OFF), about 70 s: the
# widest-ISA kernels run under ASan + UBSan in step 40 (fuzz_batch_native, 30000 inputs against
# the scalar path), and those tests themselves in step 10.
# The same tests as `cmake --workflow --preset asan`, with the preset's environment, but
# phong_tests' own test cases (ctest label unit, about 400) run in 12 processes, two at a time,
# instead of one process each: ASan's start-up (about 0.2 s a process) was a third of ctest's time.
set -euo pipefail
cmake --preset asan >/dev/null
cmake --build --preset asan
eval "$(python3 -c '
import json, shlex
presets = json.load(open("CMakePresets.json"))
env = next(t for t in presets["testPresets"] if t["name"] == "asan")["environment"]
print("\n".join(f"export {k}={shlex.quote(v)}" for k, v in env.items()))')"
RC_PARAMS="$(sed -n 's/.*ENVIRONMENT "RC_PARAMS=\([^"]*\)".*/\1/p' tests/CMakeLists.txt)"
export RC_PARAMS
[[ -n $RC_PARAMS && -n $ASAN_OPTIONS ]] || { echo "30-sanitizers: no RC_PARAMS or ASAN_OPTIONS found"; exit 1; }
ctest --preset asan -LE unit >build/asan/ctest.log 2>&1 & # the other tests (GL, examples, tools) beside them
other=$!
bin=build/asan/tests/phong_tests
n=$("$bin" --count | sed -n 's/.*passing the current filters: \([0-9]*\).*/\1/p')
[[ $n =~ ^[1-9][0-9]*$ ]] || { echo "30-sanitizers: phong_tests --count gave no number"; exit 1; }
shards=12
run_shard() { # run_shard K: test cases K n / shards + 1 to (K + 1) n / shards, output to a log
  local first=$(($1 * n / shards + 1)) last=$((($1 + 1) * n / shards))
  "$bin" --no-intro -f="$first" -l="$last" >"build/asan/unit.$1.log" 2>&1 ||
    { cat "build/asan/unit.$1.log"; echo "30-sanitizers: phong_tests' test cases $first to $last failed"; return 1; }
}
export bin n shards
export -f run_shard
seq 0 $((shards - 1)) | xargs -P2 -I{} bash -c 'run_shard {}' || status=1
wait "$other" || status=1
tail -n 25 build/asan/ctest.log
if ((${status:-0})); then echo "30-sanitizers: failed (above)"; exit 1; fi
assertions=0
for ((k = 0; k < shards; ++k)); do
  assertions=$((assertions + $(awk '/assertions:/ { print $3 }' "build/asan/unit.$k.log")))
done
echo "30-sanitizers: phong_tests under ASan + UBSan: $n test cases in $shards processes, $assertions assertions passed"
