"""Renders the strands of a Cem Yuksel .hair file with Cycles' Principled Hair BSDF, for
benchmarks/cycles_hair_benchmark.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_hair.py -- OUT.rgba.exr SIZE SPP MAX_DEPTH THREADS \
      STRANDS.hair SIGMA_R,SIGMA_G,SIGMA_B BETA_M BETA_N ALPHA_DEGREES IOR SKY SUN_X,SUN_Y,SUN_Z SUN \
      CAM_X,CAM_Y,CAM_Z AT_X,AT_Y,AT_Z FOV

The strands (each strand's points, rtpro's axes turned into Blender's, cycles_scene.py, and a radius
of half the file's thickness at each point) become a legacy curve object of poly splines, converted
into Blender 3.4's Curves (hair) object, which Cycles renders as round Catmull-Rom curves through
the points (scene.cycles_curves.shape THICK: Embree's round curves), its ends repeated as rtpro's
`basis: catmull-rom` has them. The material: the Principled Hair BSDF (Chiang et al. 2016) with the
Absorption Coefficient parametrization (σa as rtpro's `sigma_a`, per unit of the fibre's radius in
both), Roughness β_m, Radial Roughness β_n, Coat 0, IOR, Offset −α (Cycles' cuticle tilt has the
opposite sign of pbrt-v4's and rtpro's `alpha`) and no random colour or roughness: rtpro's
`type: hair` with the same keys. The world a uniform sky of radiance
SKY, light-sampled, transparent to the camera (film_transparent); a sun of irradiance SUN travelling
along SUN_X,SUN_Y,SUN_Z with an angle of 0 (rtpro's directional light). Settings otherwise
cycles_settings.py's. Prints "cycles_render_seconds S".
"""
import math
import os
import struct
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_materials import empty_node_tree  # noqa: E402
from cycles_scene import blender_axes, view_from_args  # noqa: E402
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
out_file = args[0]
size, spp, max_depth, threads = (int(a) for a in args[1:5])
hair_file = args[5]
sigma_a = [float(c) for c in args[6].split(",")]
beta_m, beta_n, alpha, ior = (float(a) for a in args[7:11])


def read_hair(path):
    """The strands of a .hair file: a list of (points, radii) per strand (rtpro's axes)."""
    data = open(path, "rb").read()
    if data[:4] != b"HAIR":
        sys.exit(f"{path}: not a .hair file")
    strands, points, flags, default_segments, default_thickness = struct.unpack_from("<IIIIf", data, 4)
    offset = 128
    if flags & 1:
        segments = struct.unpack_from(f"<{strands}H", data, offset)
        offset += 2 * strands
    else:
        segments = [default_segments] * strands
    if not flags & 2:
        sys.exit(f"{path}: no points array")
    xyz = struct.unpack_from(f"<{3 * points}f", data, offset)
    offset += 12 * points
    thickness = struct.unpack_from(f"<{points}f", data, offset) if flags & 4 else [default_thickness] * points
    result, first = [], 0
    for s in segments:
        n = s + 1
        result.append(([xyz[3 * i:3 * i + 3] for i in range(first, first + n)],
                       [thickness[i] / 2 for i in range(first, first + n)]))
        first += n
    return result


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

curve = bpy.data.curves.new("strands", "CURVE")
curve.dimensions = "3D"
for points, radii in read_hair(hair_file):
    spline = curve.splines.new("POLY")
    spline.points.add(len(points) - 1)
    spline.points.foreach_set("co", [c for p in points for c in (*blender_axes(p), 1.0)])
    spline.points.foreach_set("radius", radii)
obj = bpy.data.objects.new("strands", curve)
scene.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
obj.select_set(True)
bpy.ops.object.convert(target="CURVES")
obj = bpy.context.view_layer.objects.active
assert obj.type == "CURVES", obj.type
curve_type = obj.data.attributes["curve_type"]
curve_type.data.foreach_set("value", [0] * len(curve_type.data))  # CATMULL_ROM
scene.cycles_curves.shape = "THICK"

material = bpy.data.materials.new("hair")
nodes, links, output = empty_node_tree(material)
hair = nodes.new("ShaderNodeBsdfHairPrincipled")
hair.parametrization = "ABSORPTION"
hair.inputs["Absorption Coefficient"].default_value = sigma_a
hair.inputs["Roughness"].default_value = beta_m
hair.inputs["Radial Roughness"].default_value = beta_n
hair.inputs["Coat"].default_value = 0.0
hair.inputs["IOR"].default_value = ior
# Cycles tilts the light's angle by +2α, −α, −4α where pbrt-v4 (and rtpro) tilt the viewer's by
# −2α, +α, +4α: the same highlights for Cycles' Offset −α (third_party_notes/blender-cycles.md).
hair.inputs["Offset"].default_value = math.radians(-alpha)
hair.inputs["Random Color"].default_value = 0.0
hair.inputs["Random Roughness"].default_value = 0.0
links.new(hair.outputs["BSDF"], output.inputs["Surface"])
obj.data.materials.append(material)

view_from_args(scene, args[11:17])

configure_cycles(scene, spp, max_depth, threads)
render_timed_exr(scene, size, size, out_file)
