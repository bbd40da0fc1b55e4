#!/usr/bin/env bash
# Benchmarks smoke test (no speed targets here: those live in the report, benchmarks/report.sh).
# Builds the bench preset's benchmark targets, checks that the feature-cost kernel pairs compute
# bit-for-bit the same colours, checks the hand-written SIMD baseline (its stated error bounds and its
# agreement with phong's scalar shade<F>), runs a few benchmark rows once (their error counters included),
# and tests benchmarks/report.py on them.
set -euo pipefail
cmake --preset bench >/dev/null
cmake --build --preset bench -j 2 --target phong_bench phong_feature_cost phong_hand_simd_check phong_simd_layer
build/bench/benchmarks/phong_feature_cost --check
build/bench/benchmarks/phong_hand_simd_check
build/bench/benchmarks/phong_bench --benchmark_filter='(naive_glm|scalar|batch|hand_simd)\.exact\.phong\.float/typical/K:4/N:65536|feature\.full\.' \
  --benchmark_min_time=0.01 --benchmark_out=build/bench/smoke.json --benchmark_out_format=json
# The report script: its unit tests, then a report and picture from the rows just run.
python3 benchmarks/report_test.py
python3 benchmarks/report.py build/bench/smoke.json build/bench/smoke_report
