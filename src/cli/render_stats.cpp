#include "render_stats.h"

#include <sys/resource.h>

#include <cstdio>

namespace rtpro::cli {

std::size_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

namespace {

// "N camera  N shadow  N reflection  N refraction  (N total)".
std::string rays_text(const RayCounts& rays) {
  std::string text;
  for (const RayKind kind : kRayKinds) text += std::to_string(rays[kind]) + " " + ray_kind_name(kind) + "  ";
  return text + "(" + std::to_string(rays.total()) + " total)";
}

// {"camera": N, "shadow": N, "reflection": N, "refraction": N, "total": N}: the keys benchmarks read.
nlohmann::json rays_json(const RayCounts& rays) {
  nlohmann::json out;
  for (const RayKind kind : kRayKinds) out[ray_kind_name(kind)] = rays[kind];
  out["total"] = rays.total();
  return out;
}

std::string region_text(const PixelRegion& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y1);
}

}  // namespace

std::string samples_text(const SampleCounts& samples, int requested) {
  if (samples.uniform() && samples.max == requested) return std::to_string(requested) + " spp";
  if (samples.uniform()) return std::to_string(samples.max) + " of " + std::to_string(requested) + " spp";
  char mean[32];
  std::snprintf(mean, sizeof mean, "%.1f", samples.mean);
  return std::to_string(samples.min) + "-" + std::to_string(samples.max) + " spp (mean " + mean + ") of " +
         std::to_string(requested);
}

std::string size_text(const RenderStatistics& stats) {
  const std::string size = std::to_string(stats.width) + "x" + std::to_string(stats.height);
  if (!stats.region) return size;
  if (!stats.crop) return size + ", region " + region_text(*stats.region);
  return size + ", the crop " + region_text(*stats.region) + " of " + std::to_string(stats.full_width) + "x" +
         std::to_string(stats.full_height);
}

std::string RenderStatistics::text() const {
  const auto mib = [](std::size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
  char buffer[2048];
  std::snprintf(buffer, sizeof buffer,
                "statistics\n"
                "  image         %s, %s%s\n"
                "  backend       %s, %d threads\n"
                "  time          load %.3fs  build %.3fs  render %.3fs  write %.3fs  total %.3fs\n"
                "  rays          %s\n"
                "  speed         %.2f Mrays/s\n"
                "  rejected      %llu rays,  %llu NaN samples\n"
                "  memory        peak RSS %.1f MiB (%.1f after load, %.1f after build), geometry %.1f MiB, "
                "acceleration structure %.1f MiB\n",
                size_text(*this).c_str(), samples_text(samples, spp).c_str(), complete ? "" : " (interrupted: partial)",
                backend.c_str(), threads, load_seconds, build_seconds, render_seconds, write_seconds, total_seconds,
                rays_text(rays).c_str(), mrays_per_second(), static_cast<unsigned long long>(rejected_rays),
                static_cast<unsigned long long>(nan_samples), mib(peak_rss_bytes), mib(peak_rss_after_load_bytes),
                mib(peak_rss_after_build_bytes), mib(geometry_bytes), mib(acceleration_bytes));
  std::string out = buffer;
  if (acceleration_build_peak_bytes > 0) {
    std::snprintf(buffer, sizeof buffer, "  BVH build     %.1f MiB at most while built\n",
                  mib(acceleration_build_peak_bytes));
    out += buffer;
  }
  if (triangles > 0) {
    std::snprintf(buffer, sizeof buffer, "  triangles     %llu, %.1f bytes each (geometry and acceleration)\n",
                  static_cast<unsigned long long>(triangles), bytes_per_triangle());
    out += buffer;
  }
  if (ranks.empty()) return out;
  std::snprintf(buffer, sizeof buffer,
                "  ranks         %zu, load imbalance %.3f (busiest rank's busy time over the mean)\n", ranks.size(),
                load_imbalance(ranks));
  out += buffer;
  for (const RankStats& r : ranks) {
    std::snprintf(buffer, sizeof buffer,
                  "    rank %-3d    %llu tiles  %llu rays  busy %.3fs  idle %.3fs (thread-seconds)  sent %.2f MiB\n",
                  r.rank, static_cast<unsigned long long>(r.tiles), static_cast<unsigned long long>(r.rays.total()),
                  r.busy_seconds, r.idle_seconds, mib(r.bytes_sent));
    out += buffer;
  }
  const RankStats& leader = ranks.front();
  std::snprintf(buffer, sizeof buffer,
                "  scheduler     rank 0 took in %llu tiles from other ranks, %.1f us of its CPU per tile\n",
                static_cast<unsigned long long>(leader.remote_tiles),
                leader.remote_tiles > 0 ? leader.scheduler_seconds / double(leader.remote_tiles) * 1e6 : 0.0);
  out += buffer;
  return out;
}

nlohmann::json RenderStatistics::json() const {
  nlohmann::json out = {
      {"scene", scene},
      {"output", output},
      {"backend", backend},
      {"threads", threads},
      // The most samples a pixel took: what was asked unless a time limit, adaptive sampling or an
      // interrupt stopped short.
      {"spp", samples.max},
      {"spp_requested", spp},
      {"spp_taken", {{"min", samples.min}, {"mean", samples.mean}, {"max", samples.max}}},
      {"resolution", {width, height}},
      {"full_resolution", {full_width, full_height}},
      {"complete", complete},
      {"passes", {{"done", passes_done}, {"total", passes_total}, {"stop", stop}, {"seconds", pass_seconds}}},
      {"seconds",
       {{"load", load_seconds},
        {"build", build_seconds},
        {"render", render_seconds},
        {"write", write_seconds},
        {"denoise", denoise_seconds},
        {"total", total_seconds}}},
      {"rays", rays_json(rays)},
      {"mrays_per_second", mrays_per_second()},
      {"rejected_rays", rejected_rays},
      {"nan_samples", nan_samples},
      {"triangles", triangles},
      {"bytes_per_triangle", bytes_per_triangle()},
      {"memory_bytes",
       {{"peak_rss", peak_rss_bytes},
        {"peak_rss_after_load", peak_rss_after_load_bytes},
        {"peak_rss_after_build", peak_rss_after_build_bytes},
        {"geometry", geometry_bytes},
        {"acceleration", acceleration_bytes},
        {"acceleration_build_peak", acceleration_build_peak_bytes}}}};
  if (region) {
    out["region"] = {region->x0, region->y0, region->x1, region->y1};
    out["crop"] = crop;
  }
  if (!ranks.empty()) {
    nlohmann::json per_rank = nlohmann::json::array();
    for (const RankStats& r : ranks)
      per_rank.push_back({{"rank", r.rank},
                          {"tiles", r.tiles},
                          {"rays", r.rays.total()},
                          {"busy_seconds", r.busy_seconds},
                          {"idle_seconds", r.idle_seconds},
                          {"bytes_sent", r.bytes_sent}});
    out["ranks"] = per_rank;
    out["scheduler"] = {{"remote_tiles", ranks.front().remote_tiles}, {"cpu_seconds", ranks.front().scheduler_seconds}};
    out["load_imbalance"] = load_imbalance(ranks);
  }
  return out;
}

}  // namespace rtpro::cli
