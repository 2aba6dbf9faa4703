"""rtpro's scene parts in Blender for the Cycles side of rtpro's benchmarks, shared by
render_environment.py and render_glass_furnace.py: rtpro's axes, its camera, and spheres. Cycles has
no analytic sphere, so spheres are meshes with the exact sphere normal at each vertex (Blender's own
UV sphere operators take minutes at these sizes: the meshes are built from numpy arrays)."""
import math

import bpy
import numpy
from mathutils import Vector


def blender_axes(p):
    """rtpro's +Y-up (x, y, z) in Blender's +Z-up axes."""
    return Vector((p[0], -p[2], p[1]))


def look_at_camera(scene, position, target, fov_y):
    """The scene's camera at rtpro's `position` looking at `target`, with rtpro's vertical field of
    view of `fov_y` degrees."""
    camera_data = bpy.data.cameras.new("camera")
    camera_data.sensor_fit = "VERTICAL"
    camera_data.angle_y = math.radians(fov_y)
    camera = bpy.data.objects.new("camera", camera_data)
    scene.collection.objects.link(camera)
    camera.location = blender_axes(position)
    camera.rotation_euler = (blender_axes(target) - camera.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera


def mesh_object(scene, name, points, quads, center, mat):
    """A mesh of quads (degenerate ones at poles are fine) with the sphere's normals about `center`,
    of material `mat`, linked into `scene`."""
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(len(points))
    mesh.vertices.foreach_set("co", points.astype(numpy.float32).ravel())
    mesh.loops.add(quads.size)
    mesh.loops.foreach_set("vertex_index", quads.astype(numpy.int32).ravel())
    mesh.polygons.add(len(quads))
    mesh.polygons.foreach_set("loop_start", numpy.arange(0, quads.size, 4, dtype=numpy.int32))
    mesh.polygons.foreach_set("loop_total", numpy.full(len(quads), 4, dtype=numpy.int32))
    mesh.polygons.foreach_set("use_smooth", numpy.ones(len(quads), dtype=bool))
    mesh.update(calc_edges=True)
    mesh.validate()
    normals = points - numpy.asarray(center)
    normals /= numpy.linalg.norm(normals, axis=1)[:, None]
    mesh.use_auto_smooth = True
    mesh.normals_split_custom_set_from_vertices([tuple(n) for n in normals])
    mesh.materials.append(mat)
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


def grid_quads(rows, columns):
    """Quads of a (rows + 1) x (columns + 1) grid of vertices, row by row, wound so that their
    normal is (next row - this row) x (next column - this column): outwards for the spheres below."""
    r, c = numpy.meshgrid(numpy.arange(rows), numpy.arange(columns), indexing="ij")
    first = (r * (columns + 1) + c).ravel()
    return numpy.stack([first, first + columns + 1, first + columns + 2, first + 1], axis=1)


def uv_sphere(scene, name, center, radius, mat, segments=256, rings=128):
    """A sphere of `radius` about rtpro's `center`, of segments x rings quads."""
    c = blender_axes(center)
    theta = numpy.linspace(0.0, numpy.pi, rings + 1)[:, None]
    phi = numpy.linspace(0.0, 2.0 * numpy.pi, segments + 1)[None, :]
    points = numpy.stack([numpy.sin(theta) * numpy.cos(phi), numpy.sin(theta) * numpy.sin(phi),
                          numpy.cos(theta) * numpy.ones_like(phi)], axis=-1).reshape(-1, 3) * radius + numpy.asarray(c)
    return mesh_object(scene, name, points, grid_quads(rings, segments), c, mat)


def sky_and_sun(scene, sky, sun_direction, sun):
    """rtpro's `environment: {color: [sky, sky, sky], visible: false}` with `render.background`
    black, and a directional light of irradiance `sun` travelling along rtpro's `sun_direction`:
    a uniform world of radiance `sky`, light-sampled, transparent to the camera (film_transparent:
    the alpha channel is what the objects cover), and a sun of that strength with an angle of 0."""
    world = bpy.data.worlds.new("sky")
    scene.world = world
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (sky, sky, sky, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    world.cycles.sampling_method = "AUTOMATIC"
    scene.render.film_transparent = True
    scene.render.image_settings.color_mode = "RGBA"
    sun_data = bpy.data.lights.new("sun", "SUN")
    sun_data.energy = sun
    sun_data.angle = 0.0
    sun_object = bpy.data.objects.new("sun", sun_data)
    scene.collection.objects.link(sun_object)
    sun_object.rotation_euler = blender_axes(sun_direction).to_track_quat("-Z", "Y").to_euler()


def hdri_world(scene, hdri, rotation_degrees=0.0):
    """rtpro's `environment: {file: HDRI, rotation: [0, R, 0]}`: the image as the world on generated
    coordinates, turned by a Mapping node (scenes/FORMAT.md: rtpro's rotation about y is minus
    Blender's about z), light-sampled."""
    world = bpy.data.worlds.new("hdri")
    scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.image = bpy.data.images.load(hdri)
    texture.interpolation = "Linear"
    mapping = nodes.new("ShaderNodeMapping")
    mapping.vector_type = "POINT"
    mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(-rotation_degrees))
    links.new(nodes.new("ShaderNodeTexCoord").outputs["Generated"], mapping.inputs["Vector"])
    links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], nodes["Background"].inputs["Color"])
    nodes["Background"].inputs["Strength"].default_value = 1.0
    world.cycles.sampling_method = "AUTOMATIC"


def view_from_args(scene, args):
    """The camera, sky and sun of the benchmarks that light one object as rtpro's scene does, from
    six command-line words: SKY SUN_X,SUN_Y,SUN_Z SUN CAM_X,CAM_Y,CAM_Z AT_X,AT_Y,AT_Z FOV (rtpro's
    axes; FOV rtpro's vertical field of view in degrees). See sky_and_sun and look_at_camera."""
    vector = lambda word: [float(c) for c in word.split(",")]
    sky, sun_direction, sun, position, target, fov = args
    look_at_camera(scene, vector(position), vector(target), float(fov))
    sky_and_sun(scene, float(sky), vector(sun_direction), float(sun))
