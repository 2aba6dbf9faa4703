// The environment light made ready to sample: a 4096×2048 latitude-longitude image (the size of a
// production HDRI) turned into texels and its sampling distribution, at 1 and 2 threads, with the
// bytes it holds against the float RGB image it came from. Synthetic pixels (a sky gradient, a
// sun, noise), so the figure does not wait on an EXR decode.
#include "rtpro/render/environment_light.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>

namespace {

rtpro::Image sky(int width, int height) {
  rtpro::Image image(width, height);
  std::uint32_t state = 12345;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      state = state * 1664525u + 1013904223u;
      const float noise = static_cast<float>(state >> 8) * 0x1p-24f;
      const float sky = 0.2f + 0.8f * float(height - y) / height;
      const bool sun = std::abs(x - width * 3 / 5) < 4 && std::abs(y - height / 2 + 20) < 4;
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
    const rtpro::EnvironmentLight light(environment, std::move(copy));
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

}  // namespace

BENCHMARK_MAIN();
