#!/usr/bin/env bash
# What an #include of phong costs: CPU time and preprocessed lines of every public header and of the
# umbrella against <glm/glm.hpp> alone, one shade<F> call at -O2 against the same lighting
# hand-written on GLM, and {fmt}'s bloat test (N translation units x 5 calls, -O0 and -O2: build
# CPU time and stripped binary size) against the hand-written lighting. g++ and clang++.
#
# Usage: benchmarks/compile_time.sh [-n N] [-r RUNS] [--headers-only]
#   N: translation units of the bloat test (default 20); RUNS: runs per header and per one-call TU,
#   median (default 3; the bloat test's builds run once: each is already N + 1 compiles).
# Prints a markdown table per part. Times are user CPU seconds of the compilers: a loaded machine
# moves them less than wall time (system time swings with the load, so it is left out). Sources: benchmarks/compile_time/.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
N=20
runs=3
headers_only=0
while (($#)); do
  case $1 in
    -n) N=$2; shift 2 ;;
    -r) runs=$2; shift 2 ;;
    --headers-only) headers_only=1; shift ;;
    *) echo "usage: $0 [-n N] [-r RUNS] [--headers-only]" >&2; exit 2 ;;
  esac
done
compilers=(g++ clang++)
std=(-std=c++20 -I"$root/include")
src=$root/benchmarks/compile_time
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cpu() { # user CPU seconds of the command "$@" (and its children)
  /usr/bin/time -f '%U' -o "$tmp/time" "$@" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; return 1; }
  awk '{printf "%.2f\n", $1}' "$tmp/time"
}
median() { # median of RUNS runs of cpu "$@"
  for ((i = 0; i < runs; ++i)); do cpu "$@"; done | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

echo "CPU: $(lscpu | sed -n 's/^Model name: *//p' | head -1); $(g++ --version | head -1); $(clang++ --version | head -1)"
echo "User CPU seconds (median of $runs runs; the N-TU builds: one run); lines: \`-E -P | wc -l\`; -std=c++20, no -march."
echo

# ---- Part 1: each public header, -fsyntax-only --------------------------------------------------
heavy='xsimd|/iostream$|/sstream$|/unordered_map$|/complex$|/fstream$'
headers=("glm/glm.hpp")
# the entry headers (include/phong/*.hpp) and the headers of the sum layer a renderer may include alone
for h in "$root"/include/phong/*.hpp "$root"/include/phong/sum/*.hpp; do headers+=("${h#"$root"/include/}"); done
declare -A base
echo "| \`#include\` (-fsyntax-only) | g++ s | x glm | clang++ s | x glm | lines g++ | lines clang++ | heavy std or xsimd headers reached |"
echo "|---|--:|--:|--:|--:|--:|--:|---|"
for h in "${headers[@]}"; do
  echo "#include <$h>" >"$tmp/h.cpp"
  row="| \`<$h>\`"
  for cxx in "${compilers[@]}"; do
    t=$(median "$cxx" "${std[@]}" -fsyntax-only "$tmp/h.cpp")
    [[ $h == glm/glm.hpp ]] && base[$cxx]=$t
    row+=" | $t | $(ratio "$t" "${base[$cxx]}")"
  done
  for cxx in "${compilers[@]}"; do row+=" | $("$cxx" "${std[@]}" -E -P "$tmp/h.cpp" | wc -l)"; done
  reached=$(g++ "${std[@]}" -M "$tmp/h.cpp" | tr ' \\' '\n\n' | grep -E "$heavy" | sed -E 's|.*/xsimd/.*|xsimd|; s|.*/c\+\+/[0-9]+/||' | sort -u | tr '\n' ' ' || true)
  echo "$row | ${reached:-none} |"
done
((headers_only)) && exit 0

# ---- Part 2: one call at -O2 ----------------------------------------------------------------------
echo
echo "| one lighting function, -O2 -c | g++ s | x hand | clang++ s | x hand |"
echo "|---|--:|--:|--:|--:|"
declare -A hand
for tu in hand "<phong/sum/shade.hpp>" "<phong/phong.hpp>"; do
  if [[ $tu == hand ]]; then row="| hand-written on GLM (\`std::pow\`, a light loop)"; args=("$src/one_hand.cpp")
  else row="| one \`shade<presets::classic_phong>\` call, \`$tu\`"; args=(-DPHONG_HEADER="$tu" "$src/one_phong.cpp"); fi
  for cxx in "${compilers[@]}"; do
    t=$(median "$cxx" "${std[@]}" -O2 -c -o "$tmp/one.o" "${args[@]}")
    [[ $tu == hand ]] && hand[$cxx]=$t
    row+=" | $t | $(ratio "$t" "${hand[$cxx]}")"
  done
  echo "$row |"
done

# ---- Part 3: {fmt}'s bloat test ------------------------------------------------------------------
# N translation units, each with one function of 5 lighting calls (different points), and a main
# that calls them all. Build time: CPU time of every compile and the link, one after the other.
gen() { # gen DIR KIND: the N + 1 sources of one side
  local dir=$1 kind=$2 i
  mkdir -p "$dir"
  if [[ $kind == hand ]]; then
    inc='#include "hand.hpp"'; L=hand::light; M=hand::material; call='hand::shade(P, N, m, lights, glm::vec3(0.2f))'; env=
  else
    inc='#include <phong/phong.hpp>'; L=phong::light\<float\>; M=phong::material\<float\>
    env='    const phong::environment<float> e{.ambient = glm::vec3(0.2f)};'
    call='phong::shade<phong::presets::classic_phong>(P, N, m, lights, e)'
  fi
  for ((i = 0; i < N; ++i)); do
    {
      echo "$inc"
      echo "#include <span>"
      echo "glm::vec4 tu$i(const glm::vec3* Q, glm::vec3 N, const $M& m, std::span<const $L> lights)"
      echo "{"
      [[ -n $env ]] && echo "$env"
      echo "    glm::vec4 c(0.0f);"
      for k in 0 1 2 3 4; do echo "    { const glm::vec3 P = Q[$k]; c += $call; }"; done
      echo "    return c;"
      echo "}"
    } >"$dir/tu$i.cpp"
  done
  {
    echo "$inc"
    echo "#include <cstdio>"
    echo "#include <span>"
    for ((i = 0; i < N; ++i)); do echo "glm::vec4 tu$i(const glm::vec3*, glm::vec3, const $M&, std::span<const $L>);"; done
    echo "int main(int argc, char**)"
    echo "{"
    if [[ $kind == hand ]]; then
      echo "    const $L lights[2] = {{glm::vec4(1, 2, 3, 1), glm::vec3(1), glm::vec3(1), glm::vec3(1, 0.1f, 0.01f)}, {glm::vec4(0, 0, 1, 0), glm::vec3(0.5f), glm::vec3(0.5f), glm::vec3(1, 0, 0)}};"
      echo "    const $M m{glm::vec3(0.1f), glm::vec3(0.6f), glm::vec3(0.3f), 16.0f, 1.0f};"
    else
      echo "    const $L lights[2] = {$L::with_strength(glm::vec4(1, 2, 3, 1), glm::vec3(1), {1, 0.1f, 0.01f}), $L::with_strength(glm::vec4(0, 0, 1, 0), glm::vec3(0.5f))};"
      echo "    const $M m{.ka = glm::vec3(0.1f), .kd = glm::vec3(0.6f), .ks = glm::vec3(0.3f), .shininess = 16};"
    fi
    echo "    glm::vec3 Q[5];"
    echo "    for (int k = 0; k < 5; ++k) Q[k] = glm::vec3(0.1f * float(k), 0.2f * float(argc), -2.0f);"
    echo "    glm::vec4 c(0.0f);"
    for ((i = 0; i < N; ++i)); do echo "    c += tu$i(Q, glm::vec3(0, 0, 1), m, lights);"; done
    echo "    std::printf(\"%.5g %.5g %.5g %.5g\\n\", double(c.r), double(c.g), double(c.b), double(c.a));"
    echo "}"
  } >"$dir/main.cpp"
  [[ $kind == hand ]] && cp "$src/hand.hpp" "$dir/"
  return 0
}
gen "$tmp/hand" hand
gen "$tmp/phong" phong
script() { # script CXX OPT DIR [FLAGS]: a shell script that compiles every TU and links, one after the other
  local cxx=$1 opt=$2 dir=$3 flags=${4:-} f
  echo "set -e"
  for f in "$dir"/*.cpp; do echo "$cxx ${std[*]} $opt $flags -c $f -o ${f%.cpp}.o"; done
  echo "$cxx $opt $dir/*.o -o $dir/app"
}
# "small": phong's files again, built with -DPHONG_NO_FORCE_INLINE: the compiler's own inlining
# decisions (a call per point where it keeps shade<F> out of line), phong's opt-in for code size.
cp -r "$tmp/phong" "$tmp/small"
echo
echo "Build: CPU seconds, one run; size: stripped bytes. phong: the default build (per-point functions forced inline); small: -DPHONG_NO_FORCE_INLINE. Every build prints the same colour (checked)."
echo
echo "| $N TUs x 5 calls (+ main) | build s, hand | build s, phong | x hand | build s, small | x hand | bytes, hand | bytes, phong | x hand | bytes, small | x hand |"
echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
for cxx in "${compilers[@]}"; do
  for opt in -O0 -O2; do
    row="| $cxx $opt"
    declare -A t=() s=()
    for kind in hand phong small; do
      flags=; [[ $kind == small ]] && flags=-DPHONG_NO_FORCE_INLINE
      script "$cxx" "$opt" "$tmp/$kind" "$flags" >"$tmp/build.sh"
      t[$kind]=$(cpu bash "$tmp/build.sh")
      "$tmp/$kind/app" >"$tmp/$kind.out"
      strip -o "$tmp/$kind/app.stripped" "$tmp/$kind/app"
      s[$kind]=$(stat -c %s "$tmp/$kind/app.stripped")
    done
    for kind in phong small; do
      cmp -s "$tmp/hand.out" "$tmp/$kind.out" || { echo "$cxx $opt: $kind printed $(cat "$tmp/$kind.out"), hand $(cat "$tmp/hand.out")" >&2; exit 1; }
    done
    echo "$row | ${t[hand]} | ${t[phong]} | $(ratio "${t[phong]}" "${t[hand]}") | ${t[small]} | $(ratio "${t[small]}" "${t[hand]}") | ${s[hand]} | ${s[phong]} | $(ratio "${s[phong]}" "${s[hand]}") | ${s[small]} | $(ratio "${s[small]}" "${s[hand]}") |"
  done
done
