#include "render_request.h"

#include "pixel_region_option.h"
#include "render_output.h"
#include "thread_count.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/color_config.h"
#include "rtpro/image/output_check.h"
#include "rtpro/job/tile_journal.h"
#include "rtpro/scene/mesh_pieces.h"
#include "rtpro/render/film.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace rtpro::cli {

namespace {

// The region, the tile size and the layers, as the renderer takes them.
RenderOptions parse_render_options(const RenderCommandOptions& o) {
  RenderOptions options;
  options.region = parse_region(o.region);
  if (o.tile_size < 1) throw InputError("--tile-size must be at least 1 pixel, got " + std::to_string(o.tile_size));
  if (o.piece_triangles != 0 && o.piece_triangles < kMinPieceTriangles)
    throw InputError("--embree-pieces must be 0 (whole meshes) or at least " + std::to_string(kMinPieceTriangles) +
                     " triangles, got " + std::to_string(o.piece_triangles));
  options.tile_size = o.tile_size;
  for (const std::string& name : o.aovs) {
    const Aov aov = parse_aov(name);
    // Refused now, not by the image writer after the render: each layer's channels appear once.
    if (std::find(options.aovs.begin(), options.aovs.end(), aov) != options.aovs.end())
      throw InputError("--aov " + name + " is given twice");
    options.aovs.push_back(aov);
  }
  return options;
}

// --denoise renders the layers the denoiser reads as well; an EXR keeps them (and the noisy
// colour), so `rtpro denoise` can run on it again.
void add_denoiser_layers(std::vector<Aov>& aovs) {
  for (Aov aov : {Aov::kAlbedo, Aov::kNormal, Aov::kDepth, Aov::kHalves})
    if (std::find(aovs.begin(), aovs.end(), aov) == aovs.end()) aovs.push_back(aov);
}

std::string chosen_ocio_display(const RenderCommandOptions& o, Log& log) {
  if (!o.deprecated_display.empty() && !o.display.empty())
    throw InputError("--display is the old spelling of --ocio-display: give only --ocio-display");
  if (!o.deprecated_display.empty())
    log.warning("--display is deprecated: it names an OpenColorIO display; write --ocio-display " +
                o.deprecated_display + " (pbrt's live preview is --display-server)");
  return o.display.empty() ? o.deprecated_display : o.display;
}

// Checked even with -q, which silences it unless it is JSON for a program: a typo is an error
// whether or not it shows.
ProgressMode shown_progress(const RenderCommandOptions& o, bool leader) {
  const ProgressMode chosen = parse_progress_mode(o.progress);
  return !leader || (o.quiet && chosen != ProgressMode::kJson) ? ProgressMode::kNever : chosen;
}

// What ends the render early or lets pixels stop: the time limit, the rank timeout, adaptive sampling.
void check_stopping_options(const RenderCommandOptions& o, bool distributed) {
  if (!(o.time_limit >= 0.0 && o.time_limit < 1e9))
    throw InputError("--time-limit must be a number of seconds >= 0 (0: no limit)");
  if (!(o.rank_timeout == 0.0 || (o.rank_timeout >= 1.0 && o.rank_timeout <= 1e6)))
    throw InputError("--rank-timeout must be 0 (wait for ever) or between 1 and 1000000 seconds");
  if (!(o.start_timeout == 0.0 || (o.start_timeout >= 1.0 && o.start_timeout <= 1e6)))
    throw InputError("--start-timeout must be 0 (wait for ever) or between 1 and 1000000 seconds");
  // Below 1e-6 no float sum of samples resolves the noise, and 1/threshold stops fitting the
  // sample counts it decides.
  if (!(o.noise_threshold == 0.0 || (o.noise_threshold >= 1e-6 && o.noise_threshold < 1e6)))
    throw InputError(
        "--noise-threshold must be 0 (every pixel takes every sample) or from 0.000001 to 1000000 (Cycles' default "
        "is 0.01)");
  if (o.min_samples < 0) throw InputError("--min-samples must be >= 0 (0: automatic)");
  if (o.min_samples > 0 && o.noise_threshold == 0.0) throw InputError("--min-samples needs --noise-threshold");
  if (o.noise_threshold > 0.0 && distributed)
    throw InputError(
        "--noise-threshold decides between passes from the whole image, which only rank 0 has: "
        "render adaptively in one process");
}

// Fail before the render, not after it: the output's folder and format, and no output replacing
// another file of the render.
void check_output_files(const RenderCommandOptions& o, const OutputTarget& output) {
  check_image_output(output.file());
  if (!o.stats_json.empty()) check_replaceable(o.stats_json);
  check_output_is_distinct({"--stats-json", o.stats_json}, {{"-o", o.output}, {"the scene", o.scene}});
  check_output_is_distinct({"-o", o.output}, {{"the scene", o.scene}});
}

// The colour config, display and view a display-referred output goes through, loaded now so a
// typo fails before the render. Only what a user chose can be mistyped: the bundled config with
// its own display and view is loaded when the image is written, once the BVH is freed, so that
// OpenColorIO's parse and processor (1.4 MiB resident) do not add to the build's peak.
ImageWriteOptions colour_output(const RenderCommandOptions& o, const std::string& display, const OutputTarget& output,
                                bool leader, Log& log) {
  ImageWriteOptions write;
  if (!o.ocio_config.empty()) write.ocio_config = o.ocio_config;
  write.display = display;
  write.view = o.view;
  const char* environment_config = std::getenv("OCIO");
  const bool chosen = write.ocio_config || !display.empty() || !o.view.empty() ||
                      (environment_config != nullptr && *environment_config != '\0');
  if (!leader || writes_scene_linear(output.file())) return write;
  if (!chosen) {
    log.verbose("colour: OCIO config bundled, its default display and view");
    return write;
  }
  const ColorConfig colors = ColorConfig::load(write.ocio_config);
  const DisplayTransform transform = colors.display_transform(display, o.view);
  log.verbose("colour: OCIO config " + colors.source() + ", display '" + transform.display() + "', view '" +
              transform.view() + "'");
  return write;
}

int channels_beyond_colour(const std::vector<Aov>& aovs) {
  int channels = 0;
  for (Aov aov : aovs) channels += static_cast<int>(aov_channel_names(aov).size());
  return channels;
}

}  // namespace

