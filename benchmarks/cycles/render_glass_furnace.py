"""Renders the rough-glass white furnace with Cycles, for benchmarks/cycles_glass_furnace_benchmark.sh.
Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_glass_furnace.py -- OUT_PREFIX SIZE SPP MAX_DEPTH THREADS ROUGHNESS...

The scene is the benchmark's rtpro furnace (a sphere of radius 1 at the origin, seen from (0, 0, -4)
with a 20-degree field of view, so that it fills the image) in Blender's axes: the sphere a UV sphere
of 256 x 128 quads with the exact sphere normals (cycles_scene.py), its material a Principled BSDF
of base colour 1, Transmission 1, IOR 1.5 and the multiple-scattering GGX distribution (`MULTI_GGX`,
whose glass is energy-conserving: alpha = roughness^2, the one roughness for both reflection and
refraction), the world a uniform Background of colour 1 and strength 1, not light-sampled
(sampling_method NONE), as rtpro's `background` is not. Settings otherwise cycles_settings.py's.
One Blender start renders every roughness into OUT_PREFIX-ROUGHNESS.rgba.exr; prints
"cycles_render_seconds S" for each.
"""
import sys
import os

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_materials import empty_node_tree  # noqa: E402
from cycles_scene import look_at_camera, uv_sphere  # noqa: E402
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
out_prefix = args[0]
size, spp, max_depth, threads = (int(a) for a in args[1:5])
roughnesses = args[5:]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

glass = bpy.data.materials.new("glass")
nodes, links, output = empty_node_tree(glass)
principled = nodes.new("ShaderNodeBsdfPrincipled")
principled.distribution = "MULTI_GGX"
principled.inputs["Base Color"].default_value = (1.0, 1.0, 1.0, 1.0)
principled.inputs["Metallic"].default_value = 0.0
principled.inputs["Transmission"].default_value = 1.0
principled.inputs["IOR"].default_value = 1.5
principled.inputs["Transmission Roughness"].default_value = 0.0
links.new(principled.outputs["BSDF"], output.inputs["Surface"])
uv_sphere(scene, "sphere", (0.0, 0.0, 0.0), 1.0, glass)

look_at_camera(scene, (0.0, 0.0, -4.0), (0.0, 0.0, 0.0), 20.0)

world = bpy.data.worlds.new("furnace")
scene.world = world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
world.cycles.sampling_method = "NONE"

configure_cycles(scene, spp, max_depth, threads)
for roughness in roughnesses:
    principled.inputs["Roughness"].default_value = float(roughness)
    render_timed_exr(scene, size, size, f"{out_prefix}-{roughness}.rgba.exr")
