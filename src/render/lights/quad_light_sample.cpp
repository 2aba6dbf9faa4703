#include "quad_light_sample.h"

#include <cmath>

namespace rtpro {

// A point seen at distance d and cosine cos_l stands for area·cos_l/d² of solid angle.
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

float hit_light_of_kind(const QuadLight& light, const Ray& ray, float t_max) {
  const float facing = dot(light.normal, ray.dir);
  if (!(facing < 0.0f)) return kLightMissed;  // seen from behind or edge-on: it emits on one side only
  const float t = dot(light.normal, light.corner - ray.org) / facing;
  if (!(t > ray.tnear && t < t_max)) return kLightMissed;
  const Vec3 q = ray.at(t) - light.corner;
  const Vec3 n = light.normal * light.area;  // edge1 × edge2
  const float inv = 1.0f / dot(n, n);
  const float alpha = dot(cross(q, light.edge2), n) * inv;
  const float beta = dot(cross(light.edge1, q), n) * inv;
  if (!(alpha >= 0.0f && alpha <= 1.0f && beta >= 0.0f && beta <= 1.0f)) return kLightMissed;
  return t;
}

}  // namespace rtpro
