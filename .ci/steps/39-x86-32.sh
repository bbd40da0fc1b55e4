#!/usr/bin/env bash
# 32-bit x86 (docs/compilers.md, "32-bit x86"): with x87 arithmetic (-m32 alone: __FLT_EVAL_METHOD__
# 2) phong refuses to compile, naming -mfpmath=sse; with SSE arithmetic the accuracy table holds
# every published bound and shade_batch's lanes pass their tests (tests/batch_accuracy.test.cpp),
# at the baseline and with -march=native. Needs g++-12-multilib. A kernel without 32-bit support
# (some virtual machines) runs the programs under qemu-i386 (qemu-user), which has no AVX-512:
# the second build is then -march=x86-64-v3 (AVX2 lanes).
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
run32=()
echo 'int main() {}' | g++ -m32 -x c++ - -o build/x86-32/probe
if ! build/x86-32/probe 2>/dev/null; then
  run32=(qemu-i386)
  echo "32-bit x86: this kernel runs no 32-bit programs; they run under qemu-i386"
fi
native=-march=native
((${#run32[@]} == 0)) || native=-march=x86-64-v3
g++ "${flags[@]}" tests/accuracy_table.cpp -o build/x86-32/table -lquadmath &
g++ "${flags[@]}" -c tests/main.cpp -o build/x86-32/main.o &
wait
tables() { # the two accuracy tables, one after the other (under qemu-i386 they take most of the step)
  local args
  for args in "5000 3" "5000 4 --fast"; do
    # shellcheck disable=SC2086
    if ! "${run32[@]}" build/x86-32/table $args --bounds >build/x86-32/table.txt; then grep "ABOVE BOUND" build/x86-32/table.txt; return 1; fi
    echo "32-bit x86, SSE arithmetic: accuracy table ($args): every class within its published bound"
  done
}
tables >build/x86-32/tables.log 2>&1 & # on one core while the other builds and runs the batch tests
tables_job=$!
g++ "${flags[@]}" -c tests/batch_accuracy.test.cpp -o build/x86-32/batch.o
g++ "${flags[@]}" "$native" -c tests/batch_accuracy.test.cpp -o build/x86-32/batch-native.o
for b in batch batch-native; do
  g++ -m32 build/x86-32/main.o "build/x86-32/$b.o" -o "build/x86-32/$b" -lquadmath
  isa=baseline
  [ "$b" = batch ] || isa=$native
  echo "32-bit x86, SSE arithmetic: tests/batch_accuracy.test.cpp ($isa${run32:+, under ${run32[0]}}):"
  "${run32[@]}" "build/x86-32/$b" --no-intro | tail -n 2
done
wait "$tables_job" || { cat build/x86-32/tables.log; exit 1; }
cat build/x86-32/tables.log
