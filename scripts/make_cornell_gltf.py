#!/usr/bin/env python3
"""Writes scenes/cornell_box.gltf: the Cornell box as one glTF 2.0 file, as a new user would
write it for any renderer. The measured geometry published by the Cornell Program of Computer
Graphics (millimetres, the quads of scenes/meshes/cornell_*.obj); Lambertian walls as glTF
metallic-roughness non-metals with the RGB reflectances of Mitsuba 3's cbox and
KHR_materials_specular's specularFactor 0, which the extension defines as the pure Lambert base
(a plain glTF non-metal has a GGX specular layer of F0 0.04 over it); the
ceiling light an emissive quad with KHR_materials_emissive_strength; the camera of the published
data (at z = -800 looking along +z, 39.3 degrees vertical field of view).

With --metal-glass the tall block is a rough white metal (metallicFactor 1, base colour 1,
roughness 0.4: Schlick's Fresnel is 1 at every angle, the model Cycles' Glossy BSDF has) and
the short block clear glass (KHR_materials_transmission 1, ior 1.5, roughness 0), the second
scene of benchmarks/cycles_benchmark.sh.

Usage: scripts/make_cornell_gltf.py [--metal-glass] [OUT.gltf]
  (default: scenes/cornell_box.gltf, or benchmarks/cycles/cornell_metal_glass.gltf)
"""
import base64
import json
import math
import pathlib
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MATERIALS = {  # name: (base colour, emission colour, emissive strength)
    "white": ((0.725, 0.71, 0.68), None, None),
    "red": ((0.63, 0.065, 0.05), None, None),
    "green": ((0.14, 0.45, 0.091), None, None),
    "light": ((0.78, 0.78, 0.78), (1.0, 12.0 / 17.0, 4.0 / 17.0), 17.0),
}
# Metallic-roughness values replacing the Lambert ones of a material, and the extensions added.
METAL_GLASS = {
    "metal": ((1.0, 1.0, 1.0), 1.0, 0.4, {}),
    "glass": ((1.0, 1.0, 1.0), 0.0, 0.0, {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                                          "KHR_materials_ior": {"ior": 1.5}}),
}
MESHES = [  # OBJ file, material
    ("cornell_white.obj", "white"), ("cornell_red.obj", "red"), ("cornell_green.obj", "green"),
    ("cornell_short_block.obj", "white"), ("cornell_tall_block.obj", "white"), ("cornell_light.obj", "light"),
]


def read_quads(path):
    vertices, faces = [], []
    for line in path.read_text().splitlines():
        parts = line.split()
        if parts and parts[0] == "v":
            vertices.append(tuple(float(x) for x in parts[1:4]))
        elif parts and parts[0] == "f":
            faces.append([int(x) - 1 for x in parts[1:]])
    return vertices, faces


def main():
    args = sys.argv[1:]
    metal_glass = "--metal-glass" in args
    args = [a for a in args if a != "--metal-glass"]
    default = ROOT / "benchmarks" / "cycles" / "cornell_metal_glass.gltf" if metal_glass else ROOT / "scenes" / "cornell_box.gltf"
    out = pathlib.Path(args[0]) if args else default
    meshes_of = list(MESHES)
    if metal_glass:
        meshes_of[3] = ("cornell_short_block.obj", "glass")
        meshes_of[4] = ("cornell_tall_block.obj", "metal")
    blob = bytearray()
    accessors, views, meshes, nodes = [], [], [], []
    names = list(MATERIALS) + (list(METAL_GLASS) if metal_glass else [])
    for file, material in meshes_of:
        vertices, faces = read_quads(ROOT / "scenes" / "meshes" / file)
        indices = [i for f in faces for i in (f[0], f[1], f[2], f[0], f[2], f[3])]
        for data, target, kind in ((b"".join(struct.pack("<3f", *v) for v in vertices), 34962, "VEC3"),
                                   (struct.pack(f"<{len(indices)}I", *indices), 34963, "SCALAR")):
            while len(blob) % 4:
                blob.append(0)
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
            blob += data
            accessor = {"bufferView": len(views) - 1, "componentType": 5126 if kind == "VEC3" else 5125,
                        "count": len(vertices) if kind == "VEC3" else len(indices), "type": kind}
            if kind == "VEC3":
                accessor["min"] = [min(v[i] for v in vertices) for i in range(3)]
                accessor["max"] = [max(v[i] for v in vertices) for i in range(3)]
            accessors.append(accessor)
        meshes.append({"name": file[:-4], "primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                                          "indices": len(accessors) - 1,
                                                          "material": names.index(material)}]})
        nodes.append({"name": file[:-4], "mesh": len(meshes) - 1})
    materials = []
    for name, (base, emission, strength) in MATERIALS.items():
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*base, 1.0], "metallicFactor": 0.0,
                                                    "roughnessFactor": 1.0},
             "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}
        if emission:
            m["emissiveFactor"] = list(emission)
            m["extensions"]["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        materials.append(m)
    extensions_used = ["KHR_materials_emissive_strength", "KHR_materials_specular"]
    if metal_glass:
        for name, (base, metallic, roughness, extensions) in METAL_GLASS.items():
            materials.append({"name": name, "pbrMetallicRoughness": {"baseColorFactor": [*base, 1.0],
                                                                     "metallicFactor": metallic,
                                                                     "roughnessFactor": roughness},
                              "extensions": extensions})
        extensions_used += ["KHR_materials_ior", "KHR_materials_transmission"]
    # A glTF camera looks along its node's -z: turned half a turn about y it looks along +z.
    nodes.append({"name": "camera", "camera": 0, "translation": [278.0, 273.0, -800.0], "rotation": [0.0, 1.0, 0.0, 0.0]})
    gltf = {
        "asset": {"version": "2.0", "generator": "rtpro scripts/make_cornell_gltf.py"},
        "extensionsUsed": extensions_used,
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(39.3077), "aspectRatio": 1.0,
                                                            "znear": 1.0}}],
        "meshes": meshes,
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    out.write_text(json.dumps(gltf, indent=1) + "\n")


if __name__ == "__main__":
    main()
