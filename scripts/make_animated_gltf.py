#!/usr/bin/env python3
"""Writes scenes/animated_shot.gltf: a one-second glTF 2.0 animation for rtpro's shot rendering
(`rtpro render scenes/animated_shot.gltf --frames 0-24 -o shot_##.exr`). A box on a grey floor
spins a full turn about +y (rotation keys every quarter turn, LINEAR: slerp), slides from x = -1
to x = 1 and squashes (a morph target flattening it and widening it, weights 0 -> 1 -> 0,
CUBICSPLINE with flat tangents); the camera sits under a dolly node keyed from z = 6 to z = 5
(STEP at half a second, then LINEAR), so every sampler interpolation and a camera under an
animated parent are used. Lit by a KHR_lights_punctual sun. Written by hand for rtpro's tests:
no licence beyond the project's.

Usage: scripts/make_animated_gltf.py [OUT.gltf]   (default: scenes/animated_shot.gltf)
"""
import base64
import json
import math
import pathlib
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def add(self, values, kind, component=5126):
        while len(self.data) % 4:
            self.data.append(0)
        fmt = "<" + ("f" if component == 5126 else "H") * len(values)
        offset = len(self.data)
        self.data += struct.pack(fmt, *values)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[kind]
        accessor = {"bufferView": len(self.views) - 1, "componentType": component,
                    "count": len(values) // width, "type": kind}
        if kind == "VEC3" and component == 5126:  # POSITION needs its bounds
            accessor["min"] = [min(values[i::3]) for i in range(3)]
            accessor["max"] = [max(values[i::3]) for i in range(3)]
        if kind == "SCALAR" and component == 5126:
            accessor["min"], accessor["max"] = [min(values)], [max(values)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


def box(half):
    """A cube's 24 vertices (4 per face, flat normals) and 12 triangles."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (1, -1):
            n = [0, 0, 0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(positions) // 3
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis], p[u], p[v] = sign * half, a * half, b * half * sign
                positions += p
                normals += n
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def main():
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "scenes" / "animated_shot.gltf"
    buf = Buffer()
    positions, normals, indices = box(0.5)
    # The squash target: the top comes down by 0.4, everything widens by 30% in x and z.
    squash = []
    for i in range(0, len(positions), 3):
        x, y, z = positions[i:i + 3]
        squash += [0.3 * x, -0.4 if y > 0 else 0.0, 0.3 * z]
    floor = [-4, 0, -4, 4, 0, -4, 4, 0, 4, -4, 0, 4]
    meshes = [
        {"name": "box", "weights": [0.0], "primitives": [{
            "attributes": {"POSITION": buf.add(positions, "VEC3"), "NORMAL": buf.add(normals, "VEC3")},
            "indices": buf.add(indices, "SCALAR", 5123), "material": 0,
            "targets": [{"POSITION": buf.add(squash, "VEC3")}]}]},
        {"name": "floor", "primitives": [{
            "attributes": {"POSITION": buf.add(floor, "VEC3"), "NORMAL": buf.add([0, 1, 0] * 4, "VEC3")},
            "indices": buf.add([0, 2, 1, 0, 3, 2], "SCALAR", 5123), "material": 1}]},
    ]
    materials = [
        {"name": "orange", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.35, 0.08, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 0.5}},
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
                                                    "roughnessFactor": 0.9}},
    ]
    half_turns = [math.sin(math.pi * k / 4) for k in range(5)]  # sin of half the angle, every 90°
    quarter = [0.0, 0.25, 0.5, 0.75, 1.0]
    rotation = []
    for k in range(5):
        rotation += [0.0, half_turns[k], 0.0, math.cos(math.pi * k / 4)]
    samplers = [
        {"input": buf.add(quarter, "SCALAR"), "output": buf.add(rotation, "VEC4")},  # spin
        {"input": buf.add([0.0, 1.0], "SCALAR"), "output": buf.add([-1, 0.5, 0, 1, 0.5, 0], "VEC3")},  # slide
        # squash: CUBICSPLINE keys (in-tangent, value, out-tangent), flat tangents
        {"input": buf.add([0.0, 0.5, 1.0], "SCALAR"), "output": buf.add([0, 0, 0, 0, 1, 0, 0, 0, 0], "SCALAR"),
         "interpolation": "CUBICSPLINE"},
        {"input": buf.add([0.0, 0.5], "SCALAR"), "output": buf.add([0, 1.5, 6, 0, 1.5, 5.5], "VEC3"),
         "interpolation": "STEP"},  # dolly: a cut halfway
    ]
    channels = [
        {"sampler": 0, "target": {"node": 0, "path": "rotation"}},
        {"sampler": 1, "target": {"node": 0, "path": "translation"}},
        {"sampler": 2, "target": {"node": 0, "path": "weights"}},
        {"sampler": 3, "target": {"node": 2, "path": "translation"}},
    ]
    tilt = math.radians(-10)
    gltf = {
        "asset": {"version": "2.0", "generator": "rtpro scripts/make_animated_gltf.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "directional", "color": [1.0, 0.95, 0.9], "intensity": 2500}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 4]}],
        "nodes": [
            {"name": "box", "mesh": 0, "translation": [-1, 0.5, 0]},
            {"name": "floor", "mesh": 1},
            {"name": "dolly", "translation": [0, 1.5, 6], "children": [3]},
            {"name": "camera", "camera": 0, "rotation": [math.sin(tilt / 2), 0, 0, math.cos(tilt / 2)]},
            {"name": "sun", "rotation": [-0.4, 0.3, 0.1, 0.86],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "aspectRatio": 1.5, "znear": 0.1}}],
        "meshes": meshes,
        "materials": materials,
        "animations": [{"name": "shot", "samplers": samplers, "channels": channels}],
        "buffers": [{"byteLength": len(buf.data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf.data)).decode()}],
        "bufferViews": buf.views,
        "accessors": buf.accessors,
    }
    out.write_text(json.dumps(gltf, indent=1) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
