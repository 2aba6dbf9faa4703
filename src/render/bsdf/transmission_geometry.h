#pragma once
// Walter et al.'s (2007) refraction geometry between two directions on opposite sides of a rough
// interface, in the local frame (+z the outside, η = n_inside / n_outside): the generalised half
// vector and the dot products the rough transmission's f and pdf are made of.
#include "bsdf_sample.h"
#include "dielectric.h"

#include <cmath>
#include <optional>

namespace rtpro {

struct TransmissionGeometry {
  Vec3 wm;  // the generalised half vector, facing +z
  float etap, wo_dot_wm, wi_dot_wm, denom;
};

// Nothing where no facet facing both directions refracts one into the other.
inline std::optional<TransmissionGeometry> transmission_geometry(const Vec3& wo, const Vec3& wi, float eta) {
  if (wo.z * wi.z >= 0.0f) return std::nullopt;
  const float etap = relative_eta(wo, eta);
  const Vec3 half = wi * etap + wo;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return std::nullopt;
  Vec3 wm = half / std::sqrt(half_length2);
  if (wm.z < 0.0f) wm = -wm;
  const float wo_dot_wm = dot(wo, wm), wi_dot_wm = dot(wi, wm);
  if (wi_dot_wm * wi.z < 0.0f || wo_dot_wm * wo.z < 0.0f) return std::nullopt;
  const float sum = wi_dot_wm + wo_dot_wm / etap;
  if (sum == 0.0f) return std::nullopt;
  return TransmissionGeometry{wm, etap, wo_dot_wm, wi_dot_wm, sum * sum};
}

}  // namespace rtpro
