// One render of `rtpro render`: scene file → render scene → backend → renderer → image file.
#include "run_render.h"

#include "rtpro/backend/backend.h"
#include "backend_options.h"
#include "interrupt.h"
#include "load_scene.h"
#include "log.h"
#include "memory_option.h"
#include "output_target.h"
#include "pixel_region_option.h"
#include "progress.h"
#include "render_command_options.h"
#include "render_journal.h"
#include "render_output.h"
#include "scene_images.h"
#include "render_stats.h"
#include "tbb_workers.h"
#include "tev_client.h"
#include "thread_count.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/distributed/communicator.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/distributed/distributed_tile_executor.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/color_config.h"
#include "rtpro/image/image_io.h"
#include "rtpro/image/image_layer.h"
#include "rtpro/image/output_check.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/job/tile_journal.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/renderer.h"

#include <tbb/global_control.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

namespace rtpro::cli {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

int run_render(const RenderCommandOptions& o, Communicator* job) {
  const auto start = Clock::now();
  const bool leader = !job || job->rank() == 0;
  Log log(o.quiet || !leader ? LogLevel::kQuiet : (o.verbose > 0 ? LogLevel::kVerbose : LogLevel::kNormal));
  const BackendKind kind = parse_backend_kind(o.backend);
  const int threads = worker_thread_count(o.threads);
  RenderOptions render_options;
  render_options.region = parse_region(o.region);
  if (o.tile_size < 1) throw InputError("--tile-size must be at least 1 pixel, got " + std::to_string(o.tile_size));
  render_options.tile_size = o.tile_size;
  for (const std::string& name : o.aovs) {
    const Aov aov = parse_aov(name);
    // Refused now, not by the image writer after the render: each layer's channels appear once.
    if (std::find(render_options.aovs.begin(), render_options.aovs.end(), aov) != render_options.aovs.end())
      throw InputError("--aov " + name + " is given twice");
    render_options.aovs.push_back(aov);
  }
  const OutputTarget output(o.output, o.format);
  check_exposure(o.exposure);
  const std::optional<DisplayServerAddress> display_server =
      o.display_server.empty() ? std::nullopt : std::optional(parse_display_server(o.display_server));
  if (!render_options.aovs.empty() && !holds_layers(output.file()))
    throw InputError("--aov needs an EXR output: '" + o.output + "' holds only the colour image");
  // --denoise renders the layers the denoiser reads as well; an EXR keeps them (and the noisy
  // colour), so `rtpro denoise` can run on it again.
  if (o.denoise)
    for (Aov aov : {Aov::kAlbedo, Aov::kNormal, Aov::kDepth, Aov::kHalves})
      if (std::find(render_options.aovs.begin(), render_options.aovs.end(), aov) == render_options.aovs.end())
        render_options.aovs.push_back(aov);
  if (!o.deprecated_display.empty() && !o.display.empty())
    throw InputError("--display is the old spelling of --ocio-display: give only --ocio-display");
  if (!o.deprecated_display.empty())
    log.warning("--display is deprecated: it names an OpenColorIO display; write --ocio-display " +
                o.deprecated_display + " (pbrt's live preview is --display-server)");
  const std::string& display = o.display.empty() ? o.deprecated_display : o.display;
  // Checked even with -q, which silences it unless it is JSON for a program: a typo is an error
  // whether or not it shows.
  const ProgressMode chosen_progress = parse_progress_mode(o.progress);
  const ProgressMode progress_mode =
      !leader || (o.quiet && chosen_progress != ProgressMode::kJson) ? ProgressMode::kNever : chosen_progress;
  if (o.crop && !render_options.region) throw InputError("--crop needs --region");
  if (o.resume && o.no_journal)
    throw InputError("--resume reads the journal that --no-journal turns off: give one of them");
  if (o.resume && output.to_stdout()) throw InputError("--resume needs an output file: -o - keeps no journal");
  if (!(o.time_limit >= 0.0 && o.time_limit < 1e9))
    throw InputError("--time-limit must be a number of seconds >= 0 (0: no limit)");
  if (!(o.rank_timeout == 0.0 || (o.rank_timeout >= 1.0 && o.rank_timeout <= 1e6)))
    throw InputError("--rank-timeout must be 0 (wait for ever) or between 1 and 1000000 seconds");
  const auto rank_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(o.rank_timeout * 1000.0));
  if (!(o.noise_threshold >= 0.0 && o.noise_threshold < 1e6))
    throw InputError("--noise-threshold must be >= 0 (0: every pixel takes every sample; Cycles' default is 0.01)");
  if (o.min_samples < 0) throw InputError("--min-samples must be >= 0 (0: automatic)");
  if (o.min_samples > 0 && o.noise_threshold == 0.0) throw InputError("--min-samples needs --noise-threshold");
  if (o.noise_threshold > 0.0 && job)
    throw InputError(
        "--noise-threshold decides between passes from the whole image, which only rank 0 has: "
        "render adaptively in one process");
  render_options.time_limit_seconds = o.time_limit;
  const MemoryBudget memory = parse_memory_budget(o.max_memory_mb);

