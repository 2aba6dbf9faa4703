#!/usr/bin/env python3
"""Writes a glTF 2.0 copy of an OBJ mesh (the Stanford dragon, for benchmarks/motion_cost_benchmark.sh)
with one morph target animated over one second, so that with an open shutter each frame's mesh
deforms and rtpro gives it vertex time steps. The target ripples the surface along y by
`amplitude` × the model's size (a sine over x and z); its weight rises linearly from 0 at t = 0
to 1 at t = `seconds` (default one frame at 24 fps), or with `curved` along (1 - cos(pi t /
seconds)) / 2, keyed 33 times: vertices that move on straight lines (rtpro takes 2 vertex steps)
or that speed up (more steps). Positions only: the file has no normals (rtpro then shades it flat).

Usage: make_morph_dragon.py IN.obj OUT.gltf [amplitude [seconds [curved]]]
       (writes OUT.bin beside OUT.gltf)
"""
import array
import json
import math
import pathlib
import sys


def read_obj(path):
    positions, indices = array.array("f"), array.array("I")
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                positions.extend(float(v) for v in line.split()[1:4])
            elif line.startswith("f "):
                corners = [int(c.split("/")[0]) - 1 for c in line.split()[1:]]
                for i in range(1, len(corners) - 1):
                    indices.extend((corners[0], corners[i], corners[i + 1]))
    return positions, indices


def main():
    source, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    amplitude = float(sys.argv[3]) if len(sys.argv) > 3 else 0.05
    seconds = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0 / 24.0
    positions, indices = read_obj(source)
    lo = [min(positions[i::3]) for i in range(3)]
    hi = [max(positions[i::3]) for i in range(3)]
    size = max(h - l for h, l in zip(hi, lo))
    delta = array.array("f", [0.0]) * len(positions)
    for v in range(0, len(positions), 3):
        x, z = (positions[v] - lo[0]) / size, (positions[v + 2] - lo[2]) / size
        delta[v + 1] = amplitude * size * math.sin(12.0 * x) * math.cos(9.0 * z)
    d_lo = [min(delta[i::3]) for i in range(3)]
    d_hi = [max(delta[i::3]) for i in range(3)]
    if len(sys.argv) > 5 and sys.argv[5] == "curved":
        keys = [seconds * k / 32.0 for k in range(33)]
        times = array.array("f", keys)
        weights = array.array("f", [(1.0 - math.cos(math.pi * t / seconds)) / 2.0 for t in keys])
    else:
        times, weights = array.array("f", [0.0, seconds]), array.array("f", [0.0, 1.0])
    chunks = [positions.tobytes(), delta.tobytes(), indices.tobytes(), times.tobytes(), weights.tobytes()]
    views, offset = [], 0
    for chunk in chunks:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(chunk)})
        offset += len(chunk)
    vertices = len(positions) // 3
    gltf = {
        "asset": {"version": "2.0", "generator": "rtpro benchmarks/make_morph_dragon.py"},
        "buffers": [{"uri": out.with_suffix(".bin").name, "byteLength": offset}],
        "bufferViews": views,
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": vertices, "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": vertices, "type": "VEC3", "min": d_lo, "max": d_hi},
            {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"},
            {"bufferView": 3, "componentType": 5126, "count": len(times), "type": "SCALAR", "min": [0.0],
             "max": [times[-1]]},
            {"bufferView": 4, "componentType": 5126, "count": len(weights), "type": "SCALAR"},
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "targets": [{"POSITION": 1}]}],
                    "weights": [0.0]}],
        "nodes": [{"mesh": 0, "name": "dragon"}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}],
                        "samplers": [{"input": 3, "output": 4, "interpolation": "LINEAR"}]}],
    }
    with open(out.with_suffix(".bin"), "wb") as f:
        for chunk in chunks:
            f.write(chunk)
    out.write_text(json.dumps(gltf))


if __name__ == "__main__":
    main()
