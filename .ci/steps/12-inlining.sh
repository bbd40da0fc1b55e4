#!/usr/bin/env bash
# Issue 27: no phong function left out of line in a user's scalar shading loop, with g++ and
# clang++ at -O2 and -O3 -march=native, with and without NDEBUG (tests/inlining/check.sh: the
# symbols of the object file of tests/inlining/user_loop.cpp); and with -DPHONG_NO_FORCE_INLINE,
# no per-file clone of a phong function (g++'s .isra/.constprop/.part copies). Compile only.
set -euo pipefail
tests/inlining/check.sh g++ clang++
