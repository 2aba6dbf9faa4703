#pragma once
// End-of-render statistics (`--stats`, `--stats-json FILE`).
#include "rtpro/backend/backend.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/render/renderer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rtpro::cli {

struct RenderStatistics {
  std::string scene;
  std::string output;
  std::string backend;
  int threads = 0;
  int spp = 0;                          // asked for (render.spp, --spp)
  SampleCounts samples;                 // taken, per pixel of the region
  int width = 0, height = 0;            // of the image written: the crop's with --crop
  int full_width = 0, full_height = 0;  // the camera's
  std::optional<PixelRegion> region;    // --region
  bool crop = false;
  double load_seconds = 0, build_seconds = 0, render_seconds = 0, write_seconds = 0, total_seconds = 0;
  double denoise_seconds = 0;  // within write: --denoise
  RayCounts rays;
  std::uint64_t rejected_rays = 0;
  std::uint64_t nan_samples = 0;
  std::size_t acceleration_bytes = 0;
  std::size_t acceleration_build_peak_bytes = 0;  // the most the BVH build held at once (embree; 0: not known)
  // rtpro's own arrays of the shapes (vertices, indices, normals, texture coordinates, spheres):
  // with acceleration_bytes, what the geometry costs; per stored triangle, bytes_per_triangle().
  std::size_t geometry_bytes = 0;
  std::uint64_t triangles = 0;  // stored once each, however often instanced
  // The peak resident set size at the end of each phase, which tells which one holds the peak:
  // reading the scene (files parsed, meshes assembled), building the backend, then the whole run.
  std::size_t peak_rss_after_load_bytes = 0;
  std::size_t peak_rss_after_build_bytes = 0;
  std::size_t peak_rss_bytes = 0;
  bool complete = true;
  int passes_done = 0, passes_total = 0;
  std::string stop = "all passes";   // or "converged", "time limit", "interrupted"
  std::vector<double> pass_seconds;  // of the passes rendered by this run
  std::vector<RankStats> ranks;      // of a distributed render (mpirun), by rank; empty otherwise

  double mrays_per_second() const { return render_seconds > 0 ? rays.total() / render_seconds * 1e-6 : 0.0; }
  double bytes_per_triangle() const {
    return triangles > 0 ? double(geometry_bytes + acceleration_bytes) / double(triangles) : 0.0;
  }
  std::string text() const;
  nlohmann::json json() const;
};

// The samples a render took, for people: "16 spp" when every pixel took what was asked,
// "32 of 1024 spp" when every pixel took fewer, "16-1024 spp (mean 41.3) of 1024" otherwise.
std::string samples_text(const SampleCounts& samples, int requested);

// The image's size, for people: "24x16", "24x16, region 4,2,20,10", "16x8, the crop 4,2,20,10 of
// 24x16".
std::string size_text(const RenderStatistics& stats);

// Peak resident set size of this process so far.
std::size_t peak_rss_bytes();

}  // namespace rtpro::cli
