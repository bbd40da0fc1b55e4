#!/usr/bin/env bash
# The BSDFs (phong/bsdf.hpp, docs/bsdf.md): the full chi-square test of sample() against pdf()
# (tests/bsdf_chi2.cpp: 1e6 samples at each of 20 incident directions, m = 1 .. 1e5, both models,
# float and double; ctest runs only a short pass of it) built -O2, and the path tracer's white
# furnace (benchmarks/demo/pathtrace.cpp: exit 1 when a pixel strays from albedo(wo)), each one
# translation unit. The unit tests (tests/bsdf.test.cpp) run in step 10 with the rest.
set -euo pipefail
mkdir -p build/bsdf
g++ -std=c++20 -O2 -DNDEBUG -Iinclude -Itests tests/bsdf_chi2.cpp -o build/bsdf/phong_bsdf_chi2
build/bsdf/phong_bsdf_chi2 250000 20 # 1e6 samples per direction by hand: docs/bsdf.md
g++ -std=c++20 -O2 -DNDEBUG -Iinclude benchmarks/demo/pathtrace.cpp -o build/bsdf/phong_pathtrace # stb: Debian libstb-dev
build/bsdf/phong_pathtrace build/bsdf/images --spp 8 --size 160x120
