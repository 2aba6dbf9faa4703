#include "sphere_light_sample.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace rtpro {

namespace {

// An orthonormal frame around unit `w` (Duff et al. 2017, branch-free).
void sphere_light_frame_around(const Vec3& w, Vec3& t1, Vec3& t2) {
  const float sign = std::copysign(1.0f, w.z);
  const float a = -1.0f / (sign + w.z);
  const float b = w.x * w.y * a;
  t1 = Vec3(1.0f + sign * w.x * w.x * a, sign * b, -sign * w.x);
  t2 = Vec3(b, sign + w.y * w.y * a, -w.y);
}

}  // namespace

// Every sample sees the light's radiance over the cone's solid angle 2π(1 − cos θmax).
LightSample sample_light_of_kind(const SphereLight& light, const Vec3& point, Sample2D u) {
  const Vec3 to_center = light.center - point;
  const float d2 = dot(to_center, to_center);
  const float r2 = light.radius * light.radius;
  if (!(d2 > r2)) return {Vec3(0.0f, 1.0f, 0.0f), 0.0f, Color(0.0f)};
  const float d = std::sqrt(d2);
  const float sin2_max = r2 / d2;
  const float cos_max = std::sqrt(std::max(0.0f, 1.0f - sin2_max));
  const float one_minus_cos_max = sin2_max / (1.0f + cos_max);  // without cancellation for small lights
  const float one_minus_cos = u.x * one_minus_cos_max;
  const float cos_theta = 1.0f - one_minus_cos;
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  const float phi = 2.0f * std::numbers::pi_v<float> * u.y;
  const Vec3 w = to_center / d;
  Vec3 t1, t2;
  sphere_light_frame_around(w, t1, t2);
  const Vec3 direction = normalize(t1 * (std::cos(phi) * sin_theta) + t2 * (std::sin(phi) * sin_theta) + w * cos_theta);
  // The near intersection with the sphere along the sampled direction.
  const float b = d * cos_theta;
  const float distance = b - std::sqrt(std::max(0.0f, r2 - d2 * sin_theta * sin_theta));
  const float solid_angle = 2.0f * std::numbers::pi_v<float> * one_minus_cos_max;
  return {direction, distance, light.radiance * solid_angle};
}

float hit_light_of_kind(const SphereLight& light, const Ray& ray, float t_max) {
  const Vec3 oc = ray.org - light.center;
  const float a = dot(ray.dir, ray.dir);
  const float b = dot(oc, ray.dir);
  const float c = dot(oc, oc) - light.radius * light.radius;
  const float discriminant = b * b - a * c;
  if (!(discriminant >= 0.0f)) return kLightMissed;
  const float root = std::sqrt(discriminant);
  // The nearer root first, in the numerically stable form; the far one from inside the light.
  const float q = b >= 0.0f ? -(b + root) : -(b - root);
  float t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  for (const float t : {t0, t1})
    if (t > ray.tnear && t < t_max) return t;
  return kLightMissed;
}

}  // namespace rtpro