  // Fail before the render, not after it: output folder, format, colour config and view.
  // Only the leader writes: the output's folder may not even exist on another rank's node.
  if (leader) check_image_output(output.file());
  if (leader && !o.stats_json.empty()) check_replaceable(o.stats_json);
  // One file named twice would be replaced by the other output, or replace the scene.
  if (leader) {
    check_output_is_distinct({"--stats-json", o.stats_json}, {{"-o", o.output}, {"the scene", o.scene}});
    check_output_is_distinct({"-o", o.output}, {{"the scene", o.scene}});
  }
  ImageWriteOptions write_options;
  if (!o.ocio_config.empty()) write_options.ocio_config = o.ocio_config;
  write_options.display = display;
  write_options.view = o.view;
  if (leader && !writes_scene_linear(output.file())) {
    const ColorConfig colors = ColorConfig::load(write_options.ocio_config);
    const DisplayTransform transform = colors.display_transform(display, o.view);
    log.verbose("colour: OCIO config " + colors.source() + ", display '" + transform.display() + "', view '" +
                transform.view() + "'");
  }

  // Must exist before any TBB or Embree work so the cap really holds.
  tbb::global_control thread_cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  int extra_channels = 0;
  for (Aov aov : render_options.aovs) extra_channels += static_cast<int>(aov_channel_names(aov).size());
  const LoadedScene loaded =
      load_scene({o.scene, o.scene_overrides, memory, extra_channels, render_options.region, o.region}, &log);
  const SceneDescription& description = loaded.description;
  const SceneBuildReport& report = loaded.report;
  const RenderScene& scene = loaded.scene;
  if (render_passes(scene).passes() == 1 && (o.noise_threshold > 0.0 || o.time_limit > 0.0))
    throw InputError(std::string(o.noise_threshold > 0.0 ? "--noise-threshold" : "--time-limit") +
                     " works between passes, and this render is one pass: the stratified sampler fills its strata "
                     "grid only with all spp samples (set render.sampler: sobol, the path integrator's default)");
  render_options.adaptive = {
      static_cast<float>(o.noise_threshold),
      resolved_min_samples(o.min_samples, static_cast<float>(o.noise_threshold), scene.render.spp),
      parse_noise_metric(o.noise_metric)};
  for (const auto& mesh : report.meshes) {
    log.verbose("loaded " + mesh.file + ": " + std::to_string(mesh.stats.triangles) + " triangles in " +
                std::to_string(mesh.load_seconds) + " s");
    for (const std::string& warning : mesh.stats.warnings) log.warning(warning);
  }
  RenderStatistics stats;
  stats.scene = o.scene;
  stats.output = output.name();
  stats.threads = threads;
  stats.spp = scene.render.spp;
  stats.width = scene.camera.width;
  stats.height = scene.camera.height;
  stats.load_seconds = seconds_since(start);

  // OpenImageIO takes 0.15–0.5 s to load: do it while the BVH builds and the scene renders. Not
  // earlier: its hundreds of mmap calls slow the page faults of a large scene file's parse. EXR
  // and PNG are written without it; image textures need it before the render starts, every rank's.
  start_tbb_workers(threads);
  // Rank 0 of a job creates its render thread first: a thread created while a dlopen runs waits
  // for it (prestarted_thread.h). The other ranks write no image.
  std::optional<PrestartedThread> render_thread;
  if (job && leader) render_thread.emplace();
  const bool reads_images = !scene.textures.empty() || (scene.environment && !scene.environment->file.empty());
  if ((leader && writing_needs_image_layer(output.file())) || reads_images) start_loading_image_layer();

