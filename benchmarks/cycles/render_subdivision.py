"""Renders a subdivided, displaced cage with Cycles, for benchmarks/cycles_subdivision_benchmark.sh.
Run by Debian's Blender 3.4:

  blender -b --factory-startup --python render_subdivision.py -- OUT.rgba.exr SIZE SPP MAX_DEPTH \
      THREADS CAGE.obj TEXTURE.exr LEVEL SCALE R,G,B SKY SUN_X,SUN_Y,SUN_Z SUN CAM_X,CAM_Y,CAM_Z \
      AT_X,AT_Y,AT_Z FOV

The cage is the OBJ's vertices, texture coordinates and faces (quads kept; rtpro's axes turned
into Blender's, cycles_scene.py), smooth-shaded, with a Subdivision Surface modifier of LEVEL
render levels: Catmull-Clark on the limit surface (use_limit_surface), boundaries and uvs
interpolated as OpenSubdiv's edge-and-corner and linear-corners-only rules that rtpro uses
(boundary_smooth and uv_smooth PRESERVE_CORNERS). Its material: a Diffuse BSDF (roughness 0:
Lambert) of colour R,G,B, and true displacement (displacement_method DISPLACEMENT) by a Displacement
node of Midlevel 0 and Scale SCALE in object space, its Height the first channel of TEXTURE (an Image
Texture: Non-Color, linear interpolation, repeat) at the UV map: each vertex of the subdivided mesh
moves along its normal by SCALE x the texture, as rtpro's `displacement: {texture, scale}` moves it.
The world a uniform sky of radiance SKY, light-sampled, transparent to the camera (film_transparent:
the alpha channel is the object's coverage); a sun of irradiance SUN travelling along SUN_X,SUN_Y,SUN_Z
(rtpro's axes) with an angle of 0 (rtpro's directional light). Settings otherwise cycles_settings.py's.
Prints "cycles_render_seconds S".
"""
import os
import sys

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_materials import bsdf_node, empty_node_tree  # noqa: E402
from cycles_scene import blender_axes, view_from_args  # noqa: E402
from cycles_settings import configure_cycles, render_timed_exr  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
out_file = args[0]
size, spp, max_depth, threads = (int(a) for a in args[1:5])
cage_file, texture_file = args[5], args[6]
level, scale = int(args[7]), float(args[8])
color = [float(c) for c in args[9].split(",")]


def read_obj(path):
    """The OBJ's positions (rtpro's axes), texture coordinates, and faces as lists of (v, vt)."""
    positions, uvs, faces = [], [], []
    for line in open(path):
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            positions.append([float(w) for w in words[1:4]])
        elif words[0] == "vt":
            uvs.append([float(w) for w in words[1:3]])
        elif words[0] == "f":
            faces.append([tuple(int(i) - 1 for i in corner.split("/")[:2]) for corner in words[1:]])
    return positions, uvs, faces


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

positions, uvs, faces = read_obj(cage_file)
mesh = bpy.data.meshes.new("cage")
mesh.vertices.add(len(positions))
mesh.vertices.foreach_set("co", numpy.array([blender_axes(p) for p in positions], dtype=numpy.float32).ravel())
corners = [corner for face in faces for corner in face]
mesh.loops.add(len(corners))
mesh.loops.foreach_set("vertex_index", numpy.array([v for v, _ in corners], dtype=numpy.int32))
mesh.polygons.add(len(faces))
sizes = numpy.array([len(face) for face in faces], dtype=numpy.int32)
mesh.polygons.foreach_set("loop_start", numpy.concatenate([[0], numpy.cumsum(sizes)[:-1]]).astype(numpy.int32))
mesh.polygons.foreach_set("loop_total", sizes)
mesh.polygons.foreach_set("use_smooth", numpy.ones(len(faces), dtype=bool))
mesh.update(calc_edges=True)
uv_layer = mesh.uv_layers.new(name="UVMap")
uv_layer.data.foreach_set("uv", numpy.array([uvs[t] for _, t in corners], dtype=numpy.float32).ravel())
mesh.validate()

material = bpy.data.materials.new("displaced")
nodes, links, output = empty_node_tree(material)
links.new(bsdf_node(nodes, "lambert", color).outputs["BSDF"], output.inputs["Surface"])
texture = nodes.new("ShaderNodeTexImage")
texture.image = bpy.data.images.load(texture_file)
texture.image.colorspace_settings.name = "Non-Color"
texture.interpolation = "Linear"
texture.extension = "REPEAT"
uv_map = nodes.new("ShaderNodeUVMap")
uv_map.uv_map = "UVMap"
links.new(uv_map.outputs["UV"], texture.inputs["Vector"])
displacement = nodes.new("ShaderNodeDisplacement")
displacement.space = "OBJECT"
displacement.inputs["Midlevel"].default_value = 0.0
displacement.inputs["Scale"].default_value = scale
links.new(texture.outputs["Color"], displacement.inputs["Height"])
links.new(displacement.outputs["Displacement"], output.inputs["Displacement"])
material.cycles.displacement_method = "DISPLACEMENT"
mesh.materials.append(material)

obj = bpy.data.objects.new("cage", mesh)
scene.collection.objects.link(obj)
subdivision = obj.modifiers.new("subdivision", "SUBSURF")
subdivision.subdivision_type = "CATMULL_CLARK"
subdivision.levels = subdivision.render_levels = level
subdivision.use_limit_surface = True
subdivision.boundary_smooth = "PRESERVE_CORNERS"
subdivision.uv_smooth = "PRESERVE_CORNERS"
subdivision.use_creases = True

view_from_args(scene, args[10:16])

configure_cycles(scene, spp, max_depth, threads)
render_timed_exr(scene, size, size, out_file)
