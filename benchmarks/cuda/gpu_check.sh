#!/usr/bin/env bash
# Issue 29's GPU run, prepared so that a session lent a GPU spends its device time running, not
# building. Two halves:
#   benchmarks/cuda/gpu_check.sh build   here (no GPU needed): the GPU benchmark for sm_90, default
#                                        flags and --use_fast_math, and the GLSL test binary, all in
#                                        build/gpu/ (ignored by git; carry it to the GPU machine);
#   benchmarks/cuda/gpu_check.sh run     on the GPU machine: nvidia-smi's name of the device, both
#                                        benchmarks (21 repetitions, 4194304 points; docs/cuda.md
#                                        reads their tables), and the GLSL twin's tests on NVIDIA's
#                                        OpenGL through EGL's device platform (docs/glsl.md). Output
#                                        to $OUT (the device tool's folder) or build/gpu/out.
# Exit status: the first failing part's.
set -euo pipefail
cd "$(dirname "$0")/../.."
dir=build/gpu
case "${1:-}" in
build)
  nvcc="${NVCC:-/usr/local/cuda/bin/nvcc}"
  flags=(-std=c++20 --expt-relaxed-constexpr -O3 -arch=sm_90 -diag-suppress 20012 -I include)
  mkdir -p "$dir"
  "$nvcc" "${flags[@]}" benchmarks/cuda/shade.cu -o "$dir/shade_bench" &
  "$nvcc" "${flags[@]}" --use_fast_math benchmarks/cuda/shade.cu -o "$dir/shade_bench_fast_math"
  wait
  [[ -f build/gcc-debug/CMakeCache.txt ]] || cmake --preset gcc-debug >/dev/null
  cmake --build build/gcc-debug --target phong_glsl_tests -j2
  cp build/gcc-debug/tests/glsl/phong_glsl_tests "$dir/"
  pwd >"$dir/root.txt" # the test binary reads phong.glsl and two shaders by this checkout's absolute path
  ls -la "$dir"
  ;;
run)
  out="${OUT:-$dir/out}"
  mkdir -p "$out"
  status=0
  nvidia-smi --query-gpu=name,driver_version --format=csv | tee "$out/device.txt" || status=$?
  "$dir/shade_bench" 21 4194304 2>&1 | tee "$out/shade_bench.txt" || status=$((status ? status : 1))
  "$dir/shade_bench_fast_math" 21 4194304 2>&1 | tee "$out/shade_bench_fast_math.txt" || status=$((status ? status : 1))
  # The GLSL test binary reads include/phong/glsl/phong.glsl and tests/glsl/*.vert|frag by the build
  # checkout's absolute path: where this checkout lies elsewhere, that path is made a link to it.
  root="$(cat "$dir/root.txt")"
  if [[ "$root" != "$PWD" && ! -e "$root" ]]; then mkdir -p "$(dirname "$root")" && ln -s "$PWD" "$root"; fi
  PHONG_EGL_PLATFORM=device "$dir/phong_glsl_tests" 2>&1 | tee "$out/glsl_nvidia.txt" || status=$((status ? status : 1))
  exit $status
  ;;
*)
  echo "usage: benchmarks/cuda/gpu_check.sh build|run"; exit 2 ;;
esac
