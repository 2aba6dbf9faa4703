#!/usr/bin/env python3
"""Regenerates the seed corpora in tests/fuzz/corpus/ from the shipped scenes and meshes plus
hand-made hostile cases. The files are committed; run this only to change the seeds.
Image seeds are written with OpenImageIO's oiiotool (package openimageio-tools)."""
import os
import pathlib
import shutil
import struct
import subprocess
import tempfile
import zlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"


def put(target, name, data):
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def scene_seeds():
    for scene in sorted((ROOT / "scenes").glob("*.yaml")):
        if scene.stem == "many_spheres":  # 10,000 sphere entries teach the fuzzer nothing new
            continue
        # Mesh references point at the fuzz workspace's tiny meshes.
        text = scene.read_text()
        text = text.replace("meshes/shapes.obj", "tiny.obj").replace("../assets/dragon.ply", "tiny.ply")
        text = text.replace("../assets/dragon.obj", "tiny.obj")
        put("scene", "shipped-" + scene.stem + ".yaml", text)
    base = "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], resolution: [8, 8]}\n"
    put("scene", "minimal.yaml", base)
    put("scene", "meshes.yaml", base + "world:\n  - {type: mesh, file: tiny.obj}\n  - {type: mesh, file: tiny.ply, material: default}\n")
    # Nested instances that multiply: 10 levels of 10 instances each is 10^10 after flattening.
    levels = ["objects:", "  l0: [{type: sphere}]"]
    for i in range(1, 11):
        levels.append(f"  l{i}: [" + ", ".join(f"{{type: instance, object: l{i-1}}}" for _ in range(10)) + "]")
    put("scene", "hostile-instance-bomb.yaml", base + "\n".join(levels) + "\nworld: [{type: instance, object: l10}]\n")
    # Accumulated scale 1e-18: six nested scale 0.001.
    nested = ["objects:", "  s0: [{type: sphere}]"]
    for i in range(1, 7):
        nested.append(f"  s{i}: [{{type: instance, object: s{i-1}, transform: {{scale: 0.001}}}}]")
    put("scene", "hostile-tiny-scale.yaml", base + "\n".join(nested) + "\nworld: [{type: instance, object: s6}]\n")
    put("scene", "hostile-alias-bomb.yaml", base + "a: &a [{type: sphere}, {type: sphere}]\n"
        + "".join(f"b{i}: &b{i} [*{'a' if i == 0 else 'b' + str(i-1)}, *{'a' if i == 0 else 'b' + str(i-1)}]\n" for i in range(30)))
    put("scene", "hostile-deep-nesting.yaml", base + "world: " + "[" * 200 + "]" * 200 + "\n")
    put("scene", "hostile-huge-resolution.yaml", "#--set camera.resolution=[65536,4096]\n#--set render.spp=65536\n" + base)
    put("scene", "hostile-set-paths.yaml", "#--set world.0.radius=2\n#--set lights.0=7\n#--set a.b.c.d.e=[1,2]\n#--set =\n" + base + "world: [{type: sphere}]\n")
    put("scene", "hostile-big-numbers.yaml", base + "render: {seed: 18446744073709551616, spp: 4294967297}\nworld: [{type: sphere, radius: 1e999, center: [.nan, .inf, -0]}]\n")
    put("scene", "hostile-tags.yaml", "--- !!map\nrtpro: !!int 1\n...\n---\nsecond: document\n")
    put("scene", "hostile-binary.yaml", bytes(range(256)) * 2)
    put("scene", "hostile-cycle.yaml", base + "objects:\n  a: [{type: instance, object: b}]\n  b: [{type: instance, object: a}]\nworld: [{type: instance, object: a}]\n")
    # glTF placed by the scene file, and image textures named by it (tiny.gltf and tiny.png sit in
    # the workspace too: scene_fuzz.cpp).
    put("scene", "gltf-in-yaml.yaml", base + "objects:\n  t: [{type: mesh, file: tiny.gltf}]\nworld:\n  - {type: mesh, file: tiny.gltf}\n"
        "  - {type: instance, object: t, transform: {translate: [1, 0, 0], rotate: [0, 90, 0]}}\n")
    put("scene", "textures.yaml", base + "materials:\n  a: {color: {texture: tiny.png, tint: [1, 0.5, 0.5], wrap: mirror}}\n"
        "  b: {color: {texture: tiny.png, colorspace: linear}}\nworld:\n  - {type: sphere, material: a}\n"
        "  - {type: mesh, file: tiny.obj, material: b}\n")
    put("scene", "hostile-texture-paths.yaml", base + "materials:\n  up: {color: {texture: ../tiny.png}}\n"
        "  abs: {color: {texture: /dev/zero}}\n  dir: {color: {texture: .}}\n  none: {color: {texture: ''}}\n"
        "world: [{type: sphere, material: up}, {type: sphere, material: abs}, {type: sphere, material: dir}]\n")
    put("scene", "hostile-gltf-instance-bomb.yaml", base + "objects:\n  g0: [{type: mesh, file: tiny.gltf}]\n" +
        "".join(f"  g{i}: [{', '.join(['{type: instance, object: g%d}' % (i - 1)] * 10)}]\n" for i in range(1, 9)) +
        "world: [{type: instance, object: g8}]\n")
    put("scene", "hostile-far-vertex.yaml", base + "objects:\n  m: [{type: mesh, file: tiny.obj}]\nworld: [{type: instance, object: m, transform: {scale: 1e9, translate: [1e9, 1e9, 1e9]}}]\n")


