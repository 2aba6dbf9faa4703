"""Renders a glTF file with Cycles as rtpro's path integrator renders it, for
benchmarks/cycles_benchmark.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_gltf.py -- FILE.gltf OUT.exr SIZE SPP MAX_DEPTH THREADS \
      [FRAME SHUTTER_OPEN SHUTTER_CLOSE [OPENING CLOSING]]

SIZE is N (N x N pixels) or WxH. With FRAME the file is rendered posed at that frame (glTF time t is
frame t x 24, as rtpro's render.fps and Blender's importer map it), and with an open shutter
(SHUTTER_OPEN < SHUTTER_CLOSE, in frames relative to FRAME, rtpro's camera.shutter) with Cycles'
motion blur over the same interval: shutter length CLOSE - OPEN placed by motion_blur_position
(START for [0, s], CENTER for [-s/2, s/2], END for [-s, 0]; other intervals are refused), object
and deformation motion on; with OPENING and CLOSING (rtpro's camera.shutter_opening) the shutter
curve is the trapezoid through (0, 0), (OPENING, 1), (CLOSING, 1) and (1, 0), its handles straight,
from which Cycles samples the time as rtpro does. Every sun's angle is 0 (rtpro's directional light
is a delta light).

Fair settings (see /work/shared/notes/pathtracing.md): CPU, no adaptive sampling, no denoising, a
one-pixel box filter, no clamping, the Standard view, 32-bit float EXR, a black world (or, with
RTPRO_CYCLES_ENVIRONMENT=HDRI in the environment, that image as the world, as rtpro's --environment). Path length:
rtpro's max_depth counts path vertices after the camera ray (1 is direct light only), Cycles'
max_bounces counts bounces (0 is direct light only), so Cycles gets MAX_DEPTH - 1.

Materials are rebuilt from the glTF's own values, each as the Cycles shader with the same model,
plus an Emission shader of emissiveFactor x KHR_materials_emissive_strength:
- Lambert (Cycles' Diffuse BSDF at roughness 0): non-metals with KHR_materials_specular's
  specularFactor 0, which glTF defines as the pure Lambert base;
- a white metal (metallicFactor 1, base colour 1): Schlick's Fresnel from F0 = 1 is 1 at every
  angle, Cycles' Glossy BSDF (multiple-scattering GGX, alpha = roughness^2) of colour 1;
- glass (KHR_materials_transmission 1, a non-metal, base colour 1, roughness 0): Cycles' sharp
  Glass BSDF at KHR_materials_ior's index (glTF's Fresnel is Schlick's, Cycles' the exact one: at
  ior 1.5 the reflectance differs by up to 0.036, near grazing incidence).
Anything else is refused. The importer's Principled BSDF would use Disney diffuse, ~12% brighter
on the Cornell box.
Prints one line: "cycles_render_seconds S" (the render call: scene sync, BVH and sampling).
"""
import json
import sys
import os

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_materials import bsdf_node, empty_node_tree  # noqa: E402
from cycles_scene import hdri_world  # noqa: E402
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

numpy.bool = bool  # Blender 3.4's glTF importer still uses numpy.bool, removed in Debian's numpy 1.24

args = sys.argv[sys.argv.index("--") + 1:]
gltf_file, out_file = args[0], args[1]
width, _, height = args[2].partition("x")
width, height = int(width), int(height or width)
spp, max_depth, threads = (int(a) for a in args[3:6])
frame, shutter_open, shutter_close = (float(a) for a in args[6:9]) if len(args) > 6 else (None, 0.0, 0.0)
opening, closing = (float(a) for a in args[9:11]) if len(args) > 9 else (0.0, 1.0)

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=gltf_file)
scene = bpy.context.scene

with open(gltf_file) as f:
    gltf = json.load(f)
for spec in gltf.get("materials", []):
    material = bpy.data.materials.get(spec.get("name", ""))
    if material is None:
        continue
    pbr = spec.get("pbrMetallicRoughness", {})
    extensions = spec.get("extensions", {})
    specular = extensions.get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    transmission = extensions.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
    ior = extensions.get("KHR_materials_ior", {}).get("ior", 1.5)
    metallic, roughness = pbr.get("metallicFactor", 1.0), pbr.get("roughnessFactor", 1.0)
    base = pbr.get("baseColorFactor", [1, 1, 1, 1])
    white = list(base[:3]) == [1, 1, 1]
    if metallic == 0.0 and specular == 0.0 and transmission == 0.0:
        kind = "lambert"
    elif metallic == 1.0 and white and transmission == 0.0:
        kind = "metal"
    elif metallic == 0.0 and transmission == 1.0 and white and roughness == 0.0:
        kind = "glass"
    else:
        sys.exit("render_gltf.py: material %s is none of Lambert, white metal or clear glass" % spec.get("name"))
    emission = spec.get("emissiveFactor", [0, 0, 0])
    strength = spec.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    nodes, links, output = empty_node_tree(material)
    bsdf = bsdf_node(nodes, kind, base, roughness, ior)
    shader = bsdf.outputs["BSDF"]
    if max(emission) > 0.0:
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (emission[0], emission[1], emission[2], 1.0)
        emit.inputs["Strength"].default_value = strength
        add = nodes.new("ShaderNodeAddShader")
        links.new(bsdf.outputs["BSDF"], add.inputs[0])
        links.new(emit.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, output.inputs["Surface"])

cameras = [o for o in scene.objects if o.type == "CAMERA"]
scene.camera = cameras[0]
environment = os.environ.get("RTPRO_CYCLES_ENVIRONMENT", "")
if environment:
    hdri_world(scene, environment)  # rtpro's `--environment FILE`, unturned
else:
    scene.world = bpy.data.worlds.new("black")
    scene.world.use_nodes = True
    scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0

if frame is not None:
    scene.frame_set(int(frame), subframe=frame - int(frame))
if shutter_close > shutter_open:
    length = shutter_close - shutter_open
    positions = {0.0: "START", -length / 2: "CENTER", -length: "END"}
    if shutter_open not in positions:
        sys.exit("render_gltf.py: Cycles places its shutter at the frame's start, centre or end; not [%g, %g]"
                 % (shutter_open, shutter_close))
    scene.render.use_motion_blur = True
    scene.render.motion_blur_shutter = length
    scene.cycles.motion_blur_position = positions[shutter_open]
    if (opening, closing) != (0.0, 1.0):
        curve = scene.render.motion_blur_shutter_curve
        points = curve.curves[0].points
        corners = [(0.0, 0.0 if opening > 0.0 else 1.0)]
        if opening > 0.0:
            corners.append((opening, 1.0))
        if opening < closing < 1.0:
            corners.append((closing, 1.0))
        corners.append((1.0, 0.0 if closing < 1.0 else 1.0))
        while len(points) < len(corners):
            points.new(0.5, 0.5)
        while len(points) > len(corners):
            points.remove(points[len(points) - 1])
        for point, corner in zip(points, corners):
            point.location = corner
            point.handle_type = "VECTOR"
        curve.update()
    for obj in scene.objects:
        obj.cycles.use_motion_blur = True
        obj.cycles.use_deform_motion = True
for obj in scene.objects:
    if obj.type == "LIGHT" and obj.data.type == "SUN":
        obj.data.angle = 0.0  # rtpro's directional light is a delta light

configure_cycles(scene, spp, max_depth, threads)
render_timed_exr(scene, width, height, out_file)
