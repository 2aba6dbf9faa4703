#pragma once
// What every BSDF kind returns when it samples, and the shading-frame helpers they share.
// Conventions (pbrt-v4's): directions are in the local shading frame (normal +z), unit, and point
// away from the surface: wo towards the viewer, wi towards the light.
#include "rtpro/core/vec3.h"
#include "rtpro/render/sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace rtpro {

// The kind of lobe a sample took, as Cycles counts a path's bounces against its per-kind limits:
// diffuse (Lambert, sheen), glossy (reflection off a microfacet or mirror lobe, a rough metal's
// multiple-scattering lobe included) and transmission (refraction, rough or smooth). A subsurface
// sample enters the surface for a random walk under it (render/integrators/subsurface_walk.h): its
// f·|cos θi|/pdf is the walk's starting weight, its wi the inward normal.
enum class BsdfLobe : std::uint8_t { kDiffuse, kGlossy, kTransmission, kSubsurface };

struct BsdfSample {
  // The BSDF value without the cosine. For a delta lobe it is (lobe weight) / |cos θi|, so that
  // f·|cos θi| / pdf is the path throughput factor either way.
  Color f;
  Vec3 wi;
  // Per unit solid angle of wi; for a delta lobe the probability of having chosen that lobe.
  float pdf;
  bool delta;
  bool transmitted;  // wi is on the other side of the surface from wo
  BsdfLobe lobe;
  // For a refraction, η of the side wi leaves into over η of the side wo is on (pbrt-v4's
  // BSDFSample::eta): f carries the radiance scale 1/η², which the path integrator takes out of
  // the throughput its Russian roulette reads. 1 for every other sample.
  float eta = 1.0f;
};

// The largest float below 1, where a random number rescaled after a choice must stay.
inline constexpr float kOneMinusEpsilon = 1.0f - 0x1p-24f;
// A colour's channels averaged: the weight of a coloured lobe when one number picks among lobes.
inline float channel_mean(const Color& c) { return (c.x + c.y + c.z) / 3.0f; }

inline float cos_theta(const Vec3& w) { return w.z; }
inline float abs_cos_theta(const Vec3& w) { return std::fabs(w.z); }
inline bool same_hemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.0f; }

struct SineCosine {
  float sin, cos;
};

// sin θ and cos θ for |θ| <= π/4, the concentric mapping's range: Cephes' sinf/cosf polynomials
// (minimax on that interval, within 2 ulp of the exact values; tests/render/bsdf_sample_test.cpp),
// inline and without the range reduction that makes libm's sincosf a tenth of a Lambert sample.
inline SineCosine sine_cosine_within_quarter_turn(float theta) {
  const float z = theta * theta;
  const float sin = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * theta + theta;
  const float cos =
      ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
  return {sin, cos};
}

// Shirley and Chiu's concentric mapping: neighbouring samples stay neighbours on the disk, so
// stratification survives (a polar mapping squeezes the strata near the centre).
inline Sample2D sample_uniform_disk_concentric(Sample2D u) {
  const float x = 2.0f * u.x - 1.0f;
  const float y = 2.0f * u.y - 1.0f;
  if (x == 0.0f && y == 0.0f) return {0.0f, 0.0f};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
  if (std::fabs(x) > std::fabs(y)) {
    const SineCosine phi = sine_cosine_within_quarter_turn(kQuarterPi * (y / x));
    return {x * phi.cos, x * phi.sin};
  }
  // φ = π/2 − θ with θ = π/4 · x/y, so cos φ = sin θ and sin φ = cos θ.
  const SineCosine theta = sine_cosine_within_quarter_turn(kQuarterPi * (x / y));
  return {y * theta.sin, y * theta.cos};
}

inline Vec3 sample_cosine_hemisphere(Sample2D u) {
  const Sample2D d = sample_uniform_disk_concentric(u);
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

inline float cosine_hemisphere_pdf(float abs_cos_theta) { return abs_cos_theta * std::numbers::inv_pi_v<float>; }

}  // namespace rtpro
