"""Renders benchmarks/scenes/smoke_hdri.yaml's cloud with Cycles, for
benchmarks/cycles_volume_benchmark.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_volume.py -- SMOKE.vdb OUT.exr WIDTH HEIGHT SPP MAX_DEPTH THREADS SEED HDRI.exr

The scene is benchmarks/scenes/smoke_hdri.yaml in Blender's +Z-up axes (rtpro's (x, y, z) is Blender's (x, -z, y)):
the VDB imported as a Volume object (Blender's own VDB import) turned +90 degrees about X, so the
file's +Y (rtpro's up) is Blender's +Z, with a Principled Volume of the same optics: Color = the
albedo and Absorption Color black, so that σs = Color × density and σa = (1 − Color) × density
(Cycles' svm_node_principled_volume), Density = density_scale (the "density" grid is its Density
Attribute), Anisotropy = g, no emission. A Sun of the same strength (irradiance, W/m²) and colour
along the same direction with angle 0 (rtpro's directional light is a delta), and the HDRI as the
world at strength 0.25 (an Environment Texture turned as rtpro's `rotation: [0, 160, 0]`, a Mapping
node rotation of -160 degrees about Blender's Z, as render_environment.py; the world's multiple
importance sampling on). Cycles ray-marches heterogeneous volumes (its step rate 1: one step a voxel,
volume_max_steps 1024); rtpro tracks them without bias, so their means agree only within that
bias. Settings otherwise as render_gltf.py's (cycles_settings.py), with volume_bounces =
max_depth - 1 too (Cycles' default is 0: single scattering).
SEED is Cycles' seed: the benchmark's long reference takes another than the runs it is
compared with, so that their noise is not shared.
Prints one line: "cycles_render_seconds S".
"""
import math
import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
vdb, out_file = args[0], args[1]
width, height, spp, max_depth, threads = (int(a) for a in args[2:7])
seed, hdri = int(args[7]), args[8]

DENSITY_SCALE, ALBEDO, ANISOTROPY = 8.0, (0.9, 0.9, 0.9), 0.3
HDRI_STRENGTH, HDRI_TURN = 0.25, -160.0
SUN_DIRECTION, SUN_COLOR, SUN_STRENGTH = (-0.6, -0.8, 0.45), (1.0, 0.94, 0.85), 3.0

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def blender_axes(p):
    """rtpro's +Y-up (x, y, z) in Blender's +Z-up axes."""
    return Vector((p[0], -p[2], p[1]))


bpy.ops.object.volume_import(filepath=os.path.abspath(vdb), align="WORLD", location=(0.0, 0.0, 0.0))
cloud = bpy.context.selected_objects[0] if bpy.context.selected_objects else bpy.data.objects[-1]
cloud.rotation_euler = (math.radians(90.0), 0.0, 0.0)
material = bpy.data.materials.new("smoke")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
nodes.clear()
output = nodes.new("ShaderNodeOutputMaterial")
volume = nodes.new("ShaderNodeVolumePrincipled")
volume.inputs["Color"].default_value = (*ALBEDO, 1.0)
volume.inputs["Absorption Color"].default_value = (0.0, 0.0, 0.0, 1.0)
volume.inputs["Density"].default_value = DENSITY_SCALE
volume.inputs["Density Attribute"].default_value = "density"
volume.inputs["Anisotropy"].default_value = ANISOTROPY
volume.inputs["Emission Strength"].default_value = 0.0
volume.inputs["Blackbody Intensity"].default_value = 0.0
links.new(volume.outputs["Volume"], output.inputs["Volume"])
cloud.data.materials.append(material)

sun_data = bpy.data.lights.new("sun", "SUN")
sun_data.energy = SUN_STRENGTH
sun_data.color = SUN_COLOR
sun_data.angle = 0.0
sun = bpy.data.objects.new("sun", sun_data)
scene.collection.objects.link(sun)
sun.rotation_euler = blender_axes(SUN_DIRECTION).normalized().to_track_quat("-Z", "Y").to_euler()

camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle_y = math.radians(32.0)
camera = bpy.data.objects.new("camera", camera_data)
scene.collection.objects.link(camera)
camera.location = blender_axes((0.0, 0.4, -5.0))
camera.rotation_euler = (blender_axes((0.0, 0.05, 0.0)) - camera.location).to_track_quat("-Z", "Y").to_euler()
scene.camera = camera

world = bpy.data.worlds.new("hdri")
scene.world = world
world.use_nodes = True
world_nodes, world_links = world.node_tree.nodes, world.node_tree.links
texture = world_nodes.new("ShaderNodeTexEnvironment")
texture.image = bpy.data.images.load(os.path.abspath(hdri))
texture.interpolation = "Linear"
mapping = world_nodes.new("ShaderNodeMapping")
mapping.vector_type = "POINT"
mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(HDRI_TURN))
coordinates = world_nodes.new("ShaderNodeTexCoord")
world_links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
world_links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
world_links.new(texture.outputs["Color"], world_nodes["Background"].inputs["Color"])
world_nodes["Background"].inputs["Strength"].default_value = HDRI_STRENGTH
world.cycles.sampling_method = "AUTOMATIC"

configure_cycles(scene, spp, max_depth, threads)
scene.cycles.volume_bounces = max_depth - 1
scene.cycles.seed = seed
scene.cycles.volume_step_rate = 1.0
scene.cycles.volume_max_steps = 1024
render_timed_exr(scene, width, height, out_file)
