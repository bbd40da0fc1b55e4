#!/usr/bin/env bash
# What a reader of phong's headers pays (issue 36): lines of C++ headers, the share of comment
# lines, the public names <phong/phong.hpp> reaches, functions over 80 lines, and the include rule.
# Usage: tests/layers/surface.sh   (needs clang++ and python3)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
mapfile -t headers < <(find "$root/include/phong" -name '*.hpp' | sort)
read -r lines comments < <(python3 "$here/comment_lines.py" "${headers[@]}") # comment lines: comment and no code
echo "C++ header lines: $lines in ${#headers[@]} headers; comment lines: $comments ($((100 * comments / lines)) %)"
python3 "$here/public_names.py" phong/phong.hpp | tail -1
python3 "$here/long_functions.py" 80 | tail -1
python3 "$here/check_layers.py" | tail -1
