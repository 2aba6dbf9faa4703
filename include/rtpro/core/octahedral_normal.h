#pragma once
// Unit vectors in 32 bits: the octahedral map (Cigolle et al., "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 2014) with 16 bits per coordinate. The
// encoder picks, of the four codes around the exact point, the one that decodes closest to the
// vector: the largest angle between a unit vector and its decoded code is below 5e-5 radians (0.003°)
// (tests/core/octahedral_normal_test.cpp), far under what a shading normal can show.
#include "rtpro/core/vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rtpro {

namespace octahedral_detail {

inline float sign_not_zero(float v) { return v < 0.0f ? -1.0f : 1.0f; }

inline float from_snorm16(std::uint32_t bits) {
  const auto s = static_cast<std::int16_t>(static_cast<std::uint16_t>(bits));
  return std::max(static_cast<float>(s) / 32767.0f, -1.0f);
}

inline std::uint32_t snorm16_bits(int value) {
  return static_cast<std::uint16_t>(static_cast<std::int16_t>(std::min(std::max(value, -32767), 32767)));
}

inline Vec3 decode_xy(float x, float y) {
  Vec3 n(x, y, 1.0f - std::fabs(x) - std::fabs(y));
  if (n.z < 0.0f) {
    n.x = (1.0f - std::fabs(y)) * sign_not_zero(x);
    n.y = (1.0f - std::fabs(x)) * sign_not_zero(y);
  }
  return normalize(n);
}

}  // namespace octahedral_detail

inline Vec3 decode_octahedral(std::uint32_t code) {
  using namespace octahedral_detail;
  return decode_xy(from_snorm16(code & 0xFFFFu), from_snorm16(code >> 16));
}

// `n` must be of unit length (within float rounding).
inline std::uint32_t encode_octahedral(const Vec3& n) {
  using namespace octahedral_detail;
  const float l1 = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
  float x = n.x / l1, y = n.y / l1;
  if (n.z < 0.0f) {
    const float fx = (1.0f - std::fabs(y)) * sign_not_zero(x);
    const float fy = (1.0f - std::fabs(x)) * sign_not_zero(y);
    x = fx;
    y = fy;
  }
  const int sx = static_cast<int>(std::floor(std::min(std::max(x, -1.0f), 1.0f) * 32767.0f));
  const int sy = static_cast<int>(std::floor(std::min(std::max(y, -1.0f), 1.0f) * 32767.0f));
  // The candidates' cosines differ by about 1e-9, below float's resolution and below the ~1e-7 by
  // which a decoded vector's length misses 1: compared in double, each over its own length.
  std::uint32_t best = 0;
  double best_dot = -2.0;
  for (int dx = 0; dx <= 1; ++dx)
    for (int dy = 0; dy <= 1; ++dy) {
      const std::uint32_t code = snorm16_bits(sx + dx) | (snorm16_bits(sy + dy) << 16);
      const Vec3 m = decode_octahedral(code);
      const double d = (double(m.x) * double(n.x) + double(m.y) * double(n.y) + double(m.z) * double(n.z)) /
                       std::sqrt(double(m.x) * double(m.x) + double(m.y) * double(m.y) + double(m.z) * double(m.z));
      if (d > best_dot) {
        best_dot = d;
        best = code;
      }
    }
  return best;
}

}  // namespace rtpro