LogLevel render_log_level(const RenderCommandOptions& o, const Communicator* job) {
  const bool leader = !job || job->rank() == 0;
  return o.quiet || !leader ? LogLevel::kQuiet : (o.verbose > 0 ? LogLevel::kVerbose : LogLevel::kNormal);
}

RenderRequest parse_render_request(const RenderCommandOptions& o, const Communicator* job, Log& log) {
  const bool leader = !job || job->rank() == 0;
  const BackendKind backend = parse_backend_kind(o.backend);
  const int threads = worker_thread_count(o.threads);
  RenderOptions render = parse_render_options(o);
  OutputTarget output(o.output, o.format);
  check_exposure(o.exposure);
  std::optional<DisplayServerAddress> display_server;
  if (!o.display_server.empty()) display_server = parse_display_server(o.display_server);
  if (!render.aovs.empty() && !holds_layers(output.file()))
    throw InputError("--aov needs an EXR output: '" + o.output + "' holds only the colour image");
  if (o.denoise) add_denoiser_layers(render.aovs);
  const std::string display = chosen_ocio_display(o, log);
  const ProgressMode progress = shown_progress(o, leader);
  if (o.crop && !render.region) throw InputError("--crop needs --region");
  if (!(o.journal_after >= 0.0 && o.journal_after <= 1e6))
    throw InputError("--journal-after must be between 0 and 1000000 seconds");
  if (o.resume && o.no_journal)
    throw InputError("--resume reads the journal that --no-journal turns off: give one of them");
  if (o.resume && output.to_stdout()) throw InputError("--resume needs an output file: -o - keeps no journal");
  check_stopping_options(o, job != nullptr);
  render.time_limit_seconds = o.time_limit;
  const MemoryBudget memory = parse_memory_budget(o.max_memory_mb);
  // Only the leader writes: the output's folder may not even exist on another rank's node.
  if (leader) check_output_files(o, output);
  ImageWriteOptions write = colour_output(o, display, output, leader, log);

  BackendOptions backend_options = o.backend_options;
  backend_options.threads = threads;
  backend_options.max_memory_bytes = memory.explicit_limit ? memory.bytes : 0;
  const bool journaled = leader && !o.no_journal && !output.to_stdout();
  const std::filesystem::path journal = journaled ? journal_path(output.file()) : std::filesystem::path();
  std::string preview_name = std::filesystem::path(output.name()).filename().string();
  return RenderRequest{
      .leader = leader,
      .threads = threads,
      .scene = {o.scene, o.scene_overrides, memory, channels_beyond_colour(render.aovs), render.region, o.region,
                o.compact_normals, o.piece_triangles},
      .backend = backend,
      .backend_options = backend_options,
      .render = render,
      .noise_threshold = o.noise_threshold,
      .min_samples = o.min_samples,
      .noise_metric = parse_noise_metric(o.noise_metric),
      .output = std::move(output),
      .write = std::move(write),
      .exposure = o.exposure,
      .crop = o.crop,
      .denoise = o.denoise,
      .display_server = leader ? display_server : std::nullopt,
      .preview_name = std::move(preview_name),
      .progress = progress,
      .frame = o.frame,
      .journal = journal,
      .journal_after = std::chrono::milliseconds(static_cast<std::int64_t>(o.journal_after * 1000.0)),
      .resume = o.resume,
      .rank_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(o.rank_timeout * 1000.0)),
      .start_timeout = std::chrono::milliseconds(static_cast<std::int64_t>(o.start_timeout * 1000.0)),
      .print_stats = o.stats,
      .stats_json = o.stats_json,
  };
}

}  // namespace rtpro::cli
