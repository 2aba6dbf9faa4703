#include "render_command_options.h"

#include "backend_options.h"
#include "choice_option.h"
#include "output_target.h"

namespace rtpro::cli {

void add_render_options(CLI::App& cmd, RenderCommandOptions& o) {
  cmd.add_option(
         "scene", o.scene,
         "Scene file (YAML), a model as the whole scene (glTF, OBJ, PLY), or '-' for a YAML scene on standard input")
      ->required();
  cmd.footer(
      "Scene values: the file, then --set, -D and the flags that set a render value (--spp, --size, --seed, "
      "--max-depth, --integrator, the path controls) in the order typed (the last to set a key wins); every value "
      "is checked by the scene file's own rules.");
  cmd.add_option("-o,--output", o.output, kOutputFormatsHelp)->required();
  cmd.add_option("--format", o.format, "Image format for -o - (standard output): exr, png, tif, hdr, ...");
  cmd.add_option("--exposure", o.exposure,
                 "Scale the rendered colour by 2^STOPS, in every format (before the view transform for display "
                 "formats; not the AOVs)");
  one_of(cmd.add_option("--backend", o.backend, "Ray tracing backend: embree or native"), {"native", "embree"})
      ->capture_default_str();
  cmd.add_option("--spp", o.spp,
                 "Samples per pixel, 1 to 65536, stratified over the most nearly square grid (48: 8x6)");
  cmd.add_option("--size", o.size, "Image size WIDTHxHEIGHT, e.g. 1280x720");
  cmd.add_option("--threads", o.threads, "Worker threads (0: all cores)");
  cmd.add_option("--seed", o.seed, "Seed of the pixel sampler");
  cmd.add_option("--max-depth", o.max_depth,
                 "Most bounces after the camera ray: mirror bounces (whitted), path vertices (path)");
  cmd.add_option("--max-diffuse-depth", o.max_diffuse_depth,
                 "path: most diffuse bounces of a path (default: --max-depth); Cycles' Diffuse bounces + 1");
  cmd.add_option("--max-glossy-depth", o.max_glossy_depth,
                 "path: most glossy (microfacet or mirror reflection) bounces of a path (default: --max-depth)");
  cmd.add_option("--max-transmission-depth", o.max_transmission_depth,
                 "path: most transmission (refraction) bounces of a path (default: --max-depth)");
  cmd.add_option("--clamp-direct", o.clamp_direct,
                 "path: scale down each direct-light contribution whose channel mean is above this (Cycles' Clamp "
                 "Direct; 0: off)");
  cmd.add_option("--clamp-indirect", o.clamp_indirect,
                 "path: the same for light that scattered more than once (Cycles' Clamp Indirect; 0: off)");
  cmd.add_option("--filter-glossy", o.filter_glossy,
                 "path: roughen glossy lobes seen after diffuse or rough bounces, against caustic noise (Cycles' "
                 "Filter Glossy; 0: off)");
  one_of(cmd.add_option("--integrator", o.integrator,
                        "Light transport: path (physically based path tracing with MIS) or whitted (Phong, mirrors, "
                        "glass); default: the scene's render.integrator, else whitted"),
         {"path", "whitted"});
  add_scene_override_options(cmd, o.overrides, o.defines, o.environments, o.shutters);
  cmd.add_option("--display-server", o.display_server,
                 "Stream the image after each pass to the tev image viewer listening at HOST:PORT (tev's default: "
                 "127.0.0.1:14158); the render goes on if it is absent or goes away");
  cmd.add_option("--frames", o.frames,
                 "Render frames FIRST-LAST[:STEP] (e.g. 1-240:2), each to -o with its '####' replaced by the "
                 "zero-padded frame number; the scene variable 'frame' follows (keyframed values, $frame)");
  cmd.add_flag("--skip-existing", o.skip_existing, "Skip frames (or the single output) whose file already exists");
  cmd.add_option("--region", o.region, "Render only pixels x0,y0,x1,y1 (x1, y1 exclusive)");
  cmd.add_flag("--crop", o.crop, "With --region: write only the region instead of a full-size image");
  one_of(cmd.add_option("--aov", o.aovs,
                        "Extra EXR layers: albedo,normal,depth,object-id,halves,variance,spp,motion (EXR outputs "
                        "only)"),
         {"albedo", "normal", "depth", "object-id", "halves", "variance", "spp", "motion"})
      ->delimiter(',')
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_flag("--denoise", o.denoise,
               "Denoise the finished image with rtpro's own denoiser (the albedo, normal, depth and half-buffer "
               "layers are rendered for it); an EXR keeps the noisy colour as noisy.R/G/B and those layers");
  cmd.add_option("--tile-size", o.tile_size, "Tile edge in pixels")->capture_default_str();
  cmd.add_option("--ocio-config", o.ocio_config, "OpenColorIO config (default: $OCIO, else bundled)");
  cmd.add_option("--ocio-display", o.display, "OCIO display for display-referred outputs (default: the config's)");
  cmd.add_option("--display", o.deprecated_display, "Deprecated spelling of --ocio-display")->group("");
  cmd.add_option("--view", o.view, "OCIO view for display-referred outputs (default: the display's)");
  one_of(cmd.add_option(
             "--progress", o.progress,
             "Progress on stderr: never, auto (bar on a terminal), always, or json (one object a line, kept with -q)"),
         {"never", "auto", "always", "json"})
      ->capture_default_str();
  cmd.add_flag("-q,--quiet", o.quiet, "Print only errors");
  cmd.add_flag("-v,--verbose", o.verbose, "Print more detail");
  cmd.add_flag("--stats", o.stats, "Print statistics at the end");
  cmd.add_option("--stats-json", o.stats_json, "Write statistics as JSON to this file");
  cmd.add_flag("--resume", o.resume,
               "Continue an interrupted or killed render of the same scene and settings from its journal "
               "(OUTPUT.rtpro-journal): only the missing tiles are rendered, and the image is bit-identical to "
               "an uninterrupted one");
  cmd.add_option("--time-limit", o.time_limit,
                 "Stop after this many seconds with the passes finished by then (the first always finishes)");
  cmd.add_option("--rank-timeout", o.rank_timeout,
                 "Under mpirun: end the job when a rank sends nothing for this many seconds while the ranks render "
                 "(stopped, hung or unreachable), as if it had died; the journal keeps the finished tiles "
                 "(0: wait for ever)")
      ->capture_default_str();
  cmd.add_option("--start-timeout", o.start_timeout,
                 "Under mpirun: end the job when a rank has not loaded the scene and reached the start of the job "
                 "this many seconds after rank 0 did, or rank 0 this long after it (0: wait for ever)")
      ->capture_default_str();
  cmd.add_option("--noise-threshold", o.noise_threshold,
                 "Adaptive sampling: a pixel stops when its error (--noise-metric) is below this, e.g. 0.01 "
                 "(cycles) or 0.002 (relmse); --spp is then the most a pixel gets");
  one_of(
      cmd.add_option("--noise-metric", o.noise_metric,
                     "The error --noise-threshold stops at: cycles (Cycles' measure: every pixel stops at about "
                     "one error) or relmse (one more sample's gain in relative MSE: the lowest relMSE for the time)"),
      {"cycles", "relmse"})
      ->default_str("cycles");
  cmd.add_option("--min-samples", o.min_samples,
                 "With --noise-threshold: samples every pixel takes first (0: 16, or more for small thresholds)");
  cmd.add_flag("--no-journal", o.no_journal,
               "Keep no resume journal beside the output (one is kept while rendering and removed once the image "
               "is written)");
  cmd.add_option("--journal-after", o.journal_after,
                 "Seconds of rendering before the journal records finished tiles: the first merged pass after "
                 "them, or an interrupt, records what came before; a render killed sooner starts over on "
                 "--resume (0: record every tile as it finishes)")
      ->default_str("1");
  add_embree_options(cmd, o.backend_options);
  cmd.add_flag("--embree-compact", o.backend_options.embree_compact,
               "Smaller Embree BVH (about half), about 20% slower to trace");
  cmd.add_flag("--compact-normals", o.compact_normals,
               "Mesh shading normals in 4 bytes instead of 12 (octahedral codes, each within 5e-5 radians): "
               "smaller meshes, images that differ in the last bits");
  cmd.add_option("--embree-pieces", o.piece_triangles,
                 "Build each mesh of more than this many triangles (0: off, else at least 4096) as compact pieces "
                 "of that many, one Embree BVH after another: the build's temporary memory (32 bytes a triangle) "
                 "is one piece's. Reorders the mesh's triangles, for every backend");
  cmd.add_option("--max-memory", o.max_memory_mb,
                 "Memory budget in MiB for the whole render, checked against an up-front estimate and given to "
                 "Embree as its limit (0: no limit; default: the smaller of 4096 and the available memory)");
}

}  // namespace rtpro::cli
