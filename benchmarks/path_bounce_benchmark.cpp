// Packets against single rays, bounce by bounce, for the path integrator's rays. One frame of a
// scene at 1 spp is path traced once through a backend that records every batch it is handed
// (generation g's rays, then generation g's shadow rays); then each recorded batch is traced again,
// in blocks of 1,024 rays as a worker's batch is, three ways:
//   single:   one Backend::intersect / occluded call per ray;
//   scattered: the batch call with RayCoherence::kIncoherent, what the integrator asks for past the
//             camera (embree: rtcIntersect1 per ray in scenes with triangles, packets of eight in
//             scenes of spheres alone; native: packets of eight where the CPU has AVX2);
//   coherent: the batch call with RayCoherence::kCoherent, what camera rays get (embree: its stream
//             API, packets of eight in its own layout; native: packets of eight).
// One thread, so the rates are a core's. Scenes: $RTPRO_BENCH_SCENES (colon separated), by default
// benchmarks/embree/cornell_box.yaml (Embree's own pathtracer scene) and scenes/cornell_box.gltf;
// $RTPRO_BENCH_SIZE=WxH sets the frame (default 512x512). `benchmarks/path_bounce_benchmark.sh`
// prints the table.
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/render/camera.h"
#include "camera_samplers.h"
#include "path_integrator.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace rtpro;

// The batches a path-traced frame hands its backend, in order; forwards every query.
class RecordingBackend final : public Backend {
 public:
  explicit RecordingBackend(const Backend& inner) : inner_(inner) {}
  std::string_view name() const override { return inner_.name(); }
  bool intersect(const Ray& ray, Hit& hit) const override { return inner_.intersect(ray, hit); }
  bool occluded(const Ray& ray) const override { return inner_.occluded(ray); }
  void intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence coherence) const override {
    bounce_rays.emplace_back(rays.begin(), rays.end());
    inner_.intersect(rays, hits, coherence);
  }
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> result, RayCoherence coherence) const override {
    shadow_rays.emplace_back(rays.begin(), rays.end());
    inner_.occluded(rays, result, coherence);
  }
  BackendStats stats() const override { return inner_.stats(); }

  mutable std::vector<std::vector<Ray>> bounce_rays, shadow_rays;  // per generation

 private:
  const Backend& inner_;
};

struct Frame {
  std::string scene_name;
  BackendKind kind;
  std::shared_ptr<const RenderScene> scene;
  std::shared_ptr<const Backend> backend;
  std::vector<std::vector<Ray>> bounce_rays, shadow_rays;
};

std::vector<std::filesystem::path> benchmark_scenes() {
  std::vector<std::filesystem::path> scenes;
  const std::filesystem::path root(RTPRO_SOURCE_DIR);
  const char* list = std::getenv("RTPRO_BENCH_SCENES");
  if (!list) return {root / "benchmarks/embree/cornell_box.yaml", root / "scenes/cornell_box.gltf"};
  std::stringstream stream(list);
  for (std::string item; std::getline(stream, item, ':');)
    if (!item.empty()) scenes.emplace_back(item);
  return scenes;
}

// The frame's rays at 1 spp, traced as one batch of every pixel's camera ray.
Frame record_frame(const std::string& name, std::shared_ptr<const RenderScene> scene, BackendKind kind) {
  Frame frame{name, kind, scene, make_backend(kind, *scene, {}), {}, {}};
  const RenderCamera& camera = scene->camera;
  const CameraSamplers samplers(scene->render);
  const SobolSampler& sampler = samplers.sobol();
  std::vector<Ray> camera_rays;
  std::vector<SampleKey> keys;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const std::uint64_t pixel = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(camera.width) + x;
      const PixelOffset offset = sampler.pixel_offset(pixel, 0);
      camera_rays.push_back(
          camera_ray(camera, static_cast<float>(x) + offset.x, static_cast<float>(y) + offset.y, {0.5f, 0.5f}));
      keys.push_back({pixel, 0});
    }
  std::vector<SampleResult> results(camera_rays.size());
  RayCounts counts;
  PathIntegrator::Workspace workspace;
  const RecordingBackend recorder(*frame.backend);
  const PathIntegrator integrator(*scene, recorder, samplers, nullptr, nullptr);
  set_tracing_fp_mode();
  integrator.trace({camera_rays, keys, results}, counts, workspace);
  frame.bounce_rays = std::move(recorder.bounce_rays);
  frame.shadow_rays = std::move(recorder.shadow_rays);
  return frame;
}

