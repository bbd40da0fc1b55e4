#!/usr/bin/env bash
# CUDA: the headers compile in device code (compile only, no GPU needed): tests/cuda/shade_kernel.cu
# calls phong::shade and the scalar API from __global__ functions. Warnings are errors, except
# GLM 0.9.9.8's own #20012 (__host__ __device__ on its defaulted constructors, ignored by nvcc).
# --expt-relaxed-constexpr: phong calls constexpr std:: functions in device code
# (std::numeric_limits, std::bit_cast, std::is_constant_evaluated, std::array::operator[]).
set -euo pipefail
nvcc="${NVCC:-/usr/local/cuda/bin/nvcc}"
if [[ ! -x "$nvcc" ]]; then
  echo "50-cuda: $nvcc not found, CUDA compile check skipped"
  exit 0
fi
"$nvcc" --version | tail -n 2
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$nvcc" -std=c++20 --expt-relaxed-constexpr -diag-suppress 20012 -Werror all-warnings -Xcompiler -Wall,-Wextra \
  -I include -c tests/cuda/shade_kernel.cu -o "$out/shade_kernel.o"
echo "50-cuda: tests/cuda/shade_kernel.cu compiled for the device"
