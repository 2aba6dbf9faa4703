"""Cycles' render settings for rtpro's benchmarks, shared by render_gltf.py and render_environment.py:
the same estimator as rtpro's path integrator (no adaptive sampling, no denoising, no clamping, a
one-pixel box filter, caustics on, no glossy blur) with max_depth rtpro vertices = max_depth - 1
bounces, on `threads` fixed threads; and the render itself, to a float EXR, timed. Cycles' seed is 0
unless RTPRO_CYCLES_SEED says otherwise: a long reference takes another, or the runs compared with it
would share its first samples and their relMSE would be flattered."""
import os
import time

import bpy


def configure_cycles(scene, spp, max_depth, threads):
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
    cycles.seed = int(os.environ.get("RTPRO_CYCLES_SEED", "0"))
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads


def render_timed_exr(scene, width, height, out_file):
    """Renders `scene` at width x height into `out_file` as rtpro writes it (32-bit float EXR, the
    Standard view: no look, exposure 0, gamma 1) and prints "cycles_render_seconds S", the time of
    the render call alone (scene sync, BVH and sampling), which the benchmark scripts read, and
    "cycles_render_cpu_seconds S", the CPU time of all Blender's threads during that call."""
    scene.render.resolution_x = width
    scene.render.resolution_y = height
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

    start, start_cpu = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=True)
    print("cycles_render_seconds %.3f" % (time.perf_counter() - start))
    print("cycles_render_cpu_seconds %.3f" % (time.process_time() - start_cpu))
