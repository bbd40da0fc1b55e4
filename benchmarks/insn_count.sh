#!/usr/bin/env bash
# Executed instructions per (point, light) under qemu-user, for docs/batch.md's aarch64 table:
# each route of benchmarks/insn_count.cpp shades N points once and twice; the difference of the
# two counts (benchmarks/support/qemu_insn_count.c) is one call's, over N K the count per pair
# (start-up and the scene's set-up cancel; the call's own per-call work is included).
# Usage: benchmarks/insn_count.sh <phong_insn_count binary (aarch64)> <plugin .so> [N]
set -euo pipefail
bin=$1 plugin=$2 N=${3:-1024}
count() { qemu-aarch64 -L /usr/aarch64-linux-gnu -plugin "$plugin" "$bin" "$@" 2>&1 >/dev/null | sed -n 's/^qemu_insn_count: \([0-9]*\) .*/\1/p'; }
printf '%-6s %-6s %-5s %3s %8s\n' mode model route K per_pair
for mode in exact fast stable; do
  for model in phong blinn; do
    for K in 1 4 16; do
      for route in scalar batch hand; do
        if [ "$route" = hand ] && [ "$mode" != exact ]; then continue; fi
        a=$(count "$route" "$mode" "$model" "$N" "$K" 1)
        b=$(count "$route" "$mode" "$model" "$N" "$K" 2)
        awk -v a="$a" -v b="$b" -v n="$N" -v k="$K" -v m="$mode" -v s="$model" -v r="$route" \
            'BEGIN { printf "%-6s %-6s %-5s %3d %8.1f\n", m, s, r, k, (b - a) / (n * k) }'
      done
    done
  done
done
