#pragma once
// What every BSDF kind returns when it samples, and the shading-frame helpers they share.
// Conventions (pbrt-v4's): directions are in the local shading frame (normal +z), unit, and point
// away from the surface: wo towards the viewer, wi towards the light.
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rtpro {

struct BsdfSample {
  // The BSDF value without the cosine. For a delta lobe it is (lobe weight) / |cos θi|, so that
  // f·|cos θi| / pdf is the path throughput factor either way.
  Color f;
  Vec3 wi;
  // Per unit solid angle of wi; for a delta lobe the probability of having chosen that lobe.
  float pdf;
  bool delta;
  bool transmitted;  // wi is on the other side of the surface from wo
};

inline float cos_theta(const Vec3& w) { return w.z; }
inline float abs_cos_theta(const Vec3& w) { return std::fabs(w.z); }
inline bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.0f; }

// Shirley and Chiu's concentric mapping: neighbouring samples stay neighbours on the disk, so
// stratification survives (a polar mapping squeezes the strata near the centre).
inline Sample2D sample_uniform_disk_concentric(Sample2D u) {
  const float x = 2.0f * u.x - 1.0f;
  const float y = 2.0f * u.y - 1.0f;
  if (x == 0.0f && y == 0.0f) return {0.0f, 0.0f};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
  if (std::fabs(x) > std::fabs(y)) {
    const float phi = kQuarterPi * (y / x);
    return {x * std::cos(phi), x * std::sin(phi)};
  }
  const float phi = 2.0f * kQuarterPi - kQuarterPi * (x / y);
  return {y * std::cos(phi), y * std::sin(phi)};
}

// Malley's method: a uniform disk point lifted to the hemisphere is distributed as cos θ / π.
inline Vec3 sample_cosine_hemisphere(Sample2D u) {
  const Sample2D d = sample_uniform_disk_concentric(u);
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

inline float cosine_hemisphere_pdf(float abs_cos_theta) { return abs_cos_theta * std::numbers::inv_pi_v<float>; }

}  // namespace rtpro
