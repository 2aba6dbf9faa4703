#!/usr/bin/env python3
"""Writes scenes/meshes/fur_ball.hair, the groom of scenes/curves.yaml: 2000 strands of 6 points
growing out of a unit ball, each leaning along its root's normal and sagging under gravity, with
thickness tapering from root to tip. No colours: the scene's hair material gives them from melanin.
Deterministic (a fixed seed), so the file is reproducible byte for byte.

usage: make_fur_ball_hair.py [OUTPUT.hair]
"""
import math
import random
import struct
import sys

STRANDS, POINTS = 2000, 6


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/meshes/fur_ball.hair"
    rng = random.Random(47)
    points, thickness = [], []
    for _ in range(STRANDS):
        z = rng.uniform(-0.2, 1.0)  # the upper part of the ball: the rest sits on the ground
        phi = rng.uniform(0.0, 2.0 * math.pi)
        r = math.sqrt(max(0.0, 1.0 - z * z))
        normal = (r * math.cos(phi), z, r * math.sin(phi))
        length = rng.uniform(0.35, 0.6)
        position = list(normal)
        direction = [n + rng.uniform(-0.25, 0.25) for n in normal]
        for k in range(POINTS):
            points += position
            f = k / (POINTS - 1)
            thickness.append(0.012 * (1.0 - 0.8 * f))
            step = length / (POINTS - 1)
            direction[1] -= 0.35 * step / length  # sag
            norm = math.sqrt(sum(d * d for d in direction))
            position = [p + step * d / norm for p, d in zip(position, direction)]
    count = STRANDS * POINTS
    header = struct.pack("<4sIIIIfffff88s", b"HAIR", STRANDS, count, 2 | 4, POINTS - 1, 0.0, 1.0, 0.0, 0.0,
                         0.0, b"rtpro scripts/make_fur_ball_hair.py".ljust(88, b" "))
    with open(out, "wb") as f:
        f.write(header)
        f.write(struct.pack(f"<{3 * count}f", *points))
        f.write(struct.pack(f"<{count}f", *thickness))
    print(f"{out}: {STRANDS} strands, {count} points")


if __name__ == "__main__":
    main()
