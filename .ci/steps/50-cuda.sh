#!/usr/bin/env bash
# CUDA, compile only (no GPU needed; nvcc 13, -arch=sm_90). Warnings are errors, except GLM 0.9.9.8's
# own #20012 (__host__ __device__ on its defaulted constructors, ignored by nvcc).
# --expt-relaxed-constexpr: phong calls constexpr std:: functions in device code
# (std::numeric_limits, std::bit_cast, std::is_constant_evaluated, std::array::operator[]).
#  1. tests/cuda/recipe.cu is docs/cuda.md's block marked "<!-- tests/cuda/recipe.cu -->" (the user's
#     recipe: a kernel templated on phong::feature_set, lights in __constant__ memory, a span),
#     compiled with the flags docs/cuda.md gives.
#  2. tests/cuda/shade_kernel.cu (shade and the scalar API from __global__ code), with --use_fast_math.
#  2b. tests/cuda/bsdf_kernel.cu (phong/bsdf.hpp's BSDFs from __global__ code), with and without
#     --use_fast_math.
#  3. benchmarks/cuda/shade.cu (the GPU benchmark, docs/cuda.md) compiled, its PTX kept, and once more
#     to PTX with --use_fast_math. In both, the PTX instructions per light (ptx_per_light.awk) of
#     phong's kernels against the hand-written ones: fast <= 1.1x the __powf kernel's, exact <= 1.1x
#     the powf kernel's; a regression fails here on any machine.
set -euo pipefail
nvcc="${NVCC:-/usr/local/cuda/bin/nvcc}"
if [[ ! -x "$nvcc" ]]; then
  echo "50-cuda: $nvcc not found, CUDA compile check skipped"
  exit 0
fi
"$nvcc" --version | tail -n 2
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
flags=(-std=c++20 --expt-relaxed-constexpr -O3 -arch=sm_90 -diag-suppress 20012 -Werror all-warnings -I include)

awk 'index($0, "<!-- tests/cuda/recipe.cu") == 1 { f = 1; next } f == 1 && /^```/ { f = 2; next }
     f == 2 && /^```$/ { exit } f == 2 { print }' docs/cuda.md >"$out/recipe.cu"
[[ -s "$out/recipe.cu" ]] || { echo "50-cuda: docs/cuda.md has no block marked tests/cuda/recipe.cu"; exit 1; }
diff -u "$out/recipe.cu" tests/cuda/recipe.cu ||
  { echo "50-cuda: tests/cuda/recipe.cu differs from docs/cuda.md's block (above)"; exit 1; }

# The three compilations at once (two cores: nvcc's passes are single-threaded).
start=$SECONDS
"$nvcc" "${flags[@]}" -Xcompiler -Wall,-Wextra -c tests/cuda/recipe.cu -o "$out/recipe.o" &
recipe=$!
"$nvcc" "${flags[@]}" -Xcompiler -Wall,-Wextra --use_fast_math -c tests/cuda/shade_kernel.cu -o "$out/shade_kernel.o" &
kernel=$!
mkdir "$out/keep"
"$nvcc" "${flags[@]}" -Xcompiler -Wall,-Wextra -c benchmarks/cuda/shade.cu -o "$out/shade.o" --keep --keep-dir "$out/keep"
"$nvcc" "${flags[@]}" --use_fast_math -ptx benchmarks/cuda/shade.cu -o "$out/shade_fast_math.ptx"
wait "$recipe"
wait "$kernel"
"$nvcc" "${flags[@]}" -Xcompiler -Wall,-Wextra -c tests/cuda/bsdf_kernel.cu -o "$out/bsdf_kernel.o" &
bsdf=$!
"$nvcc" "${flags[@]}" -Xcompiler -Wall,-Wextra --use_fast_math -c tests/cuda/bsdf_kernel.cu -o "$out/bsdf_kernel_fast_math.o"
wait "$bsdf"
echo "50-cuda: recipe.cu, shade_kernel.cu (--use_fast_math), bsdf_kernel.cu (both) and benchmarks/cuda/shade.cu compiled in $((SECONDS - start)) s"

status=0
for ptx in "$out/keep/shade.ptx" "$out/shade_fast_math.ptx"; do
  [[ "$ptx" == *fast_math* ]] && what="--use_fast_math" || what="default flags"
  awk -v what="$what" -f benchmarks/cuda/ptx_per_light.awk "$ptx" | awk -v what="$what" '
    { n[$1] = $2 }
    END {
      split("count_phong_fast count_hand_fast_powf count_phong_exact count_hand_powf", k, " ")
      for (i in k) if (!(k[i] in n) || n[k[i]] == 0) { print "50-cuda: no loop found in " k[i] " (" what ")"; exit 1 }
      fast = n["count_phong_fast"] / n["count_hand_fast_powf"]; exact = n["count_phong_exact"] / n["count_hand_powf"]
      printf "50-cuda: PTX instructions per light (%s): phong fast %d, hand __powf %d (%.2fx); phong exact %d, hand powf %d (%.2fx)\n",
             what, n["count_phong_fast"], n["count_hand_fast_powf"], fast, n["count_phong_exact"], n["count_hand_powf"], exact
      if (fast > 1.1) { print "50-cuda: phong fast above 1.1x the __powf kernel (" what ")"; exit 1 }
      if (exact > 1.1) { print "50-cuda: phong exact above 1.1x the powf kernel (" what ")"; exit 1 }
    }' || status=1
done
exit "$status"
