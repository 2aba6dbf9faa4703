"""Poses a glTF file with Blender's glTF importer and compares its vertices with rtpro's, for
benchmarks/blender_posing_check.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python pose_check.py -- FILE.gltf DUMP_DIR FRAME...

DUMP_DIR/FRAME.txt holds rtpro's posed vertices at each FRAME (benchmarks/gltf_pose_dump.cpp: glTF
frame, +y up). Blender's are every mesh object's evaluated mesh (the depsgraph: armature modifier,
shape keys, object animation) at that frame, in world space, taken back from Blender's +z up to
glTF's +y up ((x, y, z) -> (x, z, -y)). The scene runs at 24 fps, so that the importer puts glTF
time t at frame t x 24, as rtpro's render.fps does.

The importer may split or merge vertices, so the vertex sets are compared as point sets: the
symmetric Hausdorff distance (the farthest any vertex of either lies from the nearest of the other),
relative to the diagonal of rtpro's posed bounding box, and the two boxes' corners likewise. Prints
one line per frame: "pose FRAME VERTS_RTPRO VERTS_BLENDER HAUSDORFF_REL BBOX_REL CENTROID_REL NLERP_DEG
SLERPED_HAUSDORFF_REL".

NLERP_DEG: the importer keys a LINEAR rotation as four linear F-curves, one per quaternion
component, so Blender interpolates rotations by normalised lerp where glTF (and rtpro) slerps; the
largest angle between the two over the file's LINEAR rotation channels at that frame tells how far
apart the poses are expected to be (0 at the keys). SLERPED_HAUSDORFF_REL is the Hausdorff distance
again once Blender's rotation keys are slerped at the compared frames (rekey_rotations_by_slerp):
what is left when the interpolations are the same.
"""
import base64
import json
import math
import os
import sys

import bpy
import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still uses numpy.bool, removed in Debian's numpy 1.24

args = sys.argv[sys.argv.index("--") + 1:]
gltf_file, dump_dir, frames = args[0], args[1], [int(a) for a in args[2:]]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps, scene.render.fps_base = 24, 1.0
bpy.ops.import_scene.gltf(filepath=gltf_file)


def blender_vertices(frame):
    scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    points = []
    for obj in scene.objects:
        if obj.type != "MESH":
            continue
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        local = numpy.empty(len(mesh.vertices) * 3)
        mesh.vertices.foreach_get("co", local)
        local = local.reshape(-1, 3)
        matrix = numpy.array(evaluated.matrix_world)
        world = local @ matrix[:3, :3].T + matrix[:3, 3]
        points.append(world)
        evaluated.to_mesh_clear()
    zup = numpy.concatenate(points)
    return numpy.stack([zup[:, 0], zup[:, 2], -zup[:, 1]], axis=1)


def rtpro_vertices(frame):
    rows = []
    with open(os.path.join(dump_dir, "%d.txt" % frame)) as f:
        for line in f:
            if not line.startswith("mesh"):
                rows.append([float(v) for v in line.split()])
    return numpy.array(rows)


def accessor(gltf, index):
    spec = gltf["accessors"][index]
    view = gltf["bufferViews"][spec["bufferView"]]
    uri = gltf["buffers"][view["buffer"]]["uri"]
    if uri.startswith("data:"):
        data = base64.b64decode(uri.partition(",")[2])
    else:
        with open(os.path.join(os.path.dirname(gltf_file), uri), "rb") as f:
            data = f.read()
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[spec["type"]]
    start = view.get("byteOffset", 0) + spec.get("byteOffset", 0)
    return numpy.frombuffer(data[start:start + 4 * width * spec["count"]], dtype=numpy.float32).reshape(-1, width)


