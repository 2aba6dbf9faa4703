#!/usr/bin/env python3
"""Turns the subdivision cages of an Embree tutorial XML model (subdiv*.xml[.gz], Debian's
embree-tools in /usr/share/doc/embree3/models) into an OBJ cage rtpro subdivides, so that Embree's
`pathtracer` and rtpro trace the same Catmull-Clark surface (benchmarks/embree_subdiv_benchmark.sh).

Each <SubdivisionMesh> gives <positions> (x y z per vertex), <faces> (corners per face) and
<position_indices>; they become `v` and `f` lines (several meshes follow one another, their
indices offset). <edge_creases> (vertex pairs) with <edge_crease_weights> and <vertex_creases> with
<vertex_crease_weights> become rtpro's `creases: [[v0, v1, s], ...]` and `corners: [[v, s], ...]`,
written to stdout as the keys of the entry's YAML `subdivision:` flow mapping (Embree's +inf is
OpenSubdiv's infinitely sharp 10; weights of 0 are left out). Holes (<holes>) have no counterpart
in rtpro and are refused. Texture coordinates and normals are not needed: rtpro's surface carries
the limit normal.

usage: embree_subdiv_to_obj.py MODEL.xml[.gz] OUTPUT.obj > subdivision-keys.txt
"""
import gzip
import sys
import xml.etree.ElementTree as ET

SHARPNESS_INFINITE = 10.0


def numbers(mesh, tag, kind):
    element = mesh.find(tag)
    if element is None or element.text is None:
        return []
    return [kind(word) for word in element.text.split()]


def sharpness(weight):
    return min(float(weight), SHARPNESS_INFINITE)


def convert(xml_path, obj_path):
    opener = gzip.open if xml_path.endswith(".gz") else open
    with opener(xml_path, "rb") as f:
        root = ET.parse(f).getroot()
    meshes = root.findall(".//SubdivisionMesh")
    if not meshes:
        sys.exit(f"{xml_path}: no <SubdivisionMesh> element")
    lines, creases, corners = [f"# {len(meshes)} subdivision cage(s) of {xml_path}"], [], []
    offset = 0
    for mesh in meshes:
        positions = numbers(mesh, "positions", float)
        faces = numbers(mesh, "faces", int)
        indices = numbers(mesh, "position_indices", int)
        if numbers(mesh, "holes", int):
            sys.exit(f"{xml_path}: a mesh with <holes>, which rtpro's cages do not have")
        if len(positions) % 3 or sum(faces) != len(indices):
            sys.exit(f"{xml_path}: <positions> or <faces>/<position_indices> do not add up")
        lines += ["v %s %s %s" % tuple(positions[i:i + 3]) for i in range(0, len(positions), 3)]
        start = 0
        for corners_of_face in faces:
            face = indices[start:start + corners_of_face]
            lines.append("f " + " ".join(str(offset + v + 1) for v in face))
            start += corners_of_face
        edges = numbers(mesh, "edge_creases", int)
        edge_weights = numbers(mesh, "edge_crease_weights", float)
        for pair, weight in zip(zip(edges[0::2], edges[1::2]), edge_weights):
            if weight > 0:
                creases.append([offset + pair[0], offset + pair[1], sharpness(weight)])
        for vertex, weight in zip(numbers(mesh, "vertex_creases", int), numbers(mesh, "vertex_crease_weights", float)):
            if weight > 0:
                corners.append([offset + vertex, sharpness(weight)])
        offset += len(positions) // 3
    with open(obj_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    keys = []
    if creases:
        keys.append("creases: [" + ", ".join("[%d, %d, %g]" % tuple(c) for c in creases) + "]")
    if corners:
        keys.append("corners: [" + ", ".join("[%d, %g]" % tuple(c) for c in corners) + "]")
    print(", ".join(keys))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[-1])
    convert(sys.argv[1], sys.argv[2])
