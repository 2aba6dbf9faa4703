#!/usr/bin/env python3
"""Writes scenes/meshes/tumbler.obj and scenes/meshes/tumbler_liquid.obj, the glass of juice of
scenes/media.yaml: a drinking glass (a solid of revolution: outer wall, rim, inner wall, inner
floor, base; 1.6 units tall, radius 0.45, walls 0.03 thick, a base 0.1 thick, standing on y = 0 about
the y axis) and the liquid in it, a closed cylinder filled to 1.05 whose side and bottom reach 0.2 mm into the glass, so that no air is
left between them (the overlap the volume stack of FORMAT.md's "Media" resolves: the liquid
counts there). Each surface has its exact normals (smooth around the axis, sharp at the profile's
corners), both meshes closed, normals outward. Deterministic, so the files are reproducible.

usage: make_tumbler_obj.py [OUTPUT_DIR]
"""
import math
import os
import sys

SEGMENTS = 128  # around the axis
RADIUS, HEIGHT, WALL, BASE = 0.45, 1.6, 0.03, 0.1
FILL, OVERLAP = 1.05, 0.0002


def lathe(profile):
    """The OBJ text of the surface swept by `profile` about +Y: a list of bands, each a list of
    (radius, y, normal_radial, normal_y) points, every band its own vertices (a sharp corner
    between bands)."""
    vertices, normals, faces = [], [], []
    for band in profile:
        first = len(vertices)
        for r, y, nr, ny in band:
            for k in range(SEGMENTS):
                phi = 2.0 * math.pi * k / SEGMENTS
                c, s = math.cos(phi), math.sin(phi)
                vertices.append((r * c, y, r * s))
                normals.append((nr * c, ny, nr * s))
        for i in range(len(band) - 1):
            for k in range(SEGMENTS):
                a = first + i * SEGMENTS + k
                b = first + i * SEGMENTS + (k + 1) % SEGMENTS
                c_, d = a + SEGMENTS, b + SEGMENTS
                # Counter-clockwise seen from outside for a profile walked with the solid on its left.
                if band[i][0] > 0.0:
                    faces.append((a, c_, b))
                if band[i + 1][0] > 0.0:
                    faces.append((b, c_, d))
    lines = [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in vertices]
    lines += [f"vn {x:.6f} {y:.6f} {z:.6f}" for x, y, z in normals]
    lines += [f"f {a + 1}//{a + 1} {b + 1}//{b + 1} {c + 1}//{c + 1}" for a, b, c in faces]
    return "\n".join(lines) + "\n"


def disk(y, radius, up):
    """A flat disk at height y, facing up (+1) or down (-1), walked outward for up, inward for down."""
    band = [(0.0, y, 0.0, up), (radius, y, 0.0, up)]
    return band if up < 0 else band[::-1]


def glass():
    inner = RADIUS - WALL
    return [
        disk(0.0, RADIUS, -1.0),                                   # base, facing down
        [(RADIUS, 0.0, 1.0, 0.0), (RADIUS, HEIGHT, 1.0, 0.0)],     # outer wall
        [(RADIUS, HEIGHT, 0.0, 1.0), (inner, HEIGHT, 0.0, 1.0)],   # rim
        [(inner, HEIGHT, -1.0, 0.0), (inner, BASE, -1.0, 0.0)],    # inner wall, facing the axis
        [(inner, BASE, 0.0, 1.0), (0.0, BASE, 0.0, 1.0)],          # inner floor, facing up
    ]


def liquid():
    radius, bottom = RADIUS - WALL + OVERLAP, BASE - OVERLAP
    return [
        disk(bottom, radius, -1.0),
        [(radius, bottom, 1.0, 0.0), (radius, FILL, 1.0, 0.0)],
        [(radius, FILL, 0.0, 1.0), (0.0, FILL, 0.0, 1.0)],
    ]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/meshes"
    for name, profile in (("tumbler", glass()), ("tumbler_liquid", liquid())):
        with open(os.path.join(out, f"{name}.obj"), "w") as f:
            f.write(f"# {name}: written by scripts/make_tumbler_obj.py\n" + lathe(profile))


if __name__ == "__main__":
    main()
