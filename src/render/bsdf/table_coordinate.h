#pragma once
// Where a value in [0, 1] falls in a table whose nodes are spaced evenly in its square root: the
// layout of the directional-albedo tables (microfacet.cpp, specular_albedo.cpp, sheen.cpp), dense
// near 0 where albedos change fastest (grazing angles, smooth surfaces).
#include <algorithm>
#include <cmath>

namespace rtpro {

struct TableCoordinate {
  int index;       // the node below, at most nodes − 2
  float fraction;  // towards the node above
};

inline TableCoordinate sqrt_spaced_coordinate(float x, int nodes) {
  const float scaled = std::sqrt(std::clamp(x, 0.0f, 1.0f)) * static_cast<float>(nodes - 1);
  const int index = std::min(static_cast<int>(scaled), nodes - 2);
  return {index, scaled - static_cast<float>(index)};
}

// Linear interpolation between two table nodes, a at t = 0 and b at t = 1.
inline float table_lerp(float t, float a, float b) { return (1.0f - t) * a + t * b; }

}  // namespace rtpro
