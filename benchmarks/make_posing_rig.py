#!/usr/bin/env python3
"""Writes a small skinned and morphed glTF for benchmarks/blender_posing_check.sh: what the Khronos
samples in Debian's assimp-testmodels leave out. A tube (15 rings of 8 vertices along +y) skinned
to a chain of 8 joints, every vertex weighted to all 8 (JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1,
Gaussian in the distance to each joint), under a skeleton root that is translated, turned and
scaled; the skinned mesh's own node is translated too (which the specification says to ignore).
A morph target bulges the tube. Keyed: the root's translation, joint 1's rotation (LINEAR, keys at
0, 0.5 and 1 s), joint 3's rotation (STEP), joint 4's non-uniform scale, joint 6's translation and
the morph weight (LINEAR, keys at 0 and 0.75 s: between keys at frame 12, where the rotations sit
on theirs). Written by hand for rtpro's checks: no licence beyond the project's.

Usage: benchmarks/make_posing_rig.py OUT.gltf
"""
import base64
import json
import math
import struct
import sys

JOINTS, RINGS, SIDES, SPACING = 8, 15, 8, 0.5


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translate(x, y, z):
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]


def rotate_z(degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def scale(f):
    return [[f, 0, 0, 0], [0, f, 0, 0], [0, 0, f, 0], [0, 0, 0, 1]]


def quaternion(axis, degrees):
    n = math.sqrt(sum(a * a for a in axis))
    s = math.sin(math.radians(degrees) / 2)
    return [a / n * s for a in axis] + [math.cos(math.radians(degrees) / 2)]


class Buffer:
    def __init__(self):
        self.data, self.views, self.accessors = bytearray(), [], []

    def add(self, values, kind, component=5126):
        offset = len(self.data)
        self.data += struct.pack("<" + ("f" if component == 5126 else "H") * len(values), *values)
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(self.data) - offset})
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4, "MAT4": 16}[kind]
        accessor = {"bufferView": len(self.views) - 1, "componentType": component,
                    "count": len(values) // width, "type": kind}
        if kind in ("VEC3", "SCALAR") and component == 5126:  # POSITION and sampler inputs need bounds
            accessor["min"] = [min(values[i::width]) for i in range(width)]
            accessor["max"] = [max(values[i::width]) for i in range(width)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1


def main():
    buf = Buffer()
    positions, bulge, joints, weights, indices = [], [], [[], []], [[], []], []
    for ring in range(RINGS):
        y = ring * 0.25
        raw = [math.exp(-((y - SPACING * j) / SPACING) ** 2) for j in range(JOINTS)]
        total = sum(raw)
        for side in range(SIDES):
            angle = 2 * math.pi * side / SIDES
            x, z = 0.2 * math.cos(angle), 0.2 * math.sin(angle)
            positions += [x, y, z]
            bulge += [0.5 * x, 0.0, 0.5 * z]
            for half in range(2):
                joints[half] += list(range(4 * half, 4 * half + 4))
                weights[half] += [w / total for w in raw[4 * half:4 * half + 4]]
            if ring + 1 < RINGS:
                a, b = ring * SIDES + side, ring * SIDES + (side + 1) % SIDES
                indices += [a, b, b + SIDES, a, b + SIDES, a + SIDES]
    root_matrix = matmul(matmul(translate(1, 0, 0), rotate_z(20)), scale(1.5))
    inverse_root = matmul(matmul(scale(1 / 1.5), rotate_z(-20)), translate(-1, 0, 0))
    inverse_binds = []
    for j in range(JOINTS):
        inverse = matmul(translate(0, -SPACING * j, 0), inverse_root)
        inverse_binds += [inverse[r][c] for c in range(4) for r in range(4)]  # column-major
    assert all(abs(matmul(matmul(root_matrix, translate(0, SPACING * 2, 0)),
                          matmul(translate(0, -SPACING * 2, 0), inverse_root))[i][i] - 1) < 1e-12 for i in range(4))
    attributes = {"POSITION": buf.add(positions, "VEC3"),
                  "JOINTS_0": buf.add(joints[0], "VEC4", 5123), "WEIGHTS_0": buf.add(weights[0], "VEC4"),
                  "JOINTS_1": buf.add(joints[1], "VEC4", 5123), "WEIGHTS_1": buf.add(weights[1], "VEC4")}
    primitive = {"attributes": attributes, "indices": buf.add(indices, "SCALAR", 5123),
                 "targets": [{"POSITION": buf.add(bulge, "VEC3")}]}
    nodes = [{"name": "tube", "mesh": 0, "skin": 0, "translation": [5, 5, 5]},
             {"name": "root", "translation": [1, 0, 0], "rotation": quaternion([0, 0, 1], 20),
              "scale": [1.5, 1.5, 1.5], "children": [2]}]
    for j in range(JOINTS):
        node = {"name": "joint%d" % j, "translation": [0, SPACING if j else 0, 0]}
        if j + 1 < JOINTS:
            node["children"] = [3 + j]
        nodes.append(node)
    samplers, channels = [], []

    def key(node, path, times, values, kind, interpolation="LINEAR"):
        samplers.append({"input": buf.add(times, "SCALAR"), "output": buf.add(values, kind),
                         "interpolation": interpolation})
        channels.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})

    key(1, "translation", [0, 0.75], [1, 0, 0, 1.5, 0.3, -0.2], "VEC3")
    key(3, "rotation", [0, 0.5, 1], [0, 0, 0, 1] + quaternion([0, 0, 1], 40) + quaternion([1, 0, 1], 80), "VEC4")
    key(5, "rotation", [0, 0.5], [0, 0, 0, 1] + quaternion([1, 0, 0], 30), "VEC4", "STEP")
    key(6, "scale", [0, 0.75], [1, 1, 1, 1.3, 0.8, 1.1], "VEC3")
    key(8, "translation", [0, 0.75], [0, SPACING, 0, 0.2, 0.6, 0], "VEC3")
    key(0, "weights", [0, 0.75], [0, 1], "SCALAR")
    gltf = {
        "asset": {"version": "2.0", "generator": "rtpro benchmarks/make_posing_rig.py"},
        "scene": 0, "scenes": [{"nodes": [0, 1]}], "nodes": nodes,
        "meshes": [{"name": "tube", "weights": [0], "primitives": [primitive]}],
        "skins": [{"joints": list(range(2, 2 + JOINTS)), "skeleton": 1,
                   "inverseBindMatrices": buf.add(inverse_binds, "MAT4")}],
        "animations": [{"name": "pose", "samplers": samplers, "channels": channels}],
        "buffers": [{"byteLength": len(buf.data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf.data).decode()}],
        "bufferViews": buf.views, "accessors": buf.accessors,
    }
    with open(sys.argv[1], "w") as f:
        json.dump(gltf, f)


main()
