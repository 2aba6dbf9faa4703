#!/usr/bin/python3
"""Writes a small cloud of smoke as an OpenVDB density grid (scenes/volumes/smoke.vdb).

The density is fractal value noise (four octaves, a fixed seed) shaped by a soft ball that
billows upward, on a 48³ grid of 1/24-unit voxels centred on the origin (two scene units across):
a cloud with a dense core, wispy edges and empty space around it, small enough to commit. Run it
again to regenerate the same file: `/usr/bin/python3 scripts/make_smoke_vdb.py [OUT.vdb]` (Debian's Python with
python3-openvdb: `import pyopenvdb`).
"""
import math
import random
import sys

import pyopenvdb as vdb

SIZE = 48          # voxels per axis
VOXEL = 2.0 / SIZE  # scene units per voxel
SEED = 46
LATTICE = 9        # value-noise lattice points per axis for the lowest octave


def lattice_values(seed, n):
    rng = random.Random(seed)
    return [rng.random() for _ in range(n * n * n)]


def smooth(t):
    return t * t * (3.0 - 2.0 * t)


def value_noise(values, n, x, y, z):
    """Trilinear value noise with smoothstep weights at (x, y, z) in lattice units, wrapping."""
    ix, iy, iz = int(math.floor(x)), int(math.floor(y)), int(math.floor(z))
    fx, fy, fz = smooth(x - ix), smooth(y - iy), smooth(z - iz)
    total = 0.0
    for dx in (0, 1):
        for dy in (0, 1):
            for dz in (0, 1):
                v = values[(((ix + dx) % n) * n + (iy + dy) % n) * n + (iz + dz) % n]
                w = (fx if dx else 1 - fx) * (fy if dy else 1 - fy) * (fz if dz else 1 - fz)
                total += v * w
    return total


def density_at(octaves, i, j, k):
    # Position in [-1, 1]³ (voxel centres), the cloud's shape a ball stretched upward.
    x, y, z = ((c + 0.5) / SIZE * 2.0 - 1.0 for c in (i, j, k))
    radius = math.sqrt(x * x + (y * 0.8 - 0.1) ** 2 + z * z)
    noise, amplitude, scale = 0.0, 0.5, 1.0
    for values, n in octaves:
        u = (x + 1.0) * 0.5 * (LATTICE - 1) * scale
        v = (y + 1.0) * 0.5 * (LATTICE - 1) * scale
        w = (z + 1.0) * 0.5 * (LATTICE - 1) * scale
        noise += amplitude * value_noise(values, n, u, v, w)
        amplitude *= 0.5
        scale *= 2.0
    shaped = noise * 1.9 - radius * 1.4
    return max(0.0, min(1.0, shaped * 2.5))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "scenes/volumes/smoke.vdb"
    octaves = []
    for octave in range(4):
        n = (LATTICE - 1) * (1 << octave) + 1
        octaves.append((lattice_values(SEED + octave, n), n))
    grid = vdb.FloatGrid(0.0)
    grid.name = "density"
    grid.gridClass = vdb.GridClass.FOG_VOLUME
    grid.transform = vdb.createLinearTransform(voxelSize=VOXEL)
    # Index (0, 0, 0)'s centre at (-1, -1, -1) + half a voxel: the cloud straddles the origin.
    grid.transform.translate((-1.0 + 0.5 * VOXEL,) * 3)
    access = grid.getAccessor()
    active = 0
    for i in range(SIZE):
        for j in range(SIZE):
            for k in range(SIZE):
                d = density_at(octaves, i, j, k)
                if d > 0.0:
                    access.setValueOn((i, j, k), d)
                    active += 1
    grid.saveFloatAsHalf = True  # halves the file; rtpro reads it back as float
    vdb.write(out, grids=[grid])
    print(f"{out}: {active} active voxels of {SIZE ** 3}")


if __name__ == "__main__":
    main()
