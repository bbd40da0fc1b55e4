#!/usr/bin/env bash
# phong's headers in a user's strict build: every test file (tests/*.test.cpp: every route, mode,
# type and extension instantiated) parsed with g++ and clang++ (-fsyntax-only, which instantiates the
# templates) under warnings that renderers and engines turn on beyond -Wall -Wextra -Wpedantic:
# -Wconversion, -Wsign-conversion, -Wdouble-promotion, -Wfloat-equal, -Wshadow, -Wold-style-cast,
# -Wcast-qual, -Wextra-semi, -Wzero-as-null-pointer-constant, -Wundef and each compiler's own
# (g++: -Wuseless-cast, -Wduplicated-cond, -Wlogical-op; clang++: -Wcomma, -Wshorten-64-to-32,
# -Wdocumentation; and -Weverything on user_builds.cpp). The builds: g++ x86-64 -O2 and x86-64-v4
# -O0 (g++'s intrinsics are macros without optimization), clang++ x86-64-v3 and -v4 -O2 (the SIMD
# back ends), aarch64 g++ -O2 (NEON).
# Fails on any warning whose location is a phong header (the tests' own lines may warn: not phong's).
# And tests/strict_warnings/user_builds.cpp, a user's file with every public header, compiled with
# the same warnings as errors without exceptions and RTTI and under GLM's type-changing macros; and
# tests/strict_warnings/aligned_glm.cpp run with GLM's 16-byte vec3 (also under ASan and UBSan); and
# handler_library.cpp, a shared library built with -fvisibility=hidden, with handler_app.cpp: the
# application's precondition handler must see the library's failed check. With g++ 11 installed:
# user_builds.cpp and every header parsed alone with it; the same with libc++ where installed.
# Usage: tests/strict_warnings/check.sh [test files...]   (default: tests/*.test.cpp)
set -euo pipefail
cd "$(dirname "$0")/../.."
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
common=(-std=c++20 -fsyntax-only -Iinclude -Itests -Ibenchmarks/demo -Wall -Wextra -Wpedantic -Wconversion
        -Wsign-conversion -Wdouble-promotion -Wfloat-equal -Wshadow -Wold-style-cast -Wcast-qual -Wextra-semi
        -Wzero-as-null-pointer-constant -Wundef)
