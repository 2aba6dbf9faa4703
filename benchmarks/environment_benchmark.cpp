// The environment light made ready to sample: a 4096×2048 latitude-longitude image (the size of a
// production HDRI) turned into texels and its sampling distribution, at 1 and 2 threads, with the
// bytes it holds against the float RGB image it came from; and its light samples, each with its
// radiance and pdf. Synthetic pixels (a sky gradient, a sun, noise), so the figure does not wait
// on an EXR decode.
#include "rtpro/render/environment_light.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>

namespace {

rtpro::Image sky(int width, int height, bool with_sun = true) {
  rtpro::Image image(width, height);
  std::uint32_t state = 12345;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      state = state * 1664525u + 1013904223u;
      const float noise = static_cast<float>(state >> 8) * 0x1p-24f;
      const float sky = 0.2f + 0.8f * float(height - y) / height;
      const bool sun = with_sun && std::abs(x - width * 3 / 5) < 4 && std::abs(y - height / 2 + 20) < 4;
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = sun ? 6500.0f : sky * (0.9f + 0.2f * noise) * (1.0f - 0.2f * c);
    }
  return image;
}

void BM_EnvironmentReady(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0)), threads = static_cast<int>(state.range(1));
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const rtpro::Image image = sky(width, width / 2);
  const rtpro::Environment environment{"sky.exr", rtpro::Color(1.0f), rtpro::Affine::identity(), true};
  std::size_t bytes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    rtpro::Image copy = image;
    state.ResumeTiming();
    const rtpro::EnvironmentLight light(environment, std::move(copy), rtpro::EnvironmentSampling::kWhole);
    bytes = light.bytes();
    benchmark::DoNotOptimize(light.mean_radiance());
  }
  const double image_bytes = static_cast<double>(image.data.size() * sizeof(float));
  state.counters["bytes_per_image_byte"] = static_cast<double>(bytes) / image_bytes;
  state.counters["MiB"] = static_cast<double>(bytes) / (1024.0 * 1024.0);
}
BENCHMARK(BM_EnvironmentReady)
    ->Args({4096, 1})
    ->Args({4096, 2})
    ->Args({1024, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Light samples of the environment, each with the radiance and pdf it carries: what a path vertex
// that picks the environment pays. Without a sun the samples spread over the whole image, so
// nearly every one reads texels and distribution entries from memory.
void BM_EnvironmentSample(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const bool with_sun = state.range(1) != 0;
  const rtpro::Environment environment{"sky.exr", rtpro::Color(1.0f), rtpro::Affine::identity(), true};
  const rtpro::EnvironmentLight light(environment, sky(width, width / 2, with_sun), rtpro::EnvironmentSampling::kWhole);
  std::uint64_t state_bits = 0x9e3779b97f4a7c15ull;
  const auto next = [&state_bits] {
    state_bits = state_bits * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<float>(state_bits >> 40) * 0x1p-24f;
  };
  float sum = 0.0f;
  for (auto _ : state) {
    const float u = next(), v = next();
    if (const auto sample = light.sample({u, v})) sum += sample->pdf + sample->radiance.x;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EnvironmentSample)->Args({1024, 0})->Args({1024, 1})->Args({4096, 0})->Args({128, 0});

}  // namespace

BENCHMARK_MAIN();