def obj_seeds():
    obj = (ROOT / "scenes/meshes/shapes.obj").read_text().replace("mtllib shapes.mtl", "mtllib model.mtl")
    mtl = (ROOT / "scenes/meshes/shapes.mtl").read_text()
    put("obj", "shipped-shapes.obj", obj + "\n#---mtl---\n" + mtl)
    put("obj", "shipped-shapes-no-mtl.obj", obj)
    tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    put("obj", "triangle.obj", tri + "f 1 2 3\n")
    put("obj", "all-index-forms.obj", tri + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf 1//1 2//1 3//1\nf -3 -2 -1\nf 1/1 2/1 3/1\n")
    put("obj", "hostile-indices.obj", tri + "f 1 2 999\nf -1000000 -6 -7\nf 0 1 2\nf 4294967296 1 2\n")
    put("obj", "hostile-numbers.obj", "v 1e30 0 0\nv abc 0 0\nv 1,5 0 0\nv 1e16 0 0\nv 1e17 0 0\nv nan inf -inf\nvw 0 1e30 0.5\n" + "v " + "9" * 5000 + " 0 0\n")
    put("obj", "hostile-unknown-statements.obj", "".join(f"kw{i} x\n" for i in range(2000)) + tri + "f 1 2 3\n")
    put("obj", "hostile-mtllib-escape.obj", "mtllib ../../../../etc/passwd\nmtllib /dev/zero\nmtllib model.mtl model.mtl\n" + tri + "usemtl nope\nf 1 2 3\n#---mtl---\nnewmtl a\nKd 1e999 -1 nan\nNs -5\nmap_Kd /etc/passwd\n")
    put("obj", "hostile-ngon.obj", "".join(f"v {i} {i*i % 7} 0\n" for i in range(300)) + "f " + " ".join(str(i + 1) for i in range(300)) + "\n")
    put("obj", "hostile-binary.obj", bytes(range(256)) + b"\nv \x00 1 2\nf \xff\n")
    put("obj", "hostile-continuation.obj", "v 0 \\\n0 0\nv 1 0 0\nv 0 1 0\r\nf 1 2 \\\n3\n")


def ply(header_lines, body):
    return ("ply\n" + "\n".join(header_lines) + "\nend_header\n").encode() + body


def ply_seeds():
    vertex_props = ["property float x", "property float y", "property float z"]
    face = ["element face 1", "property list uchar int vertex_indices"]
    put("ply", "ascii.ply", ply(["format ascii 1.0", "element vertex 3"] + vertex_props + face, b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
    put("ply", "ascii-quad.ply", ply(["format ascii 1.0", "comment a quad", "element vertex 4"] + vertex_props + ["property float nx", "property uchar red"] + face[:1] + [face[1]], b"0 0 0 1 255\n1 0 0 1 0\n1 1 0 1 0\n0 1 0 1 0\n4 0 1 2 3\n"))
    verts = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    put("ply", "binary-le.ply", ply(["format binary_little_endian 1.0", "element vertex 3"] + vertex_props + face, verts + struct.pack("<B3i", 3, 0, 1, 2)))
    put("ply", "binary-be.ply", ply(["format binary_big_endian 1.0", "element vertex 3"] + vertex_props + face, struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack(">B3i", 3, 0, 1, 2)))
    put("ply", "dragon-like.ply", ply(["format binary_little_endian 1.0", "element vertex 3"] + vertex_props + ["property float confidence", "property float intensity", "element face 1", "property list uchar int vertex_indices"], struct.pack("<15f", 0, 0, 0, 1, 1, 1, 0, 0, 1, 1, 0, 1, 0, 1, 1) + struct.pack("<B3i", 3, 0, 1, 2)))
    put("ply", "hostile-huge-counts.ply", ply(["format binary_little_endian 1.0", "element vertex 4294967295"] + vertex_props + ["element face 4294967295", "property list uint int vertex_indices"], verts))
    put("ply", "hostile-list-count.ply", ply(["format binary_little_endian 1.0", "element vertex 3"] + vertex_props + ["element face 1", "property list uint int vertex_indices"], verts + struct.pack("<I", 0xFFFFFFFF)))
    put("ply", "hostile-indices.ply", ply(["format ascii 1.0", "element vertex 3"] + vertex_props + face, b"0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n3 -1 0 1\n"))
    put("ply", "hostile-nan.ply", ply(["format binary_little_endian 1.0", "element vertex 3"] + vertex_props + face, struct.pack("<9I", 0x7fc00000, 0, 0, 0x7f800000, 0, 0, 0, 0x5f800000, 0) + struct.pack("<B3i", 3, 0, 1, 2)))
    put("ply", "hostile-header.ply", b"ply\nformat ascii 2.0\nelement vertex -1\nproperty list list float x\nelement\nend_header\n")


def image_seeds(work):
    selector = {".exr": 0, ".png": 1, ".tif": 2, ".jpg": 3, ".hdr": 4, ".pfm": 5, ".ppm": 6, ".bmp": 7, ".tga": 8}
    for extension, index in selector.items():
        if extension == ".pfm":  # oiiotool cannot write PFM: a 2x2 RGB one by hand
            put("image", "small.pfm", bytes([index]) + b"PF\n2 2\n-1.0\n" + struct.pack("<12f", *range(12)))
            continue
        path = pathlib.Path(work) / ("seed" + extension)
        subprocess.run(["oiiotool", "--pattern", "fill:top=0.1,0.5,0.9:bottom=1,0.2,0", "5x4", "3", "-o", str(path)], check=True)
        put("image", "small" + extension, bytes([index]) + path.read_bytes())
    path = pathlib.Path(work) / "aovs.exr"
    subprocess.run(["oiiotool", "--pattern", "constant:color=0.5,0.25,1,0.5,2", "3x2", "5", "--chnames", "R,G,B,A,depth.Z", "-o", str(path)], check=True)
    put("image", "channels.exr", bytes([0]) + path.read_bytes())
    # Tiled files with partial edge tiles (OpenImageIO 2.4's converting read divides by zero on
    # them, its EXR tile reader overruns on a partial rectangle), and a GIF (read by its signature).
    for name, selector_byte, data_type in (("tiled.exr", 0, "half"), ("tiled.tif", 2, "uint8")):
        path = pathlib.Path(work) / name
        subprocess.run(["oiiotool", "--pattern", "checker", "20x18", "3", "--tile", "16", "16", "-d", data_type, "-o", str(path)], check=True)
        put("image", name, bytes([selector_byte]) + path.read_bytes())
    path = pathlib.Path(work) / "small.gif"
    subprocess.run(["oiiotool", "--pattern", "checker", "6x5", "3", "-d", "uint8", "-o", str(path)], check=True)
    put("image", "small.gif", bytes([1]) + path.read_bytes())
    put("image", "small-named.gif", bytes([9]) + path.read_bytes())  # by its .gif extension too
    # A valid PNG signature and header declaring 65535 x 65535 pixels, and nothing else.
    ihdr = struct.pack(">IIBBBBB", 65535, 65535, 8, 2, 0, 0, 0)
    png = b"\x89PNG\r\n\x1a\n" + struct.pack(">I", len(ihdr)) + b"IHDR" + ihdr + struct.pack(">I", zlib.crc32(b"IHDR" + ihdr))
    put("image", "hostile-png-huge-header.png", bytes([1]) + png)
    put("image", "hostile-pfm-huge.pfm", bytes([5]) + b"PF\n65536 65536\n-1.0\n" + b"\0" * 64)
    put("image", "hostile-ppm-huge.ppm", bytes([6]) + b"P6\n100000 100000\n255\n" + b"\0" * 64)
    put("image", "hostile-truncated.exr", bytes([0]) + (CORPUS / "image" / "small.exr").read_bytes()[:120])


def gltf_document(buffer_uri, byte_length, extra=None):
    """A glTF 2.0 document: one triangle (positions, normals, 16-bit indices) in one buffer, a
    node tree with matrix and TRS transforms, a camera and a KHR_lights_punctual light."""
    import json
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 3, 4]}],
        "nodes": [
            {"children": [1, 2], "translation": [0, 0, -1], "rotation": [0, 0.382683, 0, 0.92388], "scale": [2, 2, 2]},
            {"mesh": 0},
            {"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1]},
            {"camera": 0, "translation": [0, 0, 5]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [2, 3, 4]},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01, "aspectRatio": 1.0}}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 1, 1], "intensity": 5}]}},
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1], "metallicFactor": 0.5,
                                                "roughnessFactor": 0.3}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0, "mode": 4}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 36},
            {"buffer": 0, "byteOffset": 72, "byteLength": 6},
        ],
        "buffers": [{"byteLength": byte_length} | ({"uri": buffer_uri} if buffer_uri else {})],
    }
    if extra:
        extra(doc)
    return json.dumps(doc, separators=(",", ":"))


