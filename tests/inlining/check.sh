#!/usr/bin/env bash
# Inlining check (issue 27): a user's scalar shading loops (tests/inlining/user_loop.cpp: several
# presets, the three modes, arrays, spans, masked lists, a light_traits adaptor) compiled with
# g++ and clang++ at -O2 and at -O3 -march=native, debug (assertions on) and NDEBUG; the object file
# must define no function of namespace phong (every one inlined into the extern "C" loops) other
# than the precondition handler's (called only when a debug check fails) and, without NDEBUG, the
# debug checks' bodies (validate() of the parameters and lights, out of line by design); and the same loop written
# with a renderer's own vector type through phong::vec3_of has as many instructions as with
# glm::vec3 (within 10 %). And with -DPHONG_NO_FORCE_INLINE (the size configuration, -O2, debug and
# NDEBUG): no per-file clone of a phong function (g++'s IPA-SRA / IPA-CP `.isra.N` / `.constprop.N`,
# or a split-off `.part.N`), which the linker could not merge across files. Compile only.
# Usage: tests/inlining/check.sh [compiler...]   (default: g++ clang++)
set -euo pipefail
cd "$(dirname "$0")/../.."
compilers=("$@")
((${#compilers[@]})) || compilers=(g++ clang++)
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# the entry points that may stay out of line: the precondition machinery of core/config.hpp, and
# the debug-build checks' bodies (validate() of the parameters and of each light, out of line by
# design: PHONG_DETAIL_OUT_OF_LINE; never under NDEBUG)
ndebug_allowed='^phong::(set_precondition_handler|get_precondition_handler|detail::default_precondition_handler|detail::precondition_failed|detail::load_handler|detail::exchange_handler)\('
allowed="$ndebug_allowed|^void phong::detail::validate_(parameters|light)_or_fail<"
status=0
for cxx in "${compilers[@]}"; do
  for opt in "-O2" "-O3 -march=native"; do
    for ndebug in "" "-DNDEBUG"; do
      obj="$out/user_loop.o"
      # shellcheck disable=SC2086
      "$cxx" -std=c++20 $opt $ndebug -Wall -Wextra -Wpedantic -Werror -I include -c tests/inlining/user_loop.cpp -o "$obj"
      # functions (text symbols) of namespace phong, by their mangled names: _ZN5phong..., const
      # members _ZNK5phong..., lambdas and locals inside phong functions _ZZN5phong...; a user's
      # function with phong types in its signature or template arguments does not count
      left=$(nm --defined-only "$obj" | awk '$2 ~ /^[TtWw]$/ && $3 ~ /^_ZZ?NK?5phong/ { print $3 }' | c++filt |
             grep -Ev "$([[ -n $ndebug ]] && echo "$ndebug_allowed" || echo "$allowed")" || true)
      label="$cxx $opt${ndebug:+ $ndebug}"
      # a renderer's own vector type through phong::vec3_of adds no conversion: the fragment written
      # with it has as many instructions as with glm::vec3, within 10 % (clang++ loads the
      # components one by one where glm's copy loads two at once, and allocates registers
      # differently: up to 8 % more, measured; no instruction converts anything)
      count() { objdump -d --no-show-raw-insn "$obj" | awk -v f="<$1>:" '$2 == f { on = 1; next } /^$/ { on = 0 } on { n++ } END { print n + 0 }'; }
      glm_n=$(count user_screen_glm)
      own_n=$(count user_screen_own)
      if [[ "$glm_n" -eq 0 || "$own_n" -gt $((glm_n + glm_n / 10)) ]]; then
        echo "inlining: $label: vec3_of is not free: $own_n instructions with the renderer's vector, $glm_n with glm::vec3"
        status=1
      fi
      if [[ -n "$left" ]]; then
        echo "inlining: $label: $(wc -l <<<"$left") phong function(s) out of line:"
        sed 's/^/  /' <<<"$left"
        status=1
      else
        but=" but the debug checks' bodies"; [[ -n $ndebug ]] && but=
        echo "inlining: $label: no phong function out of line$but; fragment through vec3_of $own_n instructions, with glm::vec3 $glm_n"
      fi
    done
  done
done
for cxx in "${compilers[@]}"; do
  for ndebug in "" "-DNDEBUG"; do
    obj="$out/user_loop_small.o"
    # shellcheck disable=SC2086
    "$cxx" -std=c++20 -O2 -DPHONG_NO_FORCE_INLINE $ndebug -Wall -Wextra -Wpedantic -Werror -I include -c tests/inlining/user_loop.cpp -o "$obj"
    clones=$(nm --defined-only "$obj" | awk '$2 ~ /^[Tt]$/ && $3 ~ /^_ZZ?NK?5phong/ && $3 ~ /\.(isra|constprop|part)\.[0-9]+$/ { print $3 }' | c++filt || true)
    label="$cxx -O2 -DPHONG_NO_FORCE_INLINE${ndebug:+ $ndebug}"
    if [[ -n "$clones" ]]; then
      echo "inlining: $label: $(wc -l <<<"$clones") per-file clone(s) of phong functions:"
      sed 's/^/  /' <<<"$clones" | cut -c1-200
      status=1
    else
      echo "inlining: $label: no per-file clone of a phong function"
    fi
  done
done
exit $status
