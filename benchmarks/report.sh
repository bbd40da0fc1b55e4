#!/usr/bin/env bash
# The benchmark report in one command: configures and builds the `bench` preset (g++ Release,
# -O3 -march=native), runs the whole suite with repetitions (the report reads medians), runs the
# instruction-count check (feature_cost.sh), then writes a markdown report with PASS/FAIL per
# target and a PNG of error against time. The report names the CPU (/proc/cpuinfo's model name) and
# compares shade_batch and the hand-written kernel in the default floating-point environment with
# flush-to-zero / denormals-are-zero set (phong_batch_ratio, interleaved in one process).
#
# Usage: benchmarks/report.sh [--docs] [extra Google Benchmark flags, e.g. --benchmark_filter=K:1/]
#   --docs  also copy the report and the plot to docs/benchmarks/ (what README.md shows)
# Output: build/bench/report/{report.md,error_vs_time.png,results.json}; the report is printed.
# Takes about 7 minutes on 2 cores (build ~1 min, suite ~5 min, callgrind ~15 s, the interleaved
# batch / hand ratios with and without FTZ/DAZ ~40 s).
set -euo pipefail
cd "$(dirname "$0")/.."
docs=0
if [[ ${1:-} == --docs ]]; then docs=1; shift; fi
build=build/bench
out=$build/report
mkdir -p "$out"

cmake --preset bench >/dev/null
cmake --build --preset bench -j 2 --target phong_bench phong_feature_cost phong_batch_ratio

cpu=$(python3 -c 'import sys; sys.path.insert(0, "benchmarks"); import report; print(report.cpu_model())')
echo "CPU: $cpu"
echo "Running the suite (5 repetitions per row in random order, medians; load average: $(cut -d' ' -f1-3 /proc/loadavg))"
# Random interleaving: the repetitions of all rows run in a shuffled order, so a slow spell of this
# shared machine spreads over every row instead of biasing the ones that ran during it.
"$build/benchmarks/phong_bench" --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_min_time=0.1 --benchmark_out="$out/results.json" --benchmark_out_format=json "$@" >"$out/console.txt"

benchmarks/feature_cost.sh "$build" | tee "$out/feature_cost.txt" || true

# The batch targets' ratios once more with both kernels alternating in one process (about 40 s): a
# steadier figure printed beside the verdicts, which stay the rows' above; each repetition also runs
# both kernels with FTZ/DAZ set in MXCSR (the report's section on the floating-point environment).
for mode in exact fast stable; do "$build/benchmarks/phong_batch_ratio" "$mode"; done >"$out/batch_ratio.txt"

python3 benchmarks/report.py "$out/results.json" "$out" "$build/feature_cost.tsv" "$out/batch_ratio.txt"
cat "$out/report.md"
if ((docs)); then
  mkdir -p docs/benchmarks
  cp "$out/report.md" "$out/error_vs_time.png" "$out/feature_cost.txt" docs/benchmarks/
  echo "copied to docs/benchmarks/"
fi
echo
echo "report: $out/report.md   plot: $out/error_vs_time.png"
