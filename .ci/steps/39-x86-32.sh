#!/usr/bin/env bash
# 32-bit x86 (docs/compilers.md, "32-bit x86"): with x87 arithmetic (-m32 alone: __FLT_EVAL_METHOD__
# 2) phong refuses to compile, naming -mfpmath=sse; with SSE arithmetic the accuracy table holds
# every published bound and shade_batch's lanes pass their tests (tests/batch_accuracy.test.cpp),
# at the baseline and with -march=native. Needs g++-12-multilib.
set -euo pipefail
mkdir -p build/x86-32/include
# g++-12-multilib without the gcc-multilib metapackage (which would remove the aarch64 cross
# compiler, .ci/run) lacks the /usr/include/asm link that metapackage adds: one -isystem folder holds it.
ln -sfn /usr/include/x86_64-linux-gnu/asm build/x86-32/include/asm
for cxx in g++ clang++; do
  if "$cxx" -m32 -std=c++20 -fsyntax-only -Iinclude -isystem build/x86-32/include -include phong/phong.hpp -x c++ /dev/null \
    2>build/x86-32/x87.txt; then
    echo "$cxx -m32 (x87): phong compiled"; exit 1
  fi
  grep -q -- "-mfpmath=sse\"" build/x86-32/x87.txt # phong's #error, not a missing header
done
echo "32-bit x86, x87 arithmetic: phong refuses to compile (g++, clang++), naming -mfpmath=sse"
flags=(-m32 -msse2 -mfpmath=sse -std=gnu++20 -O2 -DNDEBUG -Wall -Wextra -Wpedantic -Werror -Iinclude -Itests -DPHONG_HAVE_QUADMATH=1
       -isystem build/x86-32/include)
g++ "${flags[@]}" tests/accuracy_table.cpp -o build/x86-32/table -lquadmath &
g++ "${flags[@]}" -c tests/main.cpp -o build/x86-32/main.o &
wait
g++ "${flags[@]}" -c tests/batch_accuracy.test.cpp -o build/x86-32/batch.o &
g++ "${flags[@]}" -march=native -c tests/batch_accuracy.test.cpp -o build/x86-32/batch-native.o &
wait
for args in "5000 3" "5000 4 --fast"; do
  # shellcheck disable=SC2086
  if ! build/x86-32/table $args --bounds >build/x86-32/table.txt; then grep "ABOVE BOUND" build/x86-32/table.txt; exit 1; fi
  echo "32-bit x86, SSE arithmetic: accuracy table ($args): every class within its published bound"
done
for b in batch batch-native; do
  g++ -m32 build/x86-32/main.o "build/x86-32/$b.o" -o "build/x86-32/$b" -lquadmath
  "build/x86-32/$b" --no-intro | tail -n 2
done
