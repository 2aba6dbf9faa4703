"""Renders the environment benchmark's spheres with Cycles, for
benchmarks/cycles_environment_benchmark.sh. Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_environment.py -- HDRI.exr OUT.exr WIDTH HEIGHT SPP MAX_DEPTH THREADS

The scene is benchmarks/scenes/sunset_spheres.yaml (positions in rtpro's +Y-up axes, turned to
Blender's +Z-up ones: (x, y, z) -> (x, -z, y)): a ground sphere of radius 1000 under a Lambertian
clay sphere and a white rough metal sphere, lit only by the HDRI as the world (an Environment
Texture, rotated as rtpro's `rotation: [0, 160, 0]`, which FORMAT.md states is a Mapping node
rotation of -160 degrees about Blender's Z). Spheres are meshes with the exact sphere normal at each
vertex: the small ones UV spheres of 256 x 128 quads, the ground the part of its sphere within 190
units of the top (a 600 x 600 grid, 0.63 units a cell, its faces 0.05 mm from the sphere; every
point a camera ray or a path from the objects can reach lies inside it, the rest hiding below the
horizon). Blender's own UV sphere operators take minutes at these sizes, so the meshes are built
from numpy arrays. The materials are the same models:
Cycles' Diffuse BSDF at roughness 0 (Lambert) and its Glossy BSDF with multiple-scattering GGX at
roughness 0.3 (alpha = roughness^2, as rtpro's conductor) of colour 1 (rtpro's conductor of colour 1:
Schlick's Fresnel from F0 = 1 is 1 at every angle). The world uses multiple importance sampling
(sampling_method AUTOMATIC); settings otherwise as render_gltf.py's (no adaptive sampling, no
denoising, a one-pixel box filter, no clamping, Standard view, 32-bit EXR; Cycles' max_bounces is
rtpro's max_depth - 1).
Prints one line: "cycles_render_seconds S".
"""
import sys
import os

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_materials import bsdf_node, empty_node_tree  # noqa: E402
from cycles_scene import grid_quads, hdri_world, look_at_camera, mesh_object, uv_sphere  # noqa: E402
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
hdri, out_file = args[0], args[1]
width, height, spp, max_depth, threads = (int(a) for a in args[2:7])

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def material(name, kind, color):
    m = bpy.data.materials.new(name)
    nodes, links, output = empty_node_tree(m)
    links.new(bsdf_node(nodes, kind, color, roughness=0.3).outputs["BSDF"], output.inputs["Surface"])
    return m


def ground_cap(name, radius, mat, half_width=190.0, cells=600):
    """The top of the sphere of `radius` whose top is at the origin, over a square of the xy plane."""
    u = numpy.linspace(-half_width, half_width, cells + 1)
    x, y = numpy.meshgrid(u, u, indexing="ij")
    z = numpy.sqrt(radius * radius - x * x - y * y) - radius
    points = numpy.stack([x, y, z], axis=-1).reshape(-1, 3)
    return mesh_object(scene, name, points, grid_quads(cells, cells), (0.0, 0.0, -radius), mat)


ground_cap("ground", 1000.0, material("ground", "lambert", (0.4, 0.4, 0.4)))
uv_sphere(scene, "clay", (-0.6, 0.5, 0), 0.5, material("clay", "lambert", (0.8, 0.6, 0.5)))
uv_sphere(scene, "metal", (0.6, 0.5, 0), 0.5, material("metal", "metal", (1.0, 1.0, 1.0)))

look_at_camera(scene, (0, 0.7, -4), (0, 0.35, 0), 35.0)

hdri_world(scene, hdri, 160.0)  # rtpro's `rotation: [0, 160, 0]`

configure_cycles(scene, spp, max_depth, threads)
render_timed_exr(scene, width, height, out_file)
