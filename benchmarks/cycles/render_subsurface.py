"""Renders the subsurface sphere with Cycles, for benchmarks/cycles_subsurface_benchmark.sh. Run by
Debian's Blender 3.4:

  blender -b --factory-startup --python render_subsurface.py -- OUT_PREFIX SIZE SPP MAX_DEPTH THREADS \
      R,G,B RADIUS_R,RADIUS_G,RADIUS_B ANISOTROPY IOR SEED METHOD...

The scene is the benchmark's rtpro scene (a sphere of radius 1 at the origin, seen from (0, 0, -4)
with a 20-degree field of view) in Blender's axes: the sphere a UV sphere of 256 x 128 quads with
the exact sphere normals (cycles_scene.py), its material Cycles' Subsurface Scattering node alone
(colour R,G,B, Scale 1, the radius per channel, the anisotropy and IOR given): the random walk that
the Principled BSDF's subsurface takes, without the Principled's Disney-diffuse Fresnel factors at
entry and exit, so that it is rtpro's principled material at specular_weight 0 and subsurface 1
(entry and exit through plain Lambert lobes). The world a uniform Background of colour 1 and
strength 1, not light-sampled (sampling_method NONE), as rtpro's `background` is not. Settings
otherwise cycles_settings.py's, Cycles' seed SEED. One Blender start renders each METHOD (RANDOM_WALK,
RANDOM_WALK_FIXED_RADIUS) into OUT_PREFIX-METHOD.rgba.exr; prints "cycles_render_seconds S" for each.
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
color = [float(c) for c in args[5].split(",")]
radius = [float(r) for r in args[6].split(",")]
anisotropy, ior, seed = float(args[7]), float(args[8]), int(args[9])
methods = args[10:]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

skin = bpy.data.materials.new("subsurface")
nodes, links, output = empty_node_tree(skin)
sss = nodes.new("ShaderNodeSubsurfaceScattering")
sss.inputs["Color"].default_value = (color[0], color[1], color[2], 1.0)
sss.inputs["Scale"].default_value = 1.0
sss.inputs["Radius"].default_value = radius
sss.inputs["IOR"].default_value = ior
sss.inputs["Anisotropy"].default_value = anisotropy
links.new(sss.outputs["BSSRDF"], output.inputs["Surface"])
uv_sphere(scene, "sphere", (0.0, 0.0, 0.0), 1.0, skin)

look_at_camera(scene, (0.0, 0.0, -4.0), (0.0, 0.0, 0.0), 20.0)

world = bpy.data.worlds.new("sky")
scene.world = world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
world.cycles.sampling_method = "NONE"

configure_cycles(scene, spp, max_depth, threads)
scene.cycles.seed = seed
for method in methods:
    sss.falloff = method
    render_timed_exr(scene, size, size, f"{out_prefix}-{method}.rgba.exr")
