#include "deliver_render.h"

#include "non_finite_pixels.h"

#include "output_target.h"
#include "path_controls.h"
#include "progress.h"
#include "render_output.h"
#include "render_stats.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/scene/scene_summary.h"

#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rtpro::cli {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const char* stop_name(RenderStop stop) {
  switch (stop) {
    case RenderStop::kAllPasses: return "all passes";
    case RenderStop::kConverged: return "converged";
    case RenderStop::kTimeLimit: return "time limit";
    case RenderStop::kInterrupted: return "interrupted";
  }
  return "?";
}

// What the render measured and counted; the writing's figures come later.
RenderStatistics render_statistics(const RenderRequest& request, const RenderSession& session,
                                   const RenderResult& result, double load_seconds) {
  const RenderScene& scene = session.scene();
  RenderStatistics stats;
  stats.scene = request.scene.file;
  stats.output = request.output.name();
  stats.threads = request.threads;
  stats.spp = scene.render.spp;
  stats.samples = result.samples;
  stats.full_width = scene.camera.width;
  stats.full_height = scene.camera.height;
  stats.region = request.render.region;
  stats.crop = request.crop && request.render.region;
  stats.width = stats.crop ? stats.region->width() : scene.camera.width;
  stats.height = stats.crop ? stats.region->height() : scene.camera.height;
  stats.load_seconds = load_seconds;
  stats.backend = std::string(session.backend_name());
  stats.build_seconds = session.backend_stats().build_seconds;
  stats.ranks = session.ranks();
  stats.render_seconds = result.seconds;
  stats.rays = result.rays;
  stats.nan_samples = result.nan_samples;
  stats.complete = result.complete();
  stats.passes_done = result.passes_done;
  stats.passes_total = result.passes_total;
  stats.pass_seconds = result.pass_seconds;
  stats.stop = stop_name(result.stop);
  return stats;
}

std::vector<std::pair<std::string, std::string>> image_metadata(const RenderRequest& request, const RenderScene& scene,
                                                                const std::string& backend,
                                                                const RenderResult& result) {
  std::vector<std::pair<std::string, std::string>> metadata = {
      {"Software", std::string("rtpro ") + RTPRO_VERSION},
      {"rtpro:backend", backend},
      // As taken (a time limit or adaptive sampling takes fewer than asked): the most a pixel took,
      // then the least and the mean.
      {"rtpro:spp", std::to_string(result.samples.max)},
      {"rtpro:spp_min", std::to_string(result.samples.min)},
      {"rtpro:spp_mean", std::to_string(result.samples.mean)},
      {"rtpro:spp_max", std::to_string(result.samples.max)},
      {"rtpro:spp_requested", std::to_string(scene.render.spp)},
      {"rtpro:seed", std::to_string(scene.render.seed)},
      {"rtpro:max_depth", std::to_string(scene.render.max_depth)},
      {"rtpro:integrator", integrator_name(scene.render.integrator)},
      {"rtpro:render_seconds", std::to_string(result.seconds)},
      {"rtpro:scene", request.scene.file},
  };
  if (scene.render.integrator == Integrator::kPath)
    for (const PathControlValue& control : path_control_values(scene.render))
      metadata.push_back({"rtpro:" + control.key, control.text()});
  if (request.render.region) metadata.push_back({"rtpro:region", request.scene.region_text});
  // A cropped image says where it belongs.
  if (request.render.region && request.crop)
    metadata.push_back(
        {"rtpro:full_resolution", std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height)});
  if (request.frame >= 0) metadata.push_back({"rtpro:frame", std::to_string(request.frame)});
  if (result.passes_done < result.passes_total)
    metadata.push_back(
        {"rtpro:passes", std::to_string(result.passes_done) + " of " + std::to_string(result.passes_total)});
  if (!result.complete())
    metadata.push_back(
        {"rtpro:partial", std::to_string(result.tiles_done) + " of " + std::to_string(result.tiles_total) + " tiles"});
  if (request.exposure != 0.0) metadata.push_back({"rtpro:exposure", std::to_string(request.exposure)});
  return metadata;
}

