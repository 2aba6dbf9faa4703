// Loading the 10,000-sphere scene file (scenes/many_spheres.yaml), the load phase of
// `rtpro render`: parsing the YAML into a scene description, and building the render scene from
// it. POV-Ray's parse time for the same scene is measured by benchmarks/povray_benchmark.sh.
// Run with --benchmark_repetitions=10 for medians on a shared machine.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

namespace {

std::filesystem::path scene_file() {
  const char* source = std::getenv("RTPRO_SOURCE_DIR");
  return std::filesystem::path(source ? source : RTPRO_SOURCE_DIR) / "scenes" / "many_spheres.yaml";
}

void BM_ParseManySpheres(benchmark::State& state) {
  const auto file = scene_file();
  for (auto _ : state) benchmark::DoNotOptimize(rtpro::parse_scene_file(file));
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(std::filesystem::file_size(file)));
}
BENCHMARK(BM_ParseManySpheres)->Unit(benchmark::kMillisecond);

void BM_BuildRenderSceneManySpheres(benchmark::State& state) {
  const rtpro::SceneDescription description = rtpro::parse_scene_file(scene_file());
  for (auto _ : state) benchmark::DoNotOptimize(rtpro::build_render_scene(description));
}
BENCHMARK(BM_BuildRenderSceneManySpheres)->Unit(benchmark::kMillisecond);

// The whole load phase, as `rtpro render` does it.
void BM_LoadManySpheres(benchmark::State& state) {
  const auto file = scene_file();
  for (auto _ : state) benchmark::DoNotOptimize(rtpro::build_render_scene(rtpro::parse_scene_file(file)));
}
BENCHMARK(BM_LoadManySpheres)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
