// The light tree's pick and pmf at a shading point, as the path integrator asks for them at every
// vertex: over the two triangles of a Cornell box's ceiling light, and over 64 and 4,096 lights
// scattered through a room (one-sided quads facing random ways, points, two-sided triangles).
// The points are random in the room, so the walk takes different branches from call to call.
#include "light_tree.h"
#include "render/scattered_lights.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace {

using rtpro::BBox;
using rtpro::LightBounds;
using rtpro::LightTree;
using rtpro::Vec3;

struct Uniforms {
  std::uint32_t state;
  float next() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) * 0x1p-24f;
  }
  Vec3 next_direction() {
    const float z = 2.0f * next() - 1.0f, phi = 6.2831853f * next();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
};

std::vector<std::optional<LightBounds>> ceiling_light() {
  // Two triangles of the 130 × 105 mm quad below a 549 mm ceiling, facing down.
  std::vector<std::optional<LightBounds>> lights;
  for (int i = 0; i < 2; ++i) {
    BBox box;
    box.extend(Vec3(213.0f, 548.7f, 227.0f));
    box.extend(Vec3(343.0f, 548.7f, 332.0f));
    lights.push_back(LightBounds{box, Vec3(0.0f, -1.0f, 0.0f), 4.0e5f, 1.0f, 0.0f, false});
  }
  return lights;
}

std::vector<std::optional<LightBounds>> scattered_lights(int count) {
  Uniforms u{7};
  return rtpro::test::scattered_lights(count, u, false);
}

std::vector<std::optional<LightBounds>> lights_for(std::int64_t count) {
  return count == 2 ? ceiling_light() : scattered_lights(static_cast<int>(count));
}

// Points in the lights' room (the ceiling light's: the Cornell box in millimetres).
std::vector<Vec3> shading_points(std::int64_t count) {
  const float scale = count == 2 ? 550.0f : 20.0f, lift = count == 2 ? 0.0f : 10.0f;
  Uniforms u{11};
  std::vector<Vec3> points(1024);
  for (Vec3& p : points) p = Vec3(scale * u.next() - lift, scale * u.next() * 0.5f, scale * u.next() - lift);
  return points;
}

void BM_LightTreeSample(benchmark::State& state) {
  const LightTree tree(lights_for(state.range(0)));
  const std::vector<Vec3> points = shading_points(state.range(0));
  Uniforms u{3};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.sample(points[i++ % points.size()], u.next()));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightTreeSample)->Arg(2)->Arg(64)->Arg(4096);

void BM_LightTreePmf(benchmark::State& state) {
  const auto lights = lights_for(state.range(0));
  const LightTree tree(lights);
  const std::vector<Vec3> points = shading_points(state.range(0));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tree.pmf(points[i % points.size()], static_cast<std::uint32_t>(i % lights.size())));
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LightTreePmf)->Arg(2)->Arg(64)->Arg(4096);

}  // namespace

BENCHMARK_MAIN();