  BackendOptions backend_options = o.backend_options;
  backend_options.threads = threads;
  backend_options.max_memory_bytes = memory.explicit_limit ? memory.bytes : 0;
  const std::unique_ptr<Backend> backend = make_backend(kind, scene, backend_options);
  stats.backend = std::string(backend->name());
  stats.build_seconds = backend->stats().build_seconds;
  log.verbose("built " + stats.backend + " acceleration structure in " + std::to_string(stats.build_seconds) + " s");

  // Before the render, with the image layer (waiting for its load to finish).
  const SceneImages images = open_scene_images(scene, memory.bytes, log);
  render_options.textures = images.textures.get();
  if (images.environment) render_options.environment = &*images.environment;

  std::unique_ptr<TevClient> preview;
  if (display_server && leader) {
    preview = std::make_unique<TevClient>(*display_server, std::filesystem::path(output.name()).filename().string(),
                                          scene.camera.width, scene.camera.height, log);
    render_options.observers.push_back(preview.get());
  }
  // The journal beside the output: what --resume continues after a kill or an interrupt.
  // The ranks of a job check they render the same thing before any of them renders.
  const bool journaled = leader && !o.no_journal && !output.to_stdout();
  const FilmLayout layout(render_options.aovs);
  const TileGrid grid = render_grid(scene, checked_region(scene, render_options), render_options.tile_size);
  OpenedJournal opened;
  if (journaled || job) {
    RenderJobSettings settings;
    for (const SceneOverride& set : o.scene_overrides) settings.overrides.push_back(set.assignment);
    settings.backend = stats.backend;
    settings.backend_options = backend_options;
    settings.region = grid.region();
    settings.tile_size = grid.tile_size();
    settings.channels = layout.channels();
    settings.adaptive = render_options.adaptive;
    const JobIdentity identity = render_job_identity(description, report, scene, settings);
    if (job) agree_on_job(*job, identity);
    if (journaled)
      opened = open_render_journal(journal_path(output.file()), identity, grid, render_sums(render_options).floats(),
                                   o.resume, log);
  }
  if (opened.journal) {
    render_options.journal_items = opened.finished;
    render_options.observers.push_back(&opened);
  }
  if (!leader) {
    const TileRenderer renderer(scene, *backend, grid, render_sums(render_options), render_options.textures,
                                render_options.environment);
    // mpirun passes Ctrl-C on as SIGTERM to every rank: each finishes its tiles in flight and
    // rank 0 writes the partial image, as a single process does (if mpirun allows the time:
    // its odls_base_sigkill_timeout, 1 s by default).
    const InterruptGuard interrupt;
    follow_distributed_render(*job, renderer, grid, threads, &InterruptGuard::requested(), rank_timeout);
    return kExitOk;
  }
  std::optional<DistributedTileExecutor> executor;
  if (job) {
    executor.emplace(*job, &*render_thread, rank_timeout);
    render_options.tile_executor = &*executor;
  }
  const InterruptGuard interrupt;
  ProgressReporter progress(progress_mode, isatty(STDERR_FILENO) == 1, o.frame);
  render_options.cancel = &InterruptGuard::requested();
  render_options.observers.push_back(&progress);
  RenderResult result = render_image(scene, *backend, render_options);
  if (executor) stats.ranks = executor->ranks();
  progress.finish(result.tiles_done, result.tiles_total);
  switch (result.stop) {
    case RenderStop::kAllPasses: break;
    case RenderStop::kConverged:
      log.info("every pixel converged after " + std::to_string(result.passes_done) + " of " +
               std::to_string(result.passes_total) + " passes (--noise-threshold)");
      break;
    case RenderStop::kTimeLimit:
      log.info("stopped at the time limit after " + std::to_string(result.passes_done) + " of " +
               std::to_string(result.passes_total) + " passes");
      break;
    case RenderStop::kInterrupted: break;
  }
  stats.render_seconds = result.seconds;
  stats.rays = result.rays;
  stats.nan_samples = result.nan_samples;
  stats.complete = result.complete();
  stats.passes_done = result.passes_done;
  stats.passes_total = result.passes_total;
  stats.pass_seconds = result.pass_seconds;
  switch (result.stop) {
    case RenderStop::kAllPasses: stats.stop = "all passes"; break;
    case RenderStop::kConverged: stats.stop = "converged"; break;
    case RenderStop::kTimeLimit: stats.stop = "time limit"; break;
    case RenderStop::kInterrupted: stats.stop = "interrupted"; break;
  }

