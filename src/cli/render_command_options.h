#pragma once
// What `rtpro render` is told on its command line, and the options that fill it in.
#include "rtpro/backend/backend.h"
#include "scene_overrides.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rtpro::cli {

struct RenderCommandOptions {
  std::string scene;
  std::string output;
  std::string backend = "embree";
  // Kept as the user's text: they become scene overrides checked by the scene file's rules, so
  // "--seed -1" or "--size 4294967297x1" is an error instead of wrapping to another number.
  std::string spp, max_depth, seed, size, integrator;
  // Cycles' Light Paths controls (scene/render_settings.h, PathControls), kept as text likewise.
  std::string max_diffuse_depth, max_glossy_depth, max_transmission_depth, clamp_direct, clamp_indirect, filter_glossy;
  std::optional<int> threads;
  std::string ocio_config, display, deprecated_display, view;
  std::string format;     // for -o -
  double exposure = 0.0;  // stops
  std::vector<std::string> overrides, defines, environments, shutters;
  std::vector<SceneOverride> scene_overrides;  // all of the above, in command-line order
  std::string display_server;                  // HOST:PORT of a tev for a live preview
  std::string frames;                          // FIRST-LAST[:STEP]
  long frame = -1;                             // the frame of --frames being rendered
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
  double journal_after = 1.0;    // seconds of rendering before finished tiles are journaled
  double time_limit = 0.0;       // seconds; 0: none
  double rank_timeout = 60.0;    // seconds a rank of an MPI job may stay silent; 0: for ever
  double start_timeout = 600.0;  // seconds the ranks wait for each other to load the scene; 0: for ever
  double noise_threshold = 0.0;  // 0: no adaptive sampling
  int min_samples = 0;           // 0: automatic (adaptive_sampling.h)
  std::string noise_metric = "cycles";
  BackendOptions backend_options;  // Embree settings from the command line; threads and memory set later
  bool compact_normals = false;
  std::uint32_t piece_triangles = 0;  // --embree-pieces; 0: whole meshes
  std::string max_memory_mb;          // MiB; empty: the default budget (see parse_memory_budget)
};

// Registers every option of `rtpro render` on `cmd`, writing into `o` (which must outlive it).
void add_render_options(CLI::App& cmd, RenderCommandOptions& o);

}  // namespace rtpro::cli
