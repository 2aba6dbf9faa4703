#include "dielectric.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

float fresnel_dielectric(float cos_incident, float eta) {
  const float cos_i = std::clamp(cos_incident, 0.0f, 1.0f);
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  const float r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const float r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, float eta) {
  const float cos_i = std::clamp(-dot(incident, normal), 0.0f, 1.0f);
  const float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return std::nullopt;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  return incident / eta + normal * (cos_i / eta - cos_t);
}

}  // namespace rtpro
