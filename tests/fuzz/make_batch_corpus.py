#!/usr/bin/env python3
"""Writes the seed corpus for fuzz_batch (tests/fuzz/corpus_batch/). Encoding: fuzz_batch.cpp
(run()): selector, point count, light count, La, eye, the points, the lights, the material(s);
a coefficient v in [0, 12) in steps of 1/16 is the byte 0x40 + 16 v, a coordinate or cosine
v in [-12, 12) in steps of 1/8 is 0xA0 + 8 v, 0x20 + k the k-th special value (22: 1e30,
10: the largest finite, 26: 1e5). Bytes past the end come from fuzz_batch's generator."""
import os

def g(v):
    b = 0x40 + round(16 * v)
    assert 0x40 <= b <= 0xFF, v
    return bytes([b])

def c(v):
    b = 0xA0 + round(8 * v)
    assert 0x40 <= b <= 0xFF, v
    return bytes([b])

def special(k):
    return bytes([0x20 + k])

def light(positional=True, xyz=(1, 2, 3), amb=0.125, dif=1, spe=1, att=(1, 0.0625, 0.0625), exponent=g(2),
          cutoff=None, inner=-1, outer=-1, aim=False):
    flags = (1 if positional else 0) | 4 | (16 if cutoff is None else 0) | (32 if aim else 0)
    out = bytes([flags]) + b"".join(c(v) for v in xyz)
    out += g(amb) * 3 + g(dif) * 3 + g(spe) * 3 + b"".join(g(v) for v in att)
    out += c(0) + c(0) + c(-1) + exponent
    if cutoff is not None:
        out += c(cutoff)
    return out + c(inner) + c(outer)

def material(m=g(8), ka=0.125, kd=0.5, ks=0.25, em=0.0625, alpha=0.5):
    return g(ka) * 3 + g(kd) * 3 + g(ks) * 3 + g(em) * 3 + m + g(alpha)

def scene(selector, points, lights, mats, eye=(0, 0, 1, 1)):
    out = bytes([selector, len(points) - 1, len(lights) - 1]) + g(0.125) * 3 + b"".join(c(v) for v in eye)
    for i, (q, n) in enumerate(points):
        out += bytes([0x01 | (4 if i % 5 == 4 else 0)]) + b"".join(c(v) for v in q) + b"".join(c(v) for v in n)
    return out + b"".join(lights) + b"".join(mats)

def grid_points(count):
    return [((-2 + (i % 5), -1 + (i % 3) * 0.5, -5 - (i % 4)), (0.125 * (i % 3) - 0.125, 0.125 * (i % 2), 1))
            for i in range(count)]

here = os.path.dirname(os.path.abspath(__file__))
out_dir = os.path.join(here, "corpus_batch")
os.makedirs(out_dir, exist_ok=True)
seeds = {}
for index in range(16):
    for double in (0, 1):
        # Every feature set, float and double, 37 points (full steps of 4, 8 and 16 lanes and a
        # tail), two lights (positional, directional), SoA output with a shared material.
        sel = index | (0x10 if double else 0)
        pts = grid_points(37)
        seeds[f"set{index:02d}_{'d' if double else 'f'}"] = scene(sel, pts, [light(), light(False, (0, 1, 1))], [material()])
        # Per-point materials, interleaved output, front_facing flags read, a spot aimed at point 0.
        sel2 = sel | 0x20 | 0x40 | 0x80
        pts2 = grid_points(19)
        mats = [material(m=g(1 + (i % 11)), kd=0.0625 * (i % 8)) for i in range(19)]
        seeds[f"set{index:02d}_{'d' if double else 'f'}_perpoint"] = scene(
            sel2, pts2, [light(cutoff=0.5, exponent=g(4), aim=True, inner=0.75, outer=0.25), light(False, (1, 1, 1))], mats)
# Regressions of issue 15 item 2 (xsimd exp float-cast-overflow): stable mode, m = 1e30 and the
# largest finite shininess, double and float; a huge spot exponent.
for index in (1, 3, 6, 11, 14):
    for double in (0, 1):
        sel = index | (0x10 if double else 0)
        seeds[f"huge_m_{index:02d}_{'d' if double else 'f'}"] = scene(sel, grid_points(9), [light()], [material(m=special(22))])
        seeds[f"max_m_{index:02d}_{'d' if double else 'f'}"] = scene(sel, grid_points(9), [light()], [material(m=special(10))])
        seeds[f"huge_spot_{index:02d}_{'d' if double else 'f'}"] = scene(
            sel, grid_points(9), [light(cutoff=0, exponent=special(22), aim=True)], [material()])
# Light straight above point 0, the specular at its peak (r = v): the power's argument is 0.
seeds["peak_d"] = scene(0x11, [((0, 0, -3), (0, 0, 1))] * 3, [light(True, (0, 0, 5))], [material(m=special(26))])
seeds["peak_f"] = scene(0x01, [((0, 0, -3), (0, 0, 1))] * 3, [light(True, (0, 0, 5))], [material(m=special(26))])
for name, data in seeds.items():
    with open(os.path.join(out_dir, name), "wb") as f:
        f.write(data)
print(f"wrote {len(seeds)} seeds to {out_dir}")
