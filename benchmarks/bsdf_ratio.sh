#!/bin/sh
# The BSDF error/time table of docs/bsdf.md: benchmarks/bsdf.bench.cpp built by g++ and clang++ at
# -O2 and -O3 -march=native (one translation unit each, -DNDEBUG), every row run in randomly
# interleaved repetitions (Google Benchmark's --benchmark_enable_random_interleaving), and the
# ratio of the medians of CPU time, phong / Mitsuba-style, per type and m.
# Usage: benchmarks/bsdf_ratio.sh [build_dir = build/bsdf_ratio] [repetitions = 5]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/bsdf_ratio}
reps=${2:-5}
mkdir -p "$out"
for cxx in g++ clang++; do
  for flags in "-O2" "-O3 -march=native"; do
    tag=$(echo "$cxx$flags" | tr -c 'a-zA-Z0-9+' '_')
    $cxx -std=c++20 $flags -DNDEBUG -I"$root/include" "$root/benchmarks/bsdf.bench.cpp" \
      -lbenchmark -lbenchmark_main -lpthread -o "$out/bsdf_$tag"
    "$out/bsdf_$tag" --benchmark_min_time=0.1 --benchmark_repetitions="$reps" \
      --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
      --benchmark_format=csv 2>/dev/null > "$out/bsdf_$tag.csv"
    what=$([ "$cxx$flags" = "g++-O2" ] && echo errors || echo none)
    python3 - "$out/bsdf_$tag.csv" "$cxx $flags" "$what" <<'PY'
import csv, sys
rows, err = {}, {}
reader = csv.reader(open(sys.argv[1]))
head = None
for r in reader:
    if r and r[0] == 'name': head = r; continue
    if head and len(r) > 3 and r[0].endswith('_median'):
        name = r[0][:-len('_median')]
        rows[name] = float(r[head.index('cpu_time')])
        if 'dir_max' in head and r[head.index('dir_max')]:
            err[name] = (float(r[head.index('dir_max')]), float(r[head.index('pdf_max')]))
out = []
for t in ('float', 'double'):
    for k in range(6):
        p = rows.get(f'bsdf.phong.{t}/log10m:{k}'); m = rows.get(f'bsdf.mitsuba.{t}/log10m:{k}')
        if p and m: out.append(f'{t} m=1e{k}: {p / m:.2f}')
print(f'{sys.argv[2]:<22} phong / Mitsuba-style (median CPU time): ' + ', '.join(out))
if sys.argv[3] == 'errors':
    print('largest relative error of the sampled direction (sin a) and of its pdf, phong | Mitsuba-style:')
    for t in ('float', 'double'):
        for k in range(6):
            p = err.get(f'bsdf.phong.{t}/log10m:{k}'); m = err.get(f'bsdf.mitsuba.{t}/log10m:{k}')
            if p and m: print(f'  {t:<6} m=1e{k}: direction {p[0]:.2g} | {m[0]:.2g}, pdf {p[1]:.2g} | {m[1]:.2g}')
PY
  done
done
