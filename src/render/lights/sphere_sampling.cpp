#include "sphere_sampling.h"

#include "rtpro/core/math_constants.h"
#include "shading_frame.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

float one_minus_cos_cone(float d2, float r2) {
  const float sin2_max = r2 / d2;
  const float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2_max));
  return sin2_max / (1.0f + cos_max);  // 1 − cos θmax without cancellation for small spheres
}

}  // namespace

bool clearly_outside(const Vec3& center, float radius, const Vec3& point) {
  const Vec3 d = point - center;
  return dot(d, d) > radius * radius * 1.0001f;
}

float area_to_solid_angle(float area_pdf, const Vec3& from, const Vec3& on_light, const Vec3& n) {
  const Vec3 d = on_light - from;
  const float d2 = dot(d, d);
  const float cos_light = std::fabs(dot(n, d)) / std::sqrt(d2);
  return cos_light > 0.0f ? area_pdf * d2 / cos_light : 0.0f;
}

SphereSample sample_sphere(const Vec3& center, float radius, const Vec3& from, Sample2D u) {
  if (clearly_outside(center, radius, from)) {
    const Vec3 to_center = center - from;
    const float d2 = dot(to_center, to_center), r2 = radius * radius;
    const float d = std::sqrt(d2);
    const float one_minus_cos_max = one_minus_cos_cone(d2, r2);
    const float one_minus_cos = u.x * one_minus_cos_max;
    const float cos_theta = 1.0f - one_minus_cos;
    const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
    const float phi = 2.0f * kPi * u.y;
    const Vec3 w = to_center / d;
    const ShadingFrame frame = ShadingFrame::from_normal(w);
    const Vec3 direction =
        normalize(frame.s * (std::cos(phi) * sin_theta) + frame.t * (std::sin(phi) * sin_theta) + w * cos_theta);
    const float b = d * cos_theta;
    const float distance = b - std::sqrt(std::max(0.0f, r2 - d2 * sin_theta * sin_theta));
    const Vec3 point = from + direction * distance;
    return {point, normalize(point - center), 1.0f / (2.0f * kPi * one_minus_cos_max)};
  }
  const float z = 1.0f - 2.0f * u.x;
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 2.0f * kPi * u.y;
  const Vec3 normal(r * std::cos(phi), r * std::sin(phi), z);
  const Vec3 point = center + normal * radius;
  return {point, normal, area_to_solid_angle(1.0f / (4.0f * kPi * radius * radius), from, point, normal)};
}

float sphere_pdf(const Vec3& center, float radius, const Vec3& from, const Vec3& on_light) {
  if (clearly_outside(center, radius, from)) {
    const Vec3 to_center = center - from;
    return 1.0f / (2.0f * kPi * one_minus_cos_cone(dot(to_center, to_center), radius * radius));
  }
  return area_to_solid_angle(1.0f / (4.0f * kPi * radius * radius), from, on_light, normalize(on_light - center));
}

}  // namespace rtpro