// The image as written: cropped (--crop), denoised (--denoise, a complete render only), exposed.
Image finished_image(const RenderRequest& request, RenderResult& result, RenderStatistics& stats, Log& log) {
  Image image = request.crop ? crop_image(result.image, *request.render.region) : std::move(result.image);
  if (request.denoise && result.complete()) {
    const auto denoise_start = Clock::now();
    // An EXR keeps the noisy colour and the layers; a display image holds the colour alone.
    Image denoised = denoise(image);
    image = holds_layers(request.output.file()) ? with_denoised_colour(image, denoised) : std::move(denoised);
    stats.denoise_seconds = seconds_since(denoise_start);
    log.verbose("denoised in " + std::to_string(stats.denoise_seconds) + " s");
  }
  apply_exposure(image, request.exposure);
  if (const auto warning = non_finite_pixels_warning(image))
    log.warning(*warning + " and written as they are: a radiance in the scene is too large for 32-bit floats");
  return image;
}

void report_statistics(const RenderRequest& request, RenderStatistics& stats, const RenderScene& scene,
                       const BackendStats& backend_stats, Clock::time_point start, Log& log) {
  stats.rejected_rays = backend_stats.rejected_rays;
  stats.acceleration_bytes = backend_stats.acceleration_bytes;
  stats.acceleration_build_peak_bytes = backend_stats.build_peak_bytes;
  stats.peak_rss_bytes = peak_rss_bytes();
  if (request.print_stats || !request.stats_json.empty()) {
    const SceneSummary summary = summarize(scene);
    stats.geometry_bytes = summary.geometry_bytes;
    stats.triangles = summary.triangles_stored;
  }
  stats.total_seconds = seconds_since(start);
  if (stats.rejected_rays > 0) log.warning(std::to_string(stats.rejected_rays) + " rays were rejected as untraceable");
  if (stats.nan_samples > 0) log.warning(std::to_string(stats.nan_samples) + " samples were NaN or infinite");
  log.summarise_repeats();
  if (request.print_stats) std::fputs(stats.text().c_str(), stderr);
  if (!request.stats_json.empty()) write_file_atomically(request.stats_json, stats.json().dump(2) + "\n");
}

// Said even with -q: the image on disk is not the one asked for.
void say_interrupted(const RenderResult& result, const std::filesystem::path& written, const TileJournal* journal) {
  const std::string finished = result.passes_done > 0
                                   ? "the " + std::to_string(result.passes_done) + " of " +
                                         std::to_string(result.passes_total) + " finished passes"
                                   : "the " + std::to_string(result.tiles_done) + " finished tiles of the first pass";
  std::fprintf(stderr, "rtpro: interrupted: wrote %s to %s\n", finished.c_str(),
               printable_message(written.string()).c_str());
  if (journal)
    std::fprintf(stderr, "rtpro: the same command with --resume renders only the rest (journal %s)\n",
                 printable_message(journal->file().string()).c_str());
}

}  // namespace

int deliver_render(const RenderRequest& request, RenderSession& session, RenderResult&& result,
                   const RenderTimes& times, Log& log) {
  const auto write_start = Clock::now();
  RenderStatistics stats = render_statistics(request, session, result, times.load_seconds);
  session.release_backend();
  const BackendStats backend_stats = session.backend_stats();
  ImageWriteOptions write = request.write;
  write.metadata = image_metadata(request, session.scene(), stats.backend, result);
  const Image image = finished_image(request, result, stats, log);
  const std::filesystem::path written = request.output.write(image, result.complete(), write);
  if (TileJournal* journal = session.journal()) {
    if (const std::string error = journal->error(); !error.empty()) log.warning(error);
    if (result.complete()) journal->remove();
  }
  stats.write_seconds = seconds_since(write_start);
  stats.peak_rss_after_load_bytes = times.peak_rss_after_load_bytes;
  stats.peak_rss_after_build_bytes = session.peak_rss_after_build_bytes();
  report_statistics(request, stats, session.scene(), backend_stats, times.start, log);

  if (!result.complete()) {
    say_interrupted(result, written, session.journal());
    return kExitInterrupted;
  }
  std::ostringstream line;
  line << "wrote " << stats.output << " (" << size_text(stats) << ", " << samples_text(stats.samples, stats.spp)
       << (result.stop == RenderStop::kTimeLimit   ? ": time limit"
           : result.stop == RenderStop::kConverged ? ": converged"
                                                   : "")
       << ", " << stats.backend << ") in " << format_duration(stats.total_seconds);
  log.info(line.str());
  return kExitOk;
}

}  // namespace rtpro::cli