def gltf_buffer():
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    normals = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
    return positions + normals + struct.pack("<3H", 0, 1, 2) + b"\0\0"


def glb(json_text, binary):
    chunk_json = json_text.encode() + b" " * (-len(json_text) % 4)
    chunk_bin = binary + b"\0" * (-len(binary) % 4)
    body = struct.pack("<II", len(chunk_json), 0x4E4F534A) + chunk_json + struct.pack("<II", len(chunk_bin), 0x004E4942) + chunk_bin
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def gltf_seeds():
    import base64
    data = gltf_buffer()
    embedded = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    put("gltf", "triangle-embedded.gltf", gltf_document(embedded, len(data)))
    put("gltf", "triangle-external-bin.gltf", gltf_document("model.bin", len(data)).encode() + b"\n#---bin---\n" + data)
    put("gltf", "triangle.glb", glb(gltf_document(None, len(data)), data))
    # Hostile: an index past the vertex count, a node that is its own child, an accessor reaching
    # past its view, a missing .bin, an infinite coordinate.
    bad_index = data[:72] + struct.pack("<3H", 0, 1, 60000) + b"\0\0"
    put("gltf", "hostile-index-out-of-range.glb", glb(gltf_document(None, len(bad_index)), bad_index))
    def cycle(doc): doc["nodes"][1]["children"] = [1]
    put("gltf", "hostile-node-cycle.gltf", gltf_document(embedded, len(data), cycle))
    def overrun(doc): doc["accessors"][0]["count"] = 1000000
    put("gltf", "hostile-accessor-overrun.gltf", gltf_document(embedded, len(data), overrun))
    put("gltf", "hostile-missing-bin.gltf", gltf_document("model.bin", len(data)))
    infinite = struct.pack("<9f", 0, 0, 0, float("inf"), 0, 0, 0, 1, 0) + data[36:]
    put("gltf", "hostile-infinite-position.glb", glb(gltf_document(None, len(infinite)), infinite))
    def many_instances(doc):
        # A legal tree of 1 + 24 + 24 * 24 nodes: 576 placements of the mesh from 10 KB.
        doc["nodes"] = [{"children": list(range(1, 25))}]
        doc["nodes"] += [{"children": list(range(25 + 24 * i, 49 + 24 * i))} for i in range(24)]
        doc["nodes"] += [{"mesh": 0} for _ in range(24 * 24)]
        doc["scenes"] = [{"nodes": [0]}]
    put("gltf", "tree-of-576-placements.gltf", gltf_document(embedded, len(data), many_instances))