def nlerp_slerp_degrees(frame):
    with open(gltf_file) as f:
        gltf = json.load(f)
    worst = 0.0
    for animation in gltf.get("animations", []):
        for channel in animation["channels"]:
            sampler = animation["samplers"][channel["sampler"]]
            if channel["target"]["path"] != "rotation" or sampler.get("interpolation", "LINEAR") != "LINEAR":
                continue
            times, keys = accessor(gltf, sampler["input"])[:, 0], accessor(gltf, sampler["output"]).astype(float)
            time = frame / 24.0
            if time <= times[0] or time >= times[-1]:
                continue
            i = int(numpy.searchsorted(times, time, side="right")) - 1
            u = (time - times[i]) / (times[i + 1] - times[i])
            q0, q1 = keys[i] / numpy.linalg.norm(keys[i]), keys[i + 1] / numpy.linalg.norm(keys[i + 1])
            if q0 @ q1 < 0:
                q1 = -q1
            half = math.acos(min(1.0, q0 @ q1))
            if half < 1e-9:
                continue
            slerp = (math.sin((1 - u) * half) * q0 + math.sin(u * half) * q1) / math.sin(half)
            nlerp = (1 - u) * q0 + u * q1
            nlerp /= numpy.linalg.norm(nlerp)
            worst = max(worst, math.degrees(2 * math.acos(min(1.0, abs(nlerp @ slerp)))))
    return worst


def farthest_nearest(a, b):
    distances = numpy.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2))
    return distances.min(axis=1).max()


def slerp(q0, q1, u):
    half = math.acos(max(-1.0, min(1.0, q0 @ q1)))
    if half < 1e-9:
        return q0
    return (math.sin((1 - u) * half) * q0 + math.sin(u * half) * q1) / math.sin(half)


def rekey_rotations_by_slerp():
    """Keys every LINEAR quaternion F-curve quartet at each compared frame that lies between two of
    its keys with the slerp of those keys, so that Blender poses those frames as glTF interpolates.
    The importer's bone-space conversion multiplies every key by one constant quaternion, which
    slerp commutes with, so slerping Blender's keys is slerping the file's."""
    for action in bpy.data.actions:
        quartets = {}
        for fcurve in action.fcurves:
            if fcurve.data_path.endswith("rotation_quaternion"):
                quartets.setdefault(fcurve.data_path, [None] * 4)[fcurve.array_index] = fcurve
        for quartet in quartets.values():
            keys = [[(k.co[0], k.co[1], k.interpolation) for k in fcurve.keyframe_points] for fcurve in quartet]
            for frame in frames:
                for i in range(len(keys[0]) - 1):
                    (f0, _, interpolation), (f1, _, _) = keys[0][i], keys[0][i + 1]
                    if f0 < frame < f1 and interpolation == "LINEAR":
                        q0 = numpy.array([keys[c][i][1] for c in range(4)])
                        q1 = numpy.array([keys[c][i + 1][1] for c in range(4)])
                        value = slerp(q0 / numpy.linalg.norm(q0), q1 / numpy.linalg.norm(q1), (frame - f0) / (f1 - f0))
                        for c in range(4):
                            quartet[c].keyframe_points.insert(frame, value[c]).interpolation = "LINEAR"


def compare(ours, theirs):
    diagonal = numpy.linalg.norm(ours.max(axis=0) - ours.min(axis=0))
    hausdorff = max(farthest_nearest(ours, theirs), farthest_nearest(theirs, ours)) / diagonal
    box = max(numpy.abs(ours.min(axis=0) - theirs.min(axis=0)).max(),
              numpy.abs(ours.max(axis=0) - theirs.max(axis=0)).max()) / diagonal
    # Centroids of the distinct positions: the importer's splitting and merging would weigh them otherwise.
    centroid = numpy.linalg.norm(numpy.unique(ours.round(6), axis=0).mean(axis=0) -
                                 numpy.unique(theirs.round(6), axis=0).mean(axis=0)) / diagonal
    return hausdorff, box, centroid


as_imported = {frame: blender_vertices(frame) for frame in frames}
rekey_rotations_by_slerp()
for frame in frames:
    ours = rtpro_vertices(frame)
    hausdorff, box, centroid = compare(ours, as_imported[frame])
    slerped = compare(ours, blender_vertices(frame))[0]
    print("pose %d %d %d %.3g %.3g %.3g %.3g %.3g" % (frame, len(ours), len(as_imported[frame]), hausdorff, box,
                                                   centroid, nlerp_slerp_degrees(frame), slerped))
