"""Renders a glTF file with Cycles as rtpro's path integrator renders it, for
benchmarks/cycles_benchmark.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_gltf.py -- FILE.gltf OUT.exr SIZE SPP MAX_DEPTH THREADS

Fair settings (see /work/shared/notes/pathtracing.md): CPU, no adaptive sampling, no denoising, a
one-pixel box filter, no clamping, the Standard view, 32-bit float EXR, a black world. Path length:
rtpro's max_depth counts path vertices after the camera ray (1 is direct light only), Cycles'
max_bounces counts bounces (0 is direct light only), so Cycles gets MAX_DEPTH - 1.

Materials are rebuilt from the glTF's own values as Lambert (Cycles' Diffuse BSDF at roughness 0)
plus an Emission shader of emissiveFactor x KHR_materials_emissive_strength. Only materials that
glTF defines as Lambert are accepted: non-metals with KHR_materials_specular's specularFactor 0
(the pure Lambert base). The importer's Principled BSDF would use Disney diffuse, ~12% brighter
on the Cornell box.
Prints one line: "cycles_render_seconds S" (the render call: scene sync, BVH and sampling).
"""
import json
import sys
import time

import bpy
import numpy

numpy.bool = bool  # Blender 3.4's glTF importer still uses numpy.bool, removed in Debian's numpy 1.24

args = sys.argv[sys.argv.index("--") + 1:]
gltf_file, out_file = args[0], args[1]
size, spp, max_depth, threads = (int(a) for a in args[2:6])

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
    specular = spec.get("extensions", {}).get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    if pbr.get("metallicFactor", 1.0) != 0.0 or specular != 0.0:
        sys.exit("render_gltf.py: only Lambert materials (non-metals, specularFactor 0) are mapped (material %s)"
                 % spec.get("name"))
    base = pbr.get("baseColorFactor", [1, 1, 1, 1])
    emission = spec.get("emissiveFactor", [0, 0, 0])
    strength = spec.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (base[0], base[1], base[2], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    shader = diffuse.outputs["BSDF"]
    if max(emission) > 0.0:
        emit = nodes.new("ShaderNodeEmission")
        emit.inputs["Color"].default_value = (emission[0], emission[1], emission[2], 1.0)
        emit.inputs["Strength"].default_value = strength
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs["BSDF"], add.inputs[0])
        links.new(emit.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, output.inputs["Surface"])

cameras = [o for o in scene.objects if o.type == "CAMERA"]
scene.camera = cameras[0]
scene.world = bpy.data.worlds.new("black")
scene.world.use_nodes = True
scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0

scene.render.engine = "CYCLES"
cycles = scene.cycles
cycles.device = "CPU"
cycles.samples = spp
cycles.use_adaptive_sampling = False
cycles.use_denoising = False
cycles.pixel_filter_type = "BOX"
cycles.filter_width = 1.0
cycles.sample_clamp_direct = 0.0
cycles.sample_clamp_indirect = 0.0
cycles.max_bounces = max_depth - 1
cycles.diffuse_bounces = cycles.glossy_bounces = cycles.transmission_bounces = max_depth - 1
cycles.transparent_max_bounces = max_depth - 1
cycles.caustics_reflective = cycles.caustics_refractive = True
cycles.blur_glossy = 0.0
cycles.seed = 0
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.resolution_x = scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.use_persistent_data = False
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.exr_codec = "ZIP"
scene.render.filepath = out_file

start = time.perf_counter()
bpy.ops.render.render(write_still=True)
print("cycles_render_seconds %.3f" % (time.perf_counter() - start))
