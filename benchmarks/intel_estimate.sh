#!/usr/bin/env bash
# What shade_batch / the hand-written AVX-512 kernel would be on an Intel core, estimated without
# one (issue 35): both kernels built for AVX-512 (g++ -O3 -march=x86-64-v4, float, Phong, the
# typical scene of phong_batch_ratio), each profiled on this machine (perf, software clock) to find
# the code it runs, and that code's cycles per iteration from llvm-mca's Intel model.
#   K = 1: every hot region of a K = 1 run (each over 1 % of the samples), in address order, as one
#          loop body: a step of 16 points with its one light;
#   K = 16: the innermost loop of a K = 16 run that holds at least 80 % of the samples the
#           hottest loop holds: the light loop (16 points x one light).
# A static estimate: no memory, no branch prediction, no microcode assists (the batch path makes no
# subnormal number: tests/subnormal_free.test.cpp). Needs perf, llvm-mca-14, python3 and a CPU with
# AVX-512 to run the kernels on. Usage: benchmarks/intel_estimate.sh [llvm-mca CPU] (default sapphirerapids)
set -euo pipefail
cd "$(dirname "$0")/.."
cpu=${1:-sapphirerapids}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -q avx512f /proc/cpuinfo || { echo "intel_estimate: this CPU has no AVX-512" >&2; exit 2; }
echo "profiled on: $(lscpu | sed -n 's/^Model name: *//p' | head -1); llvm-mca model: $cpu; $(g++ --version | head -1)"
echo
echo "| mode | K | hand cycles | batch cycles | batch / hand |"
echo "|---|--:|--:|--:|--:|"
for mode in exact stable; do
  bin=$tmp/$mode
  g++ -std=c++20 -O3 -march=x86-64-v4 -DNDEBUG -DMODE="$mode" -no-pie -Iinclude -Ibenchmarks benchmarks/intel_estimate.cpp -o "$bin"
  objdump -d --no-show-raw-insn "$bin" >"$bin.s"
  for K in 1 16; do
    declare -A cycles=()
    for kernel in hand batch; do
      perf record -q -e cpu-clock -F 20000 -o "$tmp/perf.data" "$bin" "$K" "$kernel" $((K == 1 ? 3000 : 400)) >/dev/null 2>&1
      perf script -i "$tmp/perf.data" -F ip >"$tmp/ips"
      python3 - "$bin.s" "$tmp/ips" "$K" >"$tmp/body.s" <<'PY'
import collections, re, sys
asm, ips, K = sys.argv[1], sys.argv[2], int(sys.argv[3])
h = collections.Counter(int(x, 16) for x in open(ips).read().split())
total = sum(h.values())
ins = [(int(m.group(1), 16), m.group(2)) for m in (re.match(r'\s+([0-9a-f]+):\s+(.*)', l) for l in open(asm)) if m]
# hot regions: runs of sampled instructions, a run broken by 6 unsampled ones
regions, cur, cold = [], None, 0
for a, text in ins:
    if h.get(a, 0):
        if cur is None: cur = {'lines': [], 'samples': 0}
        cur['lines'] += cur.pop('pending', []) + [text]; cur['samples'] += h[a]; cold = 0
    elif cur is not None:
        cold += 1; cur.setdefault('pending', []).append(text)
        if cold >= 6: cur.pop('pending'); regions.append(cur); cur, cold = None, 0
if cur: cur.pop('pending', None); regions.append(cur)
if K == 1:
    lines = [t for r in regions if r['samples'] > 0.01 * total for t in r['lines']]
else:
    # loops: [target, branch] of each backward branch, with their share of the samples; the
    # innermost loop holding at least 80 % of the most any loop holds
    loops = []
    for a, text in ins:
        m = re.match(r'j\w+\s+([0-9a-f]+)', text)
        if m and int(m.group(1), 16) < a:
            t = int(m.group(1), 16)
            body = [x for x in ins if t <= x[0] <= a]
            loops.append((sum(h.get(x[0], 0) for x in body), len(body), [x[1] for x in body]))
    most = max(l[0] for l in loops)
    lines = min((l for l in loops if l[0] >= 0.8 * most), key=lambda l: l[1])[2]
print('.Lbody:')
for text in lines:
    t = re.sub(r'<[^>]*>', '', text.split('#')[0]).strip()
    t = re.sub(r'^(j\w+)\s+[0-9a-f]+$', r'\1 .Lbody', t) # branches: llvm-mca ignores where they go
    print('  ' + t)
PY
      cycles[$kernel]=$(llvm-mca-14 -mtriple=x86_64 -mcpu="$cpu" -iterations=500 "$tmp/body.s" | awk '/^Total Cycles:/ {print $3 / 500}')
    done
    echo "| $mode | $K | ${cycles[hand]} | ${cycles[batch]} | $(awk -v a="${cycles[batch]}" -v b="${cycles[hand]}" 'BEGIN {printf "%.2f", a / b}') |"
  done
done
