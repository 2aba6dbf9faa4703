#pragma once
// A scatter of small lights of every kind of bounds through a 20 × 10 × 20 room: points (a sphere
// of normals), one-sided quads facing random ways and two-sided triangles, their powers over three
// decades, and, where asked, every fourth a light without a position. The light tree's tests and
// its benchmark (benchmarks/light_tree_benchmark.cpp) draw from it. `random` gives next() in
// [0, 1) and next_direction().
#include "light_tree.h"

#include <cmath>
#include <optional>
#include <vector>

namespace rtpro::test {

template <class Random>
std::vector<std::optional<LightBounds>> scattered_lights(int count, Random& random, bool with_positionless) {
  std::vector<std::optional<LightBounds>> lights;
  const int kinds = with_positionless ? 4 : 3;
  for (int i = 0; i < count; ++i) {
    const Vec3 center(20.0f * random.next() - 10.0f, 10.0f * random.next(), 20.0f * random.next() - 10.0f);
    const float size = 0.05f + 0.5f * random.next();
    BBox box;
    box.extend(center - Vec3(size));
    box.extend(center + Vec3(size));
    const float power = std::pow(10.0f, 3.0f * random.next());
    switch (i % kinds) {
      case 0: lights.push_back(LightBounds{box, Vec3(0, 0, 1), power, -1.0f, 0.0f, false}); break;
      case 1: lights.push_back(LightBounds{box, random.next_direction(), power, 1.0f, 0.0f, false}); break;
      case 2: lights.push_back(LightBounds{box, random.next_direction(), power, 1.0f, 0.0f, true}); break;
      default: lights.push_back(std::nullopt); break;  // a light without a position
    }
  }
  return lights;
}

}  // namespace rtpro::test
