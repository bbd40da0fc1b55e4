#!/usr/bin/env bash
# The BSDFs (phong/bsdf.hpp, docs/bsdf.md): the chi-square test of sample() against pdf()
# (tests/bsdf_chi2.cpp: 1e6 samples at each of 20 incident directions, m = 1 .. 1e5, both models,
# float and double, 960 tests at 0.01 over all with Sidak's correction) built -O2, and the path
# tracer's white furnace (benchmarks/demo/pathtrace.cpp: exit 1 when a pixel strays from
# albedo(wo)), each one translation unit. The unit tests (tests/bsdf.test.cpp) run in step 10.
set -euo pipefail
mkdir -p build/bsdf
g++ -std=c++20 -O2 -DNDEBUG -Iinclude -Itests tests/bsdf_chi2.cpp -pthread -o build/bsdf/phong_bsdf_chi2
build/bsdf/phong_bsdf_chi2 1000000 20 # 960 tests, Sidak over all; about 100 s on 2 cores
g++ -std=c++20 -O2 -DNDEBUG -Iinclude benchmarks/demo/pathtrace.cpp -o build/bsdf/phong_pathtrace # stb: Debian libstb-dev
build/bsdf/phong_pathtrace build/bsdf/images --spp 8 --size 160x120
