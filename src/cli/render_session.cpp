#include "render_session.h"

#include "interrupt.h"
#include "progress.h"
#include "render_stats.h"
#include "tbb_workers.h"
#include "rtpro/core/error.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/image/image_layer.h"
#include "rtpro/render/tile_renderer.h"

#include <malloc.h>
#include <unistd.h>

#include <string>

namespace rtpro::cli {

namespace {

void log_meshes(const SceneBuildReport& report, Log& log) {
  for (const auto& mesh : report.meshes) {
    log.verbose("loaded " + mesh.file + ": " + std::to_string(mesh.stats.triangles) + " triangles in " +
                std::to_string(mesh.load_seconds) + " s");
    for (const std::string& warning : mesh.stats.warnings) log.warning(warning);
  }
}

}  // namespace

RenderSession::RenderSession(const RenderRequest& request, const LoadedScene& loaded, Communicator* job, Log& log)
    : request_(request), loaded_(loaded), job_(job), log_(log), options_(request.render) {
  check_passes();
  const float threshold = static_cast<float>(request.noise_threshold);
  options_.adaptive = {threshold, resolved_min_samples(request.min_samples, threshold, loaded.scene.render.spp),
                       request.noise_metric};
  if (const int spp = loaded.scene.render.spp; request.min_samples > spp)
    log.warning("--min-samples " + std::to_string(request.min_samples) + " is more than the " + std::to_string(spp) +
                " samples a pixel takes at most (--spp): every pixel takes all " + std::to_string(spp) +
                ", as without --noise-threshold");
  log_meshes(loaded.report, log);
  start_workers();
  build_backend();
  open_images();
  if (request.display_server) {
    const RenderCamera& camera = loaded.scene.camera;
    preview_ =
        std::make_unique<TevClient>(*request.display_server, request.preview_name, camera.width, camera.height, log);
  }
  open_journal();
}

void RenderSession::check_passes() const {
  const double threshold = request_.noise_threshold, time_limit = request_.render.time_limit_seconds;
  if (render_passes(loaded_.scene).passes() == 1 && (threshold > 0.0 || time_limit > 0.0))
    throw InputError(std::string(threshold > 0.0 ? "--noise-threshold" : "--time-limit") +
                     " works between passes, and this render is one pass: the stratified sampler fills its strata "
                     "grid only with all spp samples (set render.sampler: sobol, the path integrator's default)");
}

// OpenImageIO takes 0.15–0.5 s to load: do it while the BVH builds and the scene renders. Not
// earlier: its hundreds of mmap calls slow the page faults of a large scene file's parse. EXR
// and PNG are written without it, an EXR environment read without it; image textures need it
// before the render starts, every rank's.
void RenderSession::start_workers() {
  start_tbb_workers(request_.threads);
  // Rank 0 of a job creates its render thread first: a thread created while a dlopen runs waits
  // for it (prestarted_thread.h). The other ranks write no image.
  if (job_ && request_.leader) render_thread_.emplace();
  const RenderScene& scene = loaded_.scene;
  const bool reads_images = !scene.textures.empty() || (scene.environment && !scene.environment->file.empty() &&
                                                        reading_needs_image_layer(scene.environment->file));
  if ((request_.leader && writing_needs_image_layer(request_.output.file())) || reads_images)
    start_loading_image_layer();
}

void RenderSession::build_backend() {
  backend_ = make_backend(request_.backend, loaded_.scene, request_.backend_options);
  backend_name_ = backend_->name();
  peak_rss_after_build_bytes_ = peak_rss_bytes();
  log_.verbose("built " + std::string(backend_->name()) + " acceleration structure in " +
               std::to_string(backend_->stats().build_seconds) + " s");
}

void RenderSession::release_backend() {
  if (!backend_) return;
  released_stats_ = backend_->stats();
  backend_.reset();
  // glibc raises its mmap threshold to the size of each large block freed, so after Embree's
  // build array went, the BVH's blocks came from the heap and, freed, would stay resident under
  // the film and the image: handed back here, where nothing else is allocated (dragon built in
  // pieces: the render's end 97 -> 84-85 MiB).
  malloc_trim(0);
}

void RenderSession::open_images() {
  images_ = open_scene_images(loaded_.scene, request_.scene.memory.bytes, log_);
  options_.textures = images_.textures.get();
  if (images_.environment) options_.environment = &*images_.environment;
}

// The journal beside the output: what --resume continues after a kill or an interrupt. The ranks
// of a job check they render the same thing before any of them renders.
void RenderSession::open_journal() {
  const bool journaled = !request_.journal.empty();
  if (!journaled && !job_) return;
  const TileGrid tiles = grid();
  RenderJobSettings settings;
  for (const SceneOverride& set : request_.scene.overrides) settings.overrides.push_back(set.assignment);
  settings.backend = std::string(backend_->name());
  settings.backend_options = request_.backend_options;
  settings.region = tiles.region();
  settings.tile_size = tiles.tile_size();
  settings.channels = FilmLayout(options_.aovs).channels();
  settings.adaptive = options_.adaptive;
  settings.compact_normals = request_.scene.compact_normals;
  settings.piece_triangles = request_.scene.piece_triangles;
  const JobIdentity identity = render_job_identity(loaded_.description, loaded_.report, loaded_.scene, settings);
  if (job_) agree_on_job(*job_, identity, request_.start_timeout);
  if (!journaled) return;
  journal_ =
      open_render_journal(request_.journal, identity, tiles, render_sums(options_).floats(), request_.resume, log_);
  options_.journal_items = journal_.finished;
}

TileGrid RenderSession::grid() const {
  return render_grid(loaded_.scene, checked_region(loaded_.scene, options_), options_.tile_size);
}

std::vector<RenderObserver*> RenderSession::observers(RenderObserver& progress) {
  std::vector<RenderObserver*> observers;
  if (preview_) observers.push_back(preview_.get());
  if (journal_.journal) {
    journal_.record_from = std::chrono::steady_clock::now() + request_.journal_after;
    observers.push_back(&journal_);
  }
  observers.push_back(&progress);
  return observers;
}

std::vector<RankStats> RenderSession::ranks() const {
  return executor_ ? executor_->ranks() : std::vector<RankStats>();
}

int RenderSession::follow() {
  const TileGrid tiles = grid();
  const TileRenderer renderer(loaded_.scene, *backend_, tiles, render_sums(options_), options_.textures,
                              options_.environment);
  // mpirun passes Ctrl-C on as SIGTERM to every rank: each finishes its tiles in flight and
  // rank 0 writes the partial image, as a single process does (if mpirun allows the time:
  // its odls_base_sigkill_timeout, 1 s by default).
  const InterruptGuard interrupt;
  follow_distributed_render(*job_, renderer, tiles, request_.threads, &InterruptGuard::requested(),
                            request_.rank_timeout);
  return kExitOk;
}

RenderResult RenderSession::render() {
  RenderOptions options = options_;
  if (job_) {
    executor_.emplace(*job_, &*render_thread_, request_.rank_timeout);
    options.tile_executor = &*executor_;
  }
  ProgressReporter progress(request_.progress, isatty(STDERR_FILENO) == 1, request_.frame);
  options.cancel = &InterruptGuard::requested();
  options.observers = observers(progress);
  options.tracing_done = [this] { release_backend(); };
  RenderResult result = render_image(loaded_.scene, *backend_, options);
  progress.finish(result.tiles_done, result.tiles_total);
  const std::string passes = std::to_string(result.passes_done) + " of " + std::to_string(result.passes_total);
  if (result.stop == RenderStop::kConverged)
    log_.info("every pixel converged after " + passes + " passes (--noise-threshold)");
  if (result.stop == RenderStop::kTimeLimit) log_.info("stopped at the time limit after " + passes + " passes");
  return result;
}

}  // namespace rtpro::cli
