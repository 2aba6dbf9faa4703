#pragma once
// End-of-render statistics (`--stats`, `--stats-json FILE`).
#include "rtpro/backend/backend.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/render/renderer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace rtpro::cli {

struct RenderStatistics {
  std::string scene;
  std::string output;
  std::string backend;
  int threads = 0;
  int spp = 0;
  int width = 0, height = 0;
  double load_seconds = 0, build_seconds = 0, render_seconds = 0, write_seconds = 0, total_seconds = 0;
  double denoise_seconds = 0;  // within write: --denoise
  RayCounts rays;
  std::uint64_t rejected_rays = 0;
  std::uint64_t nan_samples = 0;
  std::size_t acceleration_bytes = 0;
  std::size_t peak_rss_bytes = 0;
  bool complete = true;
  int passes_done = 0, passes_total = 0;
  std::string stop = "all passes";   // or "converged", "time limit", "interrupted"
  std::vector<double> pass_seconds;  // of the passes rendered by this run
  std::vector<RankStats> ranks;      // of a distributed render (mpirun), by rank; empty otherwise

  double mrays_per_second() const { return render_seconds > 0 ? rays.total() / render_seconds * 1e-6 : 0.0; }
  std::string text() const;
  nlohmann::json json() const;
};

// Peak resident set size of this process so far.
std::size_t peak_rss_bytes();

}  // namespace rtpro::cli
