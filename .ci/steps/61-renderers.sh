#!/usr/bin/env bash
# End-to-end renderers (issue 13, item 7): the Whitted ray tracer and the software rasterizer
# through the demo_renderers target, at a small size (PHONG_RENDERERS_SIZE). The target fails when
# an image target is missed (phong exact vs inline, phong stable vs double: within 1 level of 8-bit
# sRGB at every pixel); then check that every PNG and both timing tables were written.
set -euo pipefail
cmake --preset bench >/dev/null
rm -rf build/bench/demo_renderers # so the checks below see this run's files
PHONG_RENDERERS_SIZE=${PHONG_RENDERERS_SIZE:-240x180} cmake --build --preset bench --target demo_renderers
dir=build/bench/demo_renderers
pngs=()
for n in 1 2 4; do for m in inline phong stable double; do pngs+=("whitted_${n}lights_$m"); done; done
for m in gouraud_inline gouraud_phong gouraud_stable pixel_inline pixel_phong pixel_stable pixel_batch pixel_double; do pngs+=("raster_$m"); done
for f in "${pngs[@]}"; do
  png="$dir/$f.png"
  [[ "$(head -c 4 "$png" | od -An -tx1 | tr -d ' \n')" == "89504e47" ]] || { echo "61-renderers: $png missing or not a PNG"; exit 1; }
done
for t in whitted raster; do
  grep -q "^image targets.*: PASS$" "$dir/$t.txt" || { echo "61-renderers: $dir/$t.txt: image targets not passed"; exit 1; }
done
echo "61-renderers: ${#pngs[@]} PNGs and two timing tables in $dir, image targets PASS"