gcc_only=(-Wuseless-cast -Wduplicated-cond -Wlogical-op)
clang_only=(-Wcomma -Wshorten-64-to-32 -Wdocumentation)
configs=("g++|-O2" "g++|-O0 -march=x86-64-v4" "clang++|-O2 -march=x86-64-v3" "clang++|-O2 -march=x86-64-v4")
if command -v aarch64-linux-gnu-g++ >/dev/null; then configs+=("aarch64-linux-gnu-g++|-O2"); fi
tests=("$@")
((${#tests[@]})) || tests=(tests/*.test.cpp)
parse() { # parse OUT CXX FLAGS... FILE: the diagnostics to OUT; a failed parse is an error of its own
  local o=$1
  shift
  "${@}" >"$o" 2>&1 || echo "include/phong/(none):0:0: error: the parse failed: ${*: -1} with $1 (${o##*/})" >>"$o"
}
export -f parse
simd_files() { # the test files (stdin) that include the batch path or the SIMD lanes
  while read -r f; do if [[ ! -f $f ]] || grep -q 'phong/batch.hpp\|ext/simd\|ext/batch' "$f"; then echo "$f"; fi; done
}
n=0
for c in "${configs[@]}"; do
  cxx=${c%%|*}
  read -r -a level <<<"${c#*|}"
  extra=("${gcc_only[@]}")
  [[ $cxx == clang++ ]] && extra=("${clang_only[@]}")
  # two at a time, each file's diagnostics to a file of its own
  mkdir -p "$out/$n/tests"
  # xsimd 8.1's own batch<int64> select does not compile under g++'s unoptimized AVX-512BW macros;
  # fast_math_loops.test.cpp reaches it through xsimd::log on double lanes (no shade_batch route does)
  # The x86-64-v3, g++ -v4 and aarch64 parses take the files that reach the SIMD lanes (they
  # instantiate the scalar routes too, and with them every ISA branch of core/ieee.hpp and
  # core/twofold.hpp); the scalar files' other branches are the clang++ -v4 parse's and the baseline's.
  printf '%s\n' "${tests[@]}" | { [[ $c == "g++|-O0 -march=x86-64-v4" ]] && grep -v fast_math_loops || cat; } |
    { [[ $c == *-march=x86-64-v3* || $c == "g++|-O0 -march=x86-64-v4" || $c == aarch64* ]] && simd_files || cat; } |
    xargs -P2 -I{} bash -c 'parse "$@" {}' _ "$out/$n/{}.txt" "$cxx" "${common[@]}" "${level[@]}" "${extra[@]}"
  n=$((n + 1))
done
# a user's file (every public header, a call into each) built the ways users build: without
# exceptions and RTTI, and with GLM's configuration macros that change its types (size_t lengths,
# explicit constructors, x/y/z/w members only, 16-byte aligned vec3 with SIMD intrinsics); -Werror:
# its own lines too
# and clang++'s -Weverything, less the groups no C++20 project keeps (padding, C++98 compatibility)
# and the user's own prototypes
everything=(-Weverything -Wno-padded -Wno-c++98-compat -Wno-c++98-compat-pedantic -Wno-c++20-compat
            -Wno-pre-c++20-compat-pedantic -Wno-missing-prototypes)
builds=("g++|-fno-exceptions -fno-rtti" "g++|-march=x86-64-v4 -fno-exceptions -fno-rtti"
        "clang++|-fno-exceptions -fno-rtti" "clang++|-march=x86-64-v4 -fno-exceptions -fno-rtti"
        "g++|-march=x86-64-v4 -DGLM_FORCE_SIZE_T_LENGTH" "clang++|-march=x86-64-v3 -DGLM_FORCE_SIZE_T_LENGTH"
        "g++|-march=x86-64-v3 -DGLM_FORCE_EXPLICIT_CTOR -DGLM_FORCE_XYZW_ONLY"
        "clang++|-march=x86-64-v4 -DGLM_FORCE_DEFAULT_ALIGNED_GENTYPES -DGLM_FORCE_INTRINSICS"
        "clang++|-march=x86-64-v4 ${everything[*]}")
# and g++ 11 (Ubuntu 22.04's compiler), where installed: its libstdc++ headers include less of each
# other, so each phong header is also parsed alone there (what it uses, it includes)
if command -v g++-11 >/dev/null; then
  builds+=("g++-11|-march=x86-64-v3 -fno-exceptions -fno-rtti")
  mkdir -p "$out/0/tests"
  find include/phong -name '*.hpp' ! -name 'diagnostics_*' | sort |
    xargs -P2 -I{} bash -c 'parse "$1/$(echo "$2" | tr / _).txt" g++-11 -std=c++20 -fsyntax-only -Iinclude -Wall -Wextra -Wpedantic -include "$2" -x c++ /dev/null' \
      _ "$out/0/tests" {}
fi
# and libc++ (LLVM's standard library: macOS, Android, some engines' clang builds), where installed:
# user_builds.cpp and every header parsed alone with it
if echo '#include <vector>' | clang++ -stdlib=libc++ -std=c++20 -fsyntax-only -x c++ - 2>/dev/null; then
  builds+=("clang++|-stdlib=libc++ -march=x86-64-v3 -fno-exceptions -fno-rtti")
  mkdir -p "$out/libcxx/tests"
  find include/phong -name '*.hpp' ! -name 'diagnostics_*' | sort |
    xargs -P2 -I{} bash -c 'parse "$1/$(echo "$2" | tr / _).txt" clang++ -stdlib=libc++ -std=c++20 -fsyntax-only -Iinclude -Wall -Wextra -Wpedantic -include "$2" -x c++ /dev/null' \
      _ "$out/libcxx/tests" {}
fi
k=0
for b in "${builds[@]}"; do
  k=$((k + 1))
  cxx=${b%%|*}
  read -r -a build_flags <<<"${b#*|}"
  extra=("${gcc_only[@]}")
  [[ $cxx == clang++ ]] && extra=("${clang_only[@]}")
  parse "$out/0/tests/user_builds.$k.txt" "$cxx" "${common[@]/-fsyntax-only/-c}" \
    -o "$out/user_builds.o" -O2 "${build_flags[@]}" -Werror "${extra[@]}" tests/strict_warnings/user_builds.cpp
done
# and run: shade_batch on 16-byte vec3 arrays against shade<F>, also under ASan and UBSan
for b in "g++|-O2" "g++|-O2 -march=native" "clang++|-O1 -march=native -fsanitize=address,undefined -fno-sanitize-recover=all"; do
  k=$((k + 1))
  cxx=${b%%|*}
  read -r -a build_flags <<<"${b#*|}"
  log="$out/0/tests/aligned_glm.$k.txt"
  parse "$log" "$cxx" -std=gnu++20 -Iinclude -Wall -Wextra -Wpedantic -Werror "${build_flags[@]}" -DGLM_FORCE_DEFAULT_ALIGNED_GENTYPES \
    -DGLM_FORCE_INTRINSICS -o "$out/aligned_glm" tests/strict_warnings/aligned_glm.cpp
  if [[ -x "$out/aligned_glm" ]]; then
    "$out/aligned_glm" >>"$log" 2>&1 || echo "include/phong/(none):0:0: error: aligned_glm failed with $cxx ${build_flags[*]}" >>"$log"
    rm -f "$out/aligned_glm"
  fi
done
# and a shared library built with -fvisibility=hidden: its failed checks reach the handler its
# executable installed (one handler for the process)
for cxx in g++ clang++; do
  k=$((k + 1))
  log="$out/0/tests/handler.$k.txt"
  hidden=(-std=c++20 -O2 -Iinclude -Wall -Wextra -Wpedantic -Werror -fvisibility=hidden -fvisibility-inlines-hidden)
  parse "$log" "$cxx" "${hidden[@]}" -fPIC -shared -o "$out/libhandler.so" tests/strict_warnings/handler_library.cpp
  parse "$log.app" "$cxx" "${hidden[@]}" -o "$out/handler_app" tests/strict_warnings/handler_app.cpp -L"$out" -lhandler \
    -Wl,-rpath,"$out"
  if [[ -x "$out/handler_app" ]]; then
    "$out/handler_app" >>"$log" 2>&1 || echo "include/phong/(none):0:0: error: handler_app failed with $cxx" >>"$log"
    rm -f "$out/handler_app" "$out/libhandler.so"
  fi
done
# the warnings located in phong's headers, one line per place and flag
grep -h -E '(^|/)include/phong/[^:]*:[0-9]+:[0-9]+: (warning|error):' "$out"/*/tests/*.txt* |
  sed -E 's|^.*(include/phong/)|\1|; :a; s|[A-Za-z_]+/\.\./||; ta' | sort -u >"$out/found" || true
if [[ -s "$out/found" ]]; then
  echo "strict warnings: phong's headers warn or fail in a user's build:"
  cat "$out/found"
  exit 1
fi
echo "strict warnings: ${#tests[@]} test files x ${#configs[@]} builds (the SIMD files only in three), tests/strict_warnings/user_builds.cpp x ${#builds[@]}, aligned_glm.cpp x 3, handler_app x 2 (run) and each header alone with g++ 11 and libc++ (if installed): no warning in phong's headers, every run right"