def hair(strands, points, arrays, positions, segments=None, thickness=None, transparency=None, colors=None,
         default_segments=0, default_thickness=0.01):
    """A .hair file: the 128-byte header, then the arrays its flags name, in the format's order."""
    header = b"HAIR" + struct.pack("<4I", strands, points, arrays, default_segments)
    header += struct.pack("<5f", default_thickness, 1.0, 0.5, 0.4, 0.3) + b"rtpro fuzz seed".ljust(88, b"\0")
    body = b""
    for values, form in ((segments, "H"), (positions, "f"), (thickness, "f"), (transparency, "f"), (colors, "f")):
        if values is not None:
            body += struct.pack("<%d%s" % (len(values), form), *values)
    return header + body


def hair_seeds():
    # A strand of 4 points and one of 7 (3n + 1: every basis takes them), every array present.
    xyz = [c for i in range(11) for c in (0.1 * i, 0.05 * i * i, 0.0 if i < 4 else 1.0)]
    put("hair", "all-arrays.hair", hair(2, 11, 31, xyz, segments=[3, 6], thickness=[0.02] * 11,
                                        transparency=[0.0] * 11, colors=[0.5, 0.3, 0.2] * 11))
    # No segments array: every strand has the default count; no thickness: the default one.
    put("hair", "defaults.hair", hair(3, 12, 2, [0.25 * i for i in range(36)], default_segments=3))
    put("hair", "one-point-strands.hair", hair(2, 2, 3, [0, 0, 0, 1, 1, 1], segments=[0, 0]))
    put("hair", "empty.hair", hair(0, 0, 2, []))
    put("hair", "hostile-counts.hair", hair(0xFFFFFFFF, 0xFFFFFFFF, 31, [0, 0, 0]))
    put("hair", "hostile-strands-need-more.hair", hair(2, 3, 3, [0] * 9, segments=[0xFFFF, 1]))
    put("hair", "hostile-values.hair", hair(1, 4, 7, [float("nan"), 0, 0, float("inf"), 0, 0, 1e30, 0, 0, 0, 0, 0],
                                            segments=[3], thickness=[-1.0, 0.0, float("nan"), 1e38]))


if __name__ == "__main__":
    for target in ("scene", "obj", "ply", "image", "gltf", "hair"):
        shutil.rmtree(CORPUS / target, ignore_errors=True)
    scene_seeds()
    obj_seeds()
    ply_seeds()
    gltf_seeds()
    hair_seeds()
    with tempfile.TemporaryDirectory() as work:
        image_seeds(work)
    for target in sorted(os.listdir(CORPUS)):
        print(target, len(os.listdir(CORPUS / target)), "seeds")
