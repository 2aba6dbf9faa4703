"""Cycles' render settings for rtpro's benchmarks, shared by render_gltf.py and render_environment.py:
the same estimator as rtpro's path integrator (no adaptive sampling, no denoising, no clamping, a
one-pixel box filter, caustics on, no glossy blur) with max_depth rtpro vertices = max_depth - 1
bounces, on `threads` fixed threads."""


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
    cycles.seed = 0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
