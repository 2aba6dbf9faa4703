#pragma once
// The first stage of `rtpro render`: its command line checked into what one render is asked to
// do. Every mistake in the options, and every output that could not be written, is an InputError
// here, before the scene is read.
#include "load_scene.h"
#include "log.h"
#include "output_target.h"
#include "progress.h"
#include "render_command_options.h"
#include "tev_client.h"
#include "rtpro/backend/backend.h"
#include "rtpro/distributed/communicator.h"
#include "rtpro/image/image_io.h"
#include "rtpro/render/adaptive_sampling.h"
#include "rtpro/render/renderer.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace rtpro::cli {

struct RenderRequest {
  bool leader = true;  // rank 0 of an MPI job, or the only process: it alone writes and speaks
  int threads = 1;
  SceneLoad scene;  // the file, its overrides, the memory budget, the region
  BackendKind backend = BackendKind::kEmbree;
  BackendOptions backend_options;  // with the thread count and Embree's memory limit
  // The region, tile size, layers (with those --denoise reads) and time limit of the render.
  RenderOptions render;
  // --noise-threshold (0: off), --min-samples as given (0: automatic) and --noise-metric: the
  // render's adaptive sampling once the scene's spp is known.
  double noise_threshold = 0.0;
  int min_samples = 0;
  NoiseMetric noise_metric = NoiseMetric::kCycles;
  OutputTarget output;
  ImageWriteOptions write;  // the colour config, display and view; the metadata comes with the image
  double exposure = 0.0;
  bool crop = false;
  bool denoise = false;
  std::optional<DisplayServerAddress> display_server;  // the leader's live preview, if any
  std::string preview_name;                            // the image's name in the viewer
  ProgressMode progress = ProgressMode::kNever;
  long frame = -1;                             // the frame of --frames; -1: none
  std::filesystem::path journal;               // the leader's resume journal beside the output; empty: none
  std::chrono::milliseconds journal_after{0};  // of rendering before finished tiles are recorded
  bool resume = false;
  std::chrono::milliseconds rank_timeout{0};
  std::chrono::milliseconds start_timeout{0};  // the handshake's, after loading (agree_on_job)
  bool print_stats = false;
  std::string stats_json;
};

// -q quiet (as is every rank but 0: they speak only to fail), -v verbose.
LogLevel render_log_level(const RenderCommandOptions& o, const Communicator* job);

// `job`: the MPI job when mpirun started several ranks. Warnings (a deprecated option) go to `log`.
RenderRequest parse_render_request(const RenderCommandOptions& o, const Communicator* job, Log& log);

}  // namespace rtpro::cli
