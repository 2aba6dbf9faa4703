// `rtpro render`: scene file → render scene → backend → renderer → image file.
#include "rtpro/backend/backend.h"
#include "backend_options.h"
#include "command.h"
#include "frame_sequence.h"
#include "interrupt.h"
#include "log.h"
#include "memory_option.h"
#include "output_target.h"
#include "progress.h"
#include "render_journal.h"
#include "render_stats.h"
#include "scene_overrides.h"
#include "tev_client.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/distributed/communicator.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/color_config.h"
#include "rtpro/image/image_io.h"
#include "rtpro/image/image_layer.h"
#include "rtpro/image/output_check.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace rtpro::cli {

namespace {

struct RenderCommandOptions {
  std::string scene;
  std::string output;
  std::string backend = "embree";
  // Kept as the user's text: they become scene overrides checked by the scene file's rules, so
  // "--seed -1" or "--size 4294967297x1" is an error instead of wrapping to another number.
  std::string spp, max_depth, seed, size, integrator;
  std::optional<int> threads;
  std::string ocio_config, display, deprecated_display, view;
  std::string format;      // for -o -
  double exposure = 0.0;   // stops
  std::vector<std::string> overrides, defines;
  std::vector<SceneOverride> scene_overrides;  // all of the above, in command-line order
  std::string display_server;  // HOST:PORT of a tev for a live preview
  std::string frames;  // FIRST-LAST[:STEP]
  long frame = -1;     // the frame of --frames being rendered
  bool skip_existing = false;
  std::string region;
  bool crop = false;
  std::vector<std::string> aovs;
  bool denoise = false;
  int tile_size = 32;
  std::string progress = "auto";
  bool quiet = false;
  int verbose = 0;
  bool stats = false;
  std::string stats_json;
  bool resume = false;
  bool no_journal = false;
  double time_limit = 0.0;       // seconds; 0: none
  double noise_threshold = 0.0;  // 0: no adaptive sampling
  int min_samples = 0;           // 0: automatic (adaptive_sampling.h)
  BackendOptions backend_options;  // Embree settings from the command line; threads and memory set later
  std::string max_memory_mb;  // MiB; empty: the default budget (see parse_memory_budget)
};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Only EXR has named layers for the AOVs; every other format would drop them without a word.
bool holds_layers(const std::filesystem::path& output) {
  std::string extension = output.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".exr" || extension == ".sxr" || extension == ".mxr";
}

std::optional<PixelRegion> parse_region(const std::string& text) {
  if (text.empty()) return std::nullopt;
  PixelRegion r;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &r.x0, &r.y0, &r.x1, &r.y1, &extra) != 4)
    throw InputError("--region '" + text + "': expected x0,y0,x1,y1 in pixels (x1 and y1 exclusive)");
  return r;
}

// Before the scene is built: a region outside the image would only be refused after the BVH.
void check_region_fits(const std::optional<PixelRegion>& region, const std::string& text, int width, int height) {
  if (!region) return;
  if (region->x0 < 0 || region->y0 < 0 || region->x1 > width || region->y1 > height || region->width() <= 0 ||
      region->height() <= 0)
    throw InputError("--region " + text + ": not a non-empty window inside the " + std::to_string(width) + "x" +
                     std::to_string(height) + " image (x0,y0,x1,y1 with x1, y1 exclusive)");
}

Image crop_image(const Image& full, const PixelRegion& r) {
  Image out(r.width(), r.height(), full.channels);
  for (int y = 0; y < r.height(); ++y)
    for (int x = 0; x < r.width(); ++x)
      for (int c = 0; c < full.channel_count(); ++c) out.at(x, y, c) = full.at(r.x0 + x, r.y0 + y, c);
  return out;
}

// "out.png" → "out.partial.png": an interrupted render never replaces a finished image.
std::filesystem::path partial_path(const std::filesystem::path& output) {
  std::filesystem::path p = output;
  p.replace_filename(output.stem().string() + ".partial" + output.extension().string());
  return p;
}