  const auto write_start = Clock::now();
  const std::filesystem::path target =
      result.complete() || output.to_stdout() ? output.file() : partial_path(output.file());
  write_options.metadata = {
      {"Software", std::string("rtpro ") + RTPRO_VERSION},
      {"rtpro:backend", stats.backend},
      {"rtpro:spp", std::to_string(scene.render.spp)},
      {"rtpro:seed", std::to_string(scene.render.seed)},
      {"rtpro:max_depth", std::to_string(scene.render.max_depth)},
      {"rtpro:integrator", integrator_name(scene.render.integrator)},
      {"rtpro:render_seconds", std::to_string(result.seconds)},
      {"rtpro:scene", o.scene},
  };
  if (render_options.region) write_options.metadata.push_back({"rtpro:region", o.region});
  if (o.frame >= 0) write_options.metadata.push_back({"rtpro:frame", std::to_string(o.frame)});
  if (result.passes_done < result.passes_total)
    write_options.metadata.push_back(
        {"rtpro:passes", std::to_string(result.passes_done) + " of " + std::to_string(result.passes_total)});
  if (!result.complete())
    write_options.metadata.push_back(
        {"rtpro:partial", std::to_string(result.tiles_done) + " of " + std::to_string(result.tiles_total) + " tiles"});
  if (o.exposure != 0.0) write_options.metadata.push_back({"rtpro:exposure", std::to_string(o.exposure)});
  Image image = o.crop ? crop_image(result.image, *render_options.region) : std::move(result.image);
  if (o.denoise && result.complete()) {
    const auto denoise_start = Clock::now();
    // An EXR keeps the noisy colour and the layers; a display image holds the colour alone.
    Image denoised = denoise(image);
    image = holds_layers(output.file()) ? with_denoised_colour(image, denoised) : std::move(denoised);
    stats.denoise_seconds = seconds_since(denoise_start);
    log.verbose("denoised in " + std::to_string(stats.denoise_seconds) + " s");
  }
  apply_exposure(image, o.exposure);
  write_image(target, image, write_options);
  output.deliver();
  if (opened.journal) {
    if (const std::string error = opened.journal->error(); !error.empty()) log.warning(error);
    if (result.complete()) opened.journal->remove();
  }
  stats.write_seconds = seconds_since(write_start);

  const BackendStats backend_stats = backend->stats();
  stats.rejected_rays = backend_stats.rejected_rays;
  stats.acceleration_bytes = backend_stats.acceleration_bytes;
  stats.peak_rss_bytes = peak_rss_bytes();
  stats.total_seconds = seconds_since(start);
  if (stats.rejected_rays > 0) log.warning(std::to_string(stats.rejected_rays) + " rays were rejected as untraceable");
  if (stats.nan_samples > 0) log.warning(std::to_string(stats.nan_samples) + " samples were NaN or infinite");
  log.summarise_repeats();
  if (o.stats) std::fputs(stats.text().c_str(), stderr);
  if (!o.stats_json.empty()) write_file_atomically(o.stats_json, stats.json().dump(2) + "\n");

  if (!result.complete()) {
    if (result.passes_done > 0)
      std::fprintf(stderr, "rtpro: interrupted: wrote the %d of %d finished passes to %s\n", result.passes_done,
                   result.passes_total, target.c_str());
    else
      std::fprintf(stderr, "rtpro: interrupted: wrote the %zu finished tiles of the first pass to %s\n",
                   result.tiles_done, target.c_str());
    if (opened.journal)
      std::fprintf(stderr, "rtpro: the same command with --resume renders only the rest (journal %s)\n",
                   opened.journal->file().c_str());
    return kExitInterrupted;
  }
  std::ostringstream line;
  line << "wrote " << output.name() << " (" << scene.camera.width << "x" << scene.camera.height << ", "
       << scene.render.spp << " spp, " << stats.backend << ") in " << format_duration(stats.total_seconds);
  log.info(line.str());
  return kExitOk;
}

}  // namespace rtpro::cli
