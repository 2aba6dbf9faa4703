#include "rtpro/render/light_sample.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

namespace rtpro {

namespace {

// An orthonormal frame around unit `w` (Duff et al. 2017, branch-free).
void frame_around(const Vec3& w, Vec3& t1, Vec3& t2) {
  const float sign = std::copysign(1.0f, w.z);
  const float a = -1.0f / (sign + w.z);
  const float b = w.x * w.y * a;
  t1 = Vec3(1.0f + sign * w.x * w.x * a, sign * b, -sign * w.x);
  t2 = Vec3(b, sign + w.y * w.y * a, -w.y);
}

}  // namespace

// Uniform over the cone of directions the sphere fills: every sample sees the light's radiance
// over the cone's solid angle 2π(1 − cos θmax).
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
  frame_around(w, t1, t2);
  const Vec3 direction = normalize(t1 * (std::cos(phi) * sin_theta) + t2 * (std::sin(phi) * sin_theta) + w * cos_theta);
  // The near intersection with the sphere along the sampled direction.
  const float b = d * cos_theta;
  const float distance = b - std::sqrt(std::max(0.0f, r2 - d2 * sin_theta * sin_theta));
  const float solid_angle = 2.0f * std::numbers::pi_v<float> * one_minus_cos_max;
  return {direction, distance, light.radiance * solid_angle};
}

// Uniform over the area: a point seen at distance d and cosine cos_l stands for area·cos_l/d² of
// solid angle.
LightSample sample_light_of_kind(const QuadLight& light, const Vec3& point, Sample2D u) {
  const Vec3 on_light = light.corner + light.edge1 * u.x + light.edge2 * u.y;
  const Vec3 to_light = on_light - point;
  const float d2 = dot(to_light, to_light);
  const float distance = std::sqrt(d2);
  if (!(distance > 0.0f)) return {Vec3(0.0f, 1.0f, 0.0f), 0.0f, Color(0.0f)};
  const Vec3 direction = to_light / distance;
  const float cos_light = -dot(light.normal, direction);
  if (!(cos_light > 0.0f)) return {direction, distance, Color(0.0f)};
  return {direction, distance, light.radiance * (cos_light * light.area / d2)};
}

namespace {

int per_axis(const PointLight&) { return 1; }
int per_axis(const SpotLight&) { return 1; }
int per_axis(const DirectionalLight&) { return 1; }
int per_axis(const SphereLight& light) { return light.samples_per_axis; }
int per_axis(const QuadLight& light) { return light.samples_per_axis; }

std::optional<float> hit(const PointLight&, const Ray&, float) { return std::nullopt; }
std::optional<float> hit(const SpotLight&, const Ray&, float) { return std::nullopt; }
std::optional<float> hit(const DirectionalLight&, const Ray&, float) { return std::nullopt; }

std::optional<float> hit(const SphereLight& light, const Ray& ray, float t_max) {
  const Vec3 oc = ray.org - light.center;
  const float a = dot(ray.dir, ray.dir);
  const float b = dot(oc, ray.dir);
  const float c = dot(oc, oc) - light.radius * light.radius;
  const float discriminant = b * b - a * c;
  if (!(discriminant >= 0.0f)) return std::nullopt;
  const float root = std::sqrt(discriminant);
  // The nearer root first, in the numerically stable form; the far one from inside the light.
  const float q = b >= 0.0f ? -(b + root) : -(b - root);
  float t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  for (const float t : {t0, t1})
    if (t > ray.tnear && t < t_max) return t;
  return std::nullopt;
}

std::optional<float> hit(const QuadLight& light, const Ray& ray, float t_max) {
  const float facing = dot(light.normal, ray.dir);
  if (!(facing < 0.0f)) return std::nullopt;  // seen from behind or edge-on: it emits on one side only
  const float t = dot(light.normal, light.corner - ray.org) / facing;
  if (!(t > ray.tnear && t < t_max)) return std::nullopt;
  const Vec3 q = ray.at(t) - light.corner;
  const Vec3 n = light.normal * light.area;  // edge1 × edge2
  const float inv = 1.0f / dot(n, n);
  const float alpha = dot(cross(q, light.edge2), n) * inv;
  const float beta = dot(cross(light.edge1, q), n) * inv;
  if (!(alpha >= 0.0f && alpha <= 1.0f && beta >= 0.0f && beta <= 1.0f)) return std::nullopt;
  return t;
}

Color emission(const PointLight&) { return Color(0.0f); }
Color emission(const SpotLight&) { return Color(0.0f); }
Color emission(const DirectionalLight&) { return Color(0.0f); }
Color emission(const SphereLight& light) { return light.radiance; }
Color emission(const QuadLight& light) { return light.radiance; }

}  // namespace

int light_samples_per_axis(const Light& light) {
  return std::visit([](const auto& l) { return per_axis(l); }, light);
}

std::optional<float> hit_light(const Light& light, const Ray& ray, float t_max) {
  return std::visit([&](const auto& l) { return hit(l, ray, t_max); }, light);
}

Color light_emission(const Light& light) {
  return std::visit([](const auto& l) { return emission(l); }, light);
}

}  // namespace rtpro