// Has TBB load what it loads on first use (tbbmalloc, irml) and start its worker threads before
// the image layer loads in the background: while a dlopen maps and relocates libraries, glibc
// holds a lock that another dlopen and every new thread wait for, so a worker started later would
// hold the render back until OpenImageIO is loaded. Waits at most 50 ms for the workers.
void start_tbb_workers(int threads) {
  std::atomic<int> arrived{0};
  const auto give_up = Clock::now() + std::chrono::milliseconds(50);
  tbb::parallel_for(
      0, threads,
      [&](int) {
        ++arrived;
        while (arrived.load() < threads && Clock::now() < give_up) std::this_thread::yield();
      },
      tbb::static_partitioner());
}

// `job` is the MPI job when mpirun started more than one rank: rank 0 leads (and alone writes the
// image, the journal and the statistics), the others follow and say nothing unless they fail.
int run_render(const RenderCommandOptions& o, Communicator* job) {
  const auto start = Clock::now();
  const bool leader = !job || job->rank() == 0;
  Log log(o.quiet || !leader ? LogLevel::kQuiet : (o.verbose > 0 ? LogLevel::kVerbose : LogLevel::kNormal));
  const BackendKind kind = parse_backend_kind(o.backend);
  if (o.threads && *o.threads < 0) throw InputError("--threads must be >= 0 (0: all cores)");
  const int threads = o.threads.value_or(0) > 0 ? *o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
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
  if (o.resume && o.no_journal) throw InputError("--resume reads the journal that --no-journal turns off: give one of them");
  if (o.resume && output.to_stdout()) throw InputError("--resume needs an output file: -o - keeps no journal");
  if (!(o.time_limit >= 0.0 && o.time_limit < 1e9))
    throw InputError("--time-limit must be a number of seconds >= 0 (0: no limit)");
  if (!(o.noise_threshold >= 0.0 && o.noise_threshold < 1e6))
    throw InputError("--noise-threshold must be >= 0 (0: every pixel takes every sample; Cycles' default is 0.01)");
  if (o.min_samples < 0) throw InputError("--min-samples must be >= 0 (0: automatic)");
  if (o.min_samples > 0 && o.noise_threshold == 0.0) throw InputError("--min-samples needs --noise-threshold");
  if (o.noise_threshold > 0.0 && job)
    throw InputError("--noise-threshold decides between passes from the whole image, which only rank 0 has: "
                     "render adaptively in one process");
  render_options.time_limit_seconds = o.time_limit;
  const MemoryBudget memory = parse_memory_budget(o.max_memory_mb);

  // Fail before the render, not after it: output folder, format, colour config and view.
  // Only the leader writes: the output's folder may not even exist on another rank's node.
  if (leader) check_image_output(output.file());
  if (leader && !o.stats_json.empty()) check_replaceable(o.stats_json);
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


  const SceneDescription description = parse_with_overrides(o.scene, o.scene_overrides);
  check_region_fits(render_options.region, o.region, description.camera.width, description.camera.height);
  // Refused before anything large is allocated: image buffers, flattened instances, meshes.
  int extra_channels = 0;
  for (Aov aov : render_options.aovs) extra_channels += static_cast<int>(aov_channel_names(aov).size());
  const RenderCost cost = estimate_render_cost(description, extra_channels);
  check_render_cost(cost, memory.bytes, memory.source, o.scene);
  log.verbose("estimated memory: " + format_bytes(cost.total_bytes) + " of a budget of " + format_bytes(memory.bytes));
  SceneBuildReport report;
  const RenderScene scene = build_render_scene(description, &report);
  if (render_passes(scene).passes() == 1 && (o.noise_threshold > 0.0 || o.time_limit > 0.0))
    throw InputError(std::string(o.noise_threshold > 0.0 ? "--noise-threshold" : "--time-limit") +
                     " works between passes, and this render is one pass: the stratified sampler fills its strata "
                     "grid only with all spp samples (set render.sampler: sobol, the path integrator's default)");
  render_options.adaptive = {static_cast<float>(o.noise_threshold),
                             resolved_min_samples(o.min_samples, static_cast<float>(o.noise_threshold), scene.render.spp)};
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

  // Image textures are decoded to linear .tx copies before the render (through the image layer,
  // waiting for its load to finish).
  std::unique_ptr<TextureLookup> textures;
  if (!scene.textures.empty()) {
    std::vector<TextureSource> sources;
    for (const TextureImage& texture : scene.textures)
      sources.push_back({texture.file, texture.colorspace, texture.bytes.get()});
    textures = open_textures(sources);
    render_options.textures = textures.get();
    log.verbose("opened " + std::to_string(sources.size()) + " image textures");
  }

  // The environment's image is read whole (through the image layer) and its sampling
  // distribution built before the render.
  std::optional<EnvironmentLight> environment;
  if (scene.environment) {
    Image image;
    if (!scene.environment->file.empty()) {
      const auto read_start = Clock::now();
      image = read_image(scene.environment->file, memory.bytes);
      log.verbose("read " + scene.environment->file.string() + " (" + std::to_string(image.width) + "x" +
                  std::to_string(image.height) + ") in " + std::to_string(seconds_since(read_start)) + " s");
    }
    const auto build_start = Clock::now();
    environment.emplace(*scene.environment, std::move(image));
    render_options.environment = &*environment;
    log.verbose("built the environment light in " + std::to_string(seconds_since(build_start)) + " s (" +
                format_bytes(environment->bytes()) + ")");
  }

  std::unique_ptr<TevClient> preview;
  if (display_server && leader) {
    preview = std::make_unique<TevClient>(*display_server, std::filesystem::path(output.name()).filename().string(),
                                          scene.camera.width, scene.camera.height, log);
    render_options.on_pass_image = [&preview](const Image& image, const PixelRegion& region) {
      preview->send_tile(image, region);
    };
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
    if (journaled) opened = open_render_journal(output.file(), identity, grid, kAccumulatorFloats, o.resume, log);
  }
  if (opened.journal) {
    render_options.journal_items = opened.finished;
    render_options.on_tile_result = [journal = opened.journal.get()](const TileResult& tile) { journal->append(tile); };
    // Every pass's records would make the journal spp/step times the film: once it holds twice the
    // film, the sums so far replace the records they sum.
    render_options.on_pass_merged = [journal = opened.journal.get()](int, const ProgressiveFilm& film) {
      const std::size_t film_bytes = film.grid().region().pixel_count() * kAccumulatorFloats * sizeof(float);
      if (journal->bytes() > 2 * film_bytes) journal->rewrite(film.journal_items());
    };
  }
  if (!leader) {
    const TileRenderer renderer(scene, *backend, grid, textures.get(), render_options.environment);
    // mpirun passes Ctrl-C on as SIGTERM to every rank: each finishes its tiles in flight and
    // rank 0 writes the partial image, as a single process does (if mpirun allows the time:
    // its odls_base_sigkill_timeout, 1 s by default).
    const InterruptGuard interrupt;
    follow_distributed_render(*job, renderer, grid, threads, &InterruptGuard::requested());
    return kExitOk;
  }
  if (job)
    render_options.tile_executor = [&job, &stats, &render_thread](const TileRenderer& renderer, const TileGrid& tiles,
                                                  TileSource& source, TileSink& sink) {
      stats.ranks = lead_distributed_render(*job, renderer, tiles, source, sink, &*render_thread);
    };
  const InterruptGuard interrupt;
  ProgressReporter progress(progress_mode, isatty(STDERR_FILENO) == 1, o.frame);
  render_options.cancel = &InterruptGuard::requested();
  render_options.on_tile_done = [&progress](std::size_t done, std::size_t total) { progress.tile_done(done, total); };
  RenderResult result = render_image(scene, *backend, render_options);
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
    write_options.metadata.push_back({"rtpro:passes", std::to_string(result.passes_done) + " of " +
                                                          std::to_string(result.passes_total)});
  if (!result.complete())
    write_options.metadata.push_back({"rtpro:partial", std::to_string(result.tiles_done) + " of " +
                                                           std::to_string(result.tiles_total) + " tiles"});
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

// One render, or one per frame of --frames, each exactly the image that frame renders alone.
int run_renders(const RenderCommandOptions& o, Communicator* job) {
  Log log(o.quiet ? LogLevel::kQuiet : LogLevel::kNormal);
  if (o.frames.empty()) {
    if (has_frame_pattern(o.output))
      throw InputError("-o " + o.output + " holds a frame number pattern ('#'): give --frames, e.g. --frames 1-240");
    if (o.skip_existing && o.output != "-" && std::filesystem::exists(o.output)) {
      log.info("skipped: " + o.output + " exists (--skip-existing)");
      return kExitOk;
    }
    return run_render(o, job);
  }
  const FrameRange range = parse_frame_range(o.frames);
  if (!has_frame_pattern(o.output))
    throw InputError("--frames needs a frame number pattern in -o, e.g. -o out_####.exr");
  if (o.scene == "-") throw InputError("--frames reads the scene once per frame: it cannot come from standard input");
  if (!o.stats_json.empty() && !has_frame_pattern(o.stats_json))
    throw InputError("--stats-json with --frames needs a frame number pattern too, e.g. stats_####.json");
  for (const SceneOverride& set : o.scene_overrides)
    if (set.assignment.rfind("variables.frame=", 0) == 0) throw InputError(set.flag + ": --frames sets the frame");
  for (long frame : range.frames()) {
    RenderCommandOptions one = o;
    one.output = numbered_output(o.output, frame);
    one.stats_json = numbered_output(o.stats_json, frame);
    one.frame = frame;
    if (o.skip_existing && std::filesystem::exists(one.output)) {
      log.info("frame " + std::to_string(frame) + " skipped: " + one.output + " exists (--skip-existing)");
      continue;
    }
    one.scene_overrides.push_back({"variables.frame=" + std::to_string(frame), "--frames (frame " + std::to_string(frame) + ")"});
    const int code = run_render(one, job);
    if (code != kExitOk) return code;
  }
  return kExitOk;
}

// Under mpirun every rank runs this. A rank that fails ends the whole job (MPI_Abort) with its
// exit code, so no rank waits for it; each finalizes MPI otherwise.
int run_renders_in_mpi_job(const RenderCommandOptions& o) {
  if (o.skip_existing)
    throw InputError("--skip-existing decides by files only rank 0 can see: not available under mpirun");
  std::unique_ptr<Communicator> job = join_mpi_job();
  const int rank = job->rank();
  try {
    const int code = run_renders(o, job->size() > 1 ? job.get() : nullptr);
    job.reset();
    return code;
  } catch (const std::exception& e) {
    if (rank == 0)
      std::fprintf(stderr, "rtpro: error: %s\n", e.what());
    else
      std::fprintf(stderr, "rtpro: error on rank %d: %s\n", rank, e.what());
    std::fflush(stderr);
    job->abort(dynamic_cast<const InputError*>(&e) ? kExitInputError : kExitRuntimeFailure);
  }
  return kExitRuntimeFailure;  // not reached: abort() ends the process
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to an image");
  cmd->add_option("scene", o->scene, "Scene file (YAML or glTF), or '-' for a YAML scene on standard input")->required();
  cmd->footer("Scene values: the file, then --set, -D, --spp, --size, --seed, --max-depth and --integrator in the order typed (the "
              "last to set a key wins); every value is checked by the scene file's own rules.");
  cmd->add_option("-o,--output", o->output, kOutputFormatsHelp)->required();
  cmd->add_option("--format", o->format, "Image format for -o - (standard output): exr, png, tif, hdr, ...");
  cmd->add_option("--exposure", o->exposure,
                  "Scale the rendered colour by 2^STOPS, in every format (before the view transform for display "
                  "formats; not the AOVs)");
  cmd->add_option("--backend", o->backend, "Ray tracing backend: embree or native")
      ->check(CLI::IsMember({"native", "embree"}))
      ->capture_default_str();
  cmd->add_option("--spp", o->spp,
                  "Samples per pixel, 1 to 65536, stratified over the most nearly square grid (48: 8x6)");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT, e.g. 1280x720");
  cmd->add_option("--threads", o->threads, "Worker threads (0: all cores)");
  cmd->add_option("--seed", o->seed, "Seed of the pixel sampler");
  cmd->add_option("--max-depth", o->max_depth,
                  "Most bounces after the camera ray: mirror bounces (whitted), path vertices (path)");
  cmd->add_option("--integrator", o->integrator,
                  "Light transport: path (physically based path tracing with MIS) or whitted (Phong, mirrors, "
                  "glass); default: the scene's render.integrator, else whitted")
      ->check(CLI::IsMember({"path", "whitted"}));
  add_scene_override_options(*cmd, o->overrides, o->defines);
  cmd->add_option("--display-server", o->display_server,
                  "Stream tiles as they finish to the tev image viewer listening at HOST:PORT (tev's default: "
                  "127.0.0.1:14158); the render goes on if it is absent or goes away");
  cmd->add_option("--frames", o->frames,
                  "Render frames FIRST-LAST[:STEP] (e.g. 1-240:2), each to -o with its '####' replaced by the "
                  "zero-padded frame number; the scene variable 'frame' follows (keyframed values, $frame)");
  cmd->add_flag("--skip-existing", o->skip_existing, "Skip frames (or the single output) whose file already exists");
  cmd->add_option("--region", o->region, "Render only pixels x0,y0,x1,y1 (x1, y1 exclusive)");
  cmd->add_flag("--crop", o->crop, "With --region: write only the region instead of a full-size image");
  cmd->add_option("--aov", o->aovs, "Extra EXR layers: albedo,normal,depth,object-id,halves,variance,spp (EXR outputs only)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_flag("--denoise", o->denoise,
                "Denoise the finished image with rtpro's own denoiser (the albedo, normal, depth and half-buffer "
                "layers are rendered for it); an EXR keeps the noisy colour as noisy.R/G/B and those layers");
  cmd->add_option("--tile-size", o->tile_size, "Tile edge in pixels")->capture_default_str();
  cmd->add_option("--ocio-config", o->ocio_config, "OpenColorIO config (default: $OCIO, else bundled)");
  cmd->add_option("--ocio-display", o->display, "OCIO display for display-referred outputs (default: the config's)");
  cmd->add_option("--display", o->deprecated_display, "Deprecated spelling of --ocio-display")->group("");
  cmd->add_option("--view", o->view, "OCIO view for display-referred outputs (default: the display's)");
  cmd->add_option("--progress", o->progress, "Progress on stderr: never, auto (bar on a terminal), always, or json (one object a line, kept with -q)")
      ->type_name("TEXT:{never,auto,always,json}")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "Print only errors");
  cmd->add_flag("-v,--verbose", o->verbose, "Print more detail");
  cmd->add_flag("--stats", o->stats, "Print statistics at the end");
  cmd->add_option("--stats-json", o->stats_json, "Write statistics as JSON to this file");
  cmd->add_flag("--resume", o->resume,
                "Continue an interrupted or killed render of the same scene and settings from its journal "
                "(OUTPUT.rtpro-journal): only the missing tiles are rendered, and the image is bit-identical to "
                "an uninterrupted one");
  cmd->add_option("--time-limit", o->time_limit,
                  "Stop after this many seconds with the passes finished by then (the first always finishes)");
  cmd->add_option("--noise-threshold", o->noise_threshold,
                  "Adaptive sampling: a pixel stops when its error (Cycles' measure) is below this, e.g. 0.01; "
                  "--spp is then the most a pixel gets");
  cmd->add_option("--min-samples", o->min_samples,
                  "With --noise-threshold: samples every pixel takes first (0: 16, or more for small thresholds)");
  cmd->add_flag("--no-journal", o->no_journal,
                "Keep no resume journal beside the output (one is kept while rendering and removed once the image "
                "is written)");
  add_embree_options(*cmd, o->backend_options);
  cmd->add_flag("--embree-compact", o->backend_options.embree_compact, "Smaller Embree BVH (about half), about 20% slower to trace");
  cmd->add_option("--max-memory", o->max_memory_mb,
                  "Memory budget in MiB for the whole render, checked against an up-front estimate and given to "
                  "Embree as its limit (0: no limit; default: the smaller of 4096 and the available memory)");
  cmd->callback([o, cmd, &action] {
    o->scene_overrides = command_line_overrides(*cmd);
    action = [o] { return launched_by_mpirun() ? run_renders_in_mpi_job(*o) : run_renders(*o, nullptr); };
  });
}

}  // namespace rtpro::cli
