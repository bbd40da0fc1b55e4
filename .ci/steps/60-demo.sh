#!/usr/bin/env bash
# Demo renderer (issue 6): the README's one command renders the demo images; check that the five
# PNGs were written (PNG signature). The ray caster's properties are tested in tests/render.test.cpp.
set -euo pipefail
cmake --preset bench >/dev/null
rm -rf build/bench/demo_images # so the check below sees this run's images
cmake --build --preset bench --target demo_images
for f in phong_perspective blinn_perspective phong_orthographic blinn_orthographic demo; do
  png="build/bench/demo_images/$f.png"
  [[ "$(head -c 4 "$png" | od -An -tx1 | tr -d ' \n')" == "89504e47" ]] || { echo "60-demo: $png missing or not a PNG"; exit 1; }
done
echo "60-demo: five PNGs in build/bench/demo_images"
