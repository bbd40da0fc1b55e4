#!/usr/bin/env python3
"""Writes the seed corpus for fuzz_shade (tests/fuzz/corpus/). Encoding: see scalar() in
fuzz_shade.cpp: a coefficient v in [0, 12) in steps of 1/16 is the byte 0x40 + 16 v; a coordinate
or cosine v in [-12, 12) in steps of 1/8 is the byte 0xA0 + 8 v."""
import os

def g(v):  # coefficient
    b = 0x40 + round(16 * v)
    assert 0x40 <= b <= 0xFF, v
    return bytes([b])

def c(v):  # coordinate or cosine
    b = 0xA0 + round(8 * v)
    assert 0x40 <= b <= 0xFF, v
    return bytes([b])

def vec(*vs):
    return b"".join(g(v) for v in vs)

def cvec(*vs):
    return b"".join(c(v) for v in vs)

def light(flags, xyz, w=None, amb=(0, 0, 0), dif=(1, 1, 1), spe=(1, 1, 1), att=(1, 0, 0), rng=None,
          axis=(0, 0, -1), exponent=0, cutoff=None, inner=-1, outer=-1, exponent_tag=None):
    out = bytes([flags]) + cvec(*xyz)
    if flags & 3 >= 2:
        out += g(w)
    out += vec(*amb) + vec(*dif) + vec(*spe) + vec(*att)
    if not flags & 4:
        out += g(rng)
    out += cvec(*axis) + (bytes([exponent_tag]) if exponent_tag is not None else g(exponent))
    if not flags & 16:
        out += c(cutoff)
    return out + c(inner) + c(outer)

def scene(selector, lights, pos=(0, 0, -5), n=(0, 0, 1), La=(0.125, 0.125, 0.125), eye=(0, 0, 0, 1),
          ka=(0.25, 0.125, 0.125), kd=(0.75, 0.25, 0.25), ks=(0.5, 0.5, 0.5), em=(0, 0, 0), m=8, alpha=1):
    out = bytes([selector, len(lights) - 1]) + cvec(*pos) + cvec(*n) + vec(*La) + cvec(*eye)
    out += vec(*ka) + vec(*kd) + vec(*ks) + vec(*em) + g(m) + g(alpha)
    return out + b"".join(lights)

positional = light(1 | 4 | 16, (2, 2, 0))
directional = light(0 | 4 | 16, (0, 1, 1))
spot = light(1 | 8 | 4, (0, 0, 0), axis=(0, 0, -1), exponent=2, cutoff=0.5, inner=0.75, outer=0.5)
windowed = light(1 | 16, (1, 1, -4), rng=8, att=(0, 0, 1))
homog = light(2 | 4 | 16, (1, 2, -2), w=0.5, att=(1, 0.5, 0.25))
at_point = light(1 | 4 | 16, (0, 0, -5))
seeds = {}
for sel in range(16):
    for typ in (0, 0x10):
        seeds[f"scene_{sel:02d}_{'d' if typ else 'f'}"] = scene(sel | typ | 0x20, [positional, directional, spot])
# Spot axes aimed exactly at the point (flag 32; 64 scales the axis by 1 + 2^-11), exponent 1e30
# (special value 22, tag 0x36): c = -l.s rounds to 1 or just above.
aimed = light(1 | 4 | 32, (1, 11, -2), axis=(0, 0, 0), exponent_tag=0x36, cutoff=0.5)
aimed_long = light(1 | 4 | 32 | 64, (3, 1, 2), axis=(0, 0, 0), exponent_tag=0x36, cutoff=0.5)
seeds["aimed_spot_f"] = scene(0x2B, [aimed, aimed_long])
seeds["aimed_spot_d"] = scene(0x3B, [aimed, aimed_long])
seeds["eight_lights"] = scene(0x2C, [positional, directional, spot, windowed, homog, at_point, spot, positional])
seeds["light_at_point"] = scene(0x21, [at_point])
seeds["zero_normal"] = scene(0x22, [positional], n=(0, 0, 0))
seeds["back_facing"] = scene(0x0A, [windowed, homog], n=(0, 0, -1))
seeds["nan_position"] = bytes([0x20, 0]) + bytes([0x28]) + scene(0x20, [positional])[3:]
seeds["raw_bits"] = bytes([0x11, 0x02]) + bytes([0x00] + [0x3F, 0xF0] + [0] * 6) * 40
# Repaired inputs (selector bit 0x40): raw bit patterns moved into the domain by the fuzzer.
import random
rng = random.Random(7)
for name, sel in (("repaired_raw_f", 0x4C), ("repaired_raw_d", 0x5C), ("repaired_raw_f2", 0x62), ("repaired_raw_d2", 0x77)):
    body = bytearray([sel, 7])
    for _ in range(260):
        body += bytes([rng.randrange(0, 0x20)]) + bytes(rng.randrange(256) for _ in range(8))
    seeds[name] = bytes(body)
os.makedirs(os.path.join(os.path.dirname(__file__) or ".", "corpus"), exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(os.path.dirname(__file__) or ".", "corpus", name), "wb") as f:
        f.write(data)
print(len(seeds), "seeds")
