#pragma once
// Exact (unpolarised) Fresnel reflectance of a smooth dielectric interface and Snell refraction.
// `eta` is always the ratio n_transmitted / n_incident, so one function serves entering and
// leaving a medium: the caller decides which from the geometric normal.
#include "rtpro/core/vec3.h"

#include <optional>

namespace rtpro {

// Fraction of light reflected for a ray meeting the interface at cos_incident (>= 0, measured to
// the normal on the incident side); 1 under total internal reflection.
float fresnel_dielectric(float cos_incident, float eta);

// Direction of the refracted ray for unit `incident` travelling towards the surface and unit
// `normal` on the incident side; nothing under total internal reflection.
std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, float eta);

// In a BSDF's local frame (+z the outside normal), with `eta` = n_inside / n_outside:
// the ratio n_wi / n_wo for a transmission starting on wo's side,
inline float relative_eta(const Vec3& wo, float eta) { return wo.z > 0.0f ? eta : 1.0f / eta; }

// and wo refracted through the facet with normal wm (either orientation), or nothing under total
// internal reflection.
inline std::optional<Vec3> refract_through(const Vec3& wo, const Vec3& wm, float eta) {
  const bool from_outside = dot(wo, wm) > 0.0f;
  return refract(-wo, from_outside ? wm : -wm, from_outside ? eta : 1.0f / eta);
}

}  // namespace rtpro
