// Backend speed, native vs embree on the same scenes in the same run: BVH build time, primary-ray
// throughput (closest hit only) and whole-render throughput (camera + shadow + reflection rays).
// Scenes: every scenes/*.yaml whose meshes are present, or those named in $RTPRO_BENCH_SCENES
// (colon separated); $RTPRO_BENCH_SIZE=WxH overrides every scene's resolution. Run a Release build;
// `benchmarks/run_benchmarks.sh` and `benchmarks/dragon_benchmark.sh` print the tables.
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/render/camera.h"
#include "light_sample.h"
#include "ray_offset.h"
#include "surface.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace rtpro;

std::vector<std::filesystem::path> benchmark_scenes() {
  std::vector<std::filesystem::path> scenes;
  if (const char* list = std::getenv("RTPRO_BENCH_SCENES")) {
    std::stringstream stream(list);
    for (std::string item; std::getline(stream, item, ':');)
      if (!item.empty()) scenes.emplace_back(item);
    return scenes;
  }
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(RTPRO_SOURCE_DIR) / "scenes"))
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

struct LoadedScene {
  std::string name;
  RenderScene scene;
};

// Scenes are parsed and loaded once per process; benchmarks only time backends and rendering.
const std::vector<std::unique_ptr<LoadedScene>>& loaded_scenes() {
  static const auto scenes = [] {
    std::vector<std::unique_ptr<LoadedScene>> out;
    for (const auto& file : benchmark_scenes()) {
      try {
        auto loaded = std::make_unique<LoadedScene>();
        loaded->name = file.stem().string();
        std::vector<std::string> overrides{"render.spp=1"};
        if (const char* size = std::getenv("RTPRO_BENCH_SIZE")) {
          std::string resolution(size);
          resolution.replace(resolution.find('x'), 1, ",");
          overrides.push_back("camera.resolution=[" + resolution + "]");
        }
        loaded->scene = build_render_scene(parse_scene_file(file, overrides));
        out.push_back(std::move(loaded));
      } catch (const std::exception& e) {
        std::cerr << "skipping " << file << ": " << e.what() << "\n";
      }
    }
    return out;
  }();
  return scenes;
}

std::vector<Ray> camera_rays(const RenderScene& scene) {
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(scene.camera.width) * scene.camera.height);
  for (int y = 0; y < scene.camera.height; ++y)
    for (int x = 0; x < scene.camera.width; ++x)
      rays.push_back(
          camera_ray(scene.camera, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, {0.5f, 0.5f}));
  return rays;
}

void build(benchmark::State& state, const LoadedScene* loaded, BackendKind kind) {
  for (auto _ : state) {
    auto backend = make_backend(kind, loaded->scene, {});
    benchmark::DoNotOptimize(backend.get());
  }
}

void primary_rays(benchmark::State& state, const LoadedScene* loaded, BackendKind kind) {
  const auto backend = make_backend(kind, loaded->scene, {});
  const std::vector<Ray> rays = camera_rays(loaded->scene);
  std::vector<Hit> hits(rays.size());
  constexpr std::size_t kBlock = 4096;  // like a tile of camera rays, traced as one batch
  for (auto _ : state) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kBlock), [&](const auto& r) {
      set_tracing_fp_mode();
      backend->intersect(std::span(rays).subspan(r.begin(), r.size()), std::span(hits).subspan(r.begin(), r.size()),
                         RayCoherence::kCoherent);
    });
    benchmark::ClobberMemory();
  }
  state.counters["Mrays/s"] =
      benchmark::Counter(static_cast<double>(rays.size()) * state.iterations() * 1e-6, benchmark::Counter::kIsRate);
}

// Camera rays plus one shadow ray per hit towards the scene's first light: the two queries a
// direct-lighting renderer makes, without shading cost.
void primary_and_shadow_rays(benchmark::State& state, const LoadedScene* loaded, BackendKind kind) {
  const auto backend = make_backend(kind, loaded->scene, {});
  const std::vector<Ray> rays = camera_rays(loaded->scene);
  if (loaded->scene.lights.empty()) {
    state.SkipWithError("scene has no light");
    return;
  }
  const Light& light = loaded->scene.lights.front();
  std::vector<Hit> hits(rays.size());
  std::atomic<std::uint64_t> traced{0};
  constexpr std::size_t kBlock = 4096;
  for (auto _ : state) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kBlock), [&](const auto& r) {
      set_tracing_fp_mode();
      backend->intersect(std::span(rays).subspan(r.begin(), r.size()), std::span(hits).subspan(r.begin(), r.size()),
                         RayCoherence::kCoherent);
      std::vector<Ray> shadow_rays;
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        if (!hits[i].valid()) continue;
        const SurfacePoint sp = make_surface(loaded->scene, rays[i], hits[i]);
        const LightSample ls = sample_light(light, sp.position, Sample2D{0.5f, 0.5f});
        shadow_rays.push_back(std::isinf(ls.distance) ? spawn_ray(sp, ls.direction)
                                                      : spawn_ray_to(sp, sp.position + ls.direction * ls.distance));
      }
      std::vector<std::uint8_t> occluded(shadow_rays.size());
      backend->occluded(shadow_rays, occluded, RayCoherence::kIncoherent);
      benchmark::DoNotOptimize(occluded.data());
      traced += r.size() + shadow_rays.size();
    });
  }
  state.counters["Mrays/s"] =
      benchmark::Counter(static_cast<double>(traced.load()) * 1e-6, benchmark::Counter::kIsRate);
}

void whole_render(benchmark::State& state, const LoadedScene* loaded, BackendKind kind) {
  const auto backend = make_backend(kind, loaded->scene, {});
  std::uint64_t rays = 0;
  for (auto _ : state) {
    const RenderResult result = render_image(loaded->scene, *backend, {});
    rays += result.rays.total();
  }
  state.counters["Mrays/s"] = benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
}

using BackendBenchmark = void (*)(benchmark::State&, const LoadedScene*, BackendKind);

void register_benchmarks() {
  const std::pair<const char*, BackendBenchmark> kinds[] = {{"build", build},
                                                            {"primary", primary_rays},
                                                            {"primary_shadow", primary_and_shadow_rays},
                                                            {"render_1spp", whole_render}};
  for (const auto& loaded : loaded_scenes())
    for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree})
      for (const auto& [label, function] : kinds) {
        const std::string name = std::string(label) + "/" + loaded->name + "/" + std::string(backend_name(kind));
        benchmark::RegisterBenchmark(name.c_str(), function, loaded.get(), kind)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  register_benchmarks();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