constexpr std::size_t kBlock = 1024;

enum class Mode { kSingle, kScattered, kCoherent };

void trace_bounce(benchmark::State& state, const Frame* frame, std::size_t generation, bool shadow, Mode mode) {
  const std::vector<Ray>& rays = (shadow ? frame->shadow_rays : frame->bounce_rays)[generation];
  const Backend& backend = *frame->backend;
  std::vector<Hit> hits(kBlock);
  std::vector<std::uint8_t> occluded(kBlock);
  set_tracing_fp_mode();
  for (auto _ : state) {
    for (std::size_t start = 0; start < rays.size(); start += kBlock) {
      const std::span<const Ray> block = std::span(rays).subspan(start, std::min(kBlock, rays.size() - start));
      switch (mode) {
        case Mode::kSingle:
          for (std::size_t i = 0; i < block.size(); ++i) {
            if (shadow) occluded[i] = backend.occluded(block[i]) ? 1 : 0;
            else if (!backend.intersect(block[i], hits[i])) hits[i] = Hit{};
          }
          break;
        case Mode::kScattered:
        case Mode::kCoherent: {
          const RayCoherence coherence = mode == Mode::kCoherent ? RayCoherence::kCoherent : RayCoherence::kIncoherent;
          if (shadow) backend.occluded(block, std::span(occluded).first(block.size()), coherence);
          else backend.intersect(block, std::span(hits).first(block.size()), coherence);
          break;
        }
      }
      benchmark::DoNotOptimize(hits.data());
      benchmark::DoNotOptimize(occluded.data());
    }
  }
  state.counters["rays"] = static_cast<double>(rays.size());
  state.counters["Mrays/s"] =
      benchmark::Counter(static_cast<double>(rays.size()) * state.iterations() * 1e-6, benchmark::Counter::kIsRate);
}

const char* mode_name(Mode mode) {
  switch (mode) {
    case Mode::kSingle: return "single";
    case Mode::kScattered: return "scattered";
    case Mode::kCoherent: return "coherent";
  }
  return "?";
}

std::vector<std::unique_ptr<Frame>>& frames() {
  static std::vector<std::unique_ptr<Frame>> recorded;
  return recorded;
}

void register_benchmarks() {
  for (const auto& file : benchmark_scenes()) {
    std::shared_ptr<const RenderScene> scene;
    try {
      std::vector<std::string> overrides{"render.spp=1", "render.integrator=path"};
      std::string size = std::getenv("RTPRO_BENCH_SIZE") ? std::getenv("RTPRO_BENCH_SIZE") : "512x512";
      size.replace(size.find('x'), 1, ",");
      overrides.push_back("camera.resolution=[" + size + "]");
      scene = std::make_shared<const RenderScene>(build_render_scene(parse_scene_file(file, overrides)));
    } catch (const std::exception& e) {
      std::cerr << "skipping " << file << ": " << e.what() << "\n";
      continue;
    }
    for (const BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
      // The file name with its extension: scenes/cornell_box.gltf and a cornell_box.yaml differ.
      frames().push_back(std::make_unique<Frame>(record_frame(file.filename().string(), scene, kind)));
      const Frame* frame = frames().back().get();
      for (std::size_t g = 0; g < frame->bounce_rays.size(); ++g)
        for (const bool shadow : {false, true}) {
          if (shadow && (g >= frame->shadow_rays.size() || frame->shadow_rays[g].empty())) continue;
          if (!shadow && frame->bounce_rays[g].empty()) continue;
          for (const Mode mode : {Mode::kSingle, Mode::kScattered, Mode::kCoherent}) {
            const std::string name = frame->scene_name + "/" + std::string(backend_name(kind)) + "/" +
                                     (shadow ? "shadow" : "bounce") + std::to_string(g) + "/" + mode_name(mode);
            benchmark::RegisterBenchmark(name.c_str(), trace_bounce, frame, g, shadow, mode)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
          }
        }
    }
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
