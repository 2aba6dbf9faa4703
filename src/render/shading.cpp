#include "rtpro/render/shading.h"

#include "rtpro/render/light_sample.h"
#include "rtpro/render/ray_offset.h"
#include "rtpro/render/surface.h"

#include <cmath>

namespace rtpro {

namespace {

// Light reflected directly towards the viewer at one surface point (no mirror term).
Color direct_light(const RenderScene& scene, const Backend& backend, const SurfacePoint& sp, const Material& m,
                   const Vec3& mirror_direction, RayCounts& counts) {
  Color result = m.color * scene.render.ambient;
  for (const LightDesc& light : scene.lights) {
    const LightSample ls = sample_light(light, sp.position);
    const float n_dot_l = dot(sp.shading_normal, ls.direction);
    // Lights behind the surface (by either normal) contribute nothing and need no shadow ray.
    if (n_dot_l <= 0.0f || dot(sp.geometric_normal, ls.direction) <= 0.0f) continue;
    const Ray shadow = std::isinf(ls.distance) ? spawn_ray(sp, ls.direction)
                                               : spawn_ray_to(sp, sp.position + ls.direction * ls.distance);
    ++counts.shadow;
    if (backend.occluded(shadow)) continue;
    result += m.color * ls.radiance * n_dot_l;
    const float r_dot_l = dot(mirror_direction, ls.direction);
    if (r_dot_l > 0.0f && m.specular > 0.0f) result += ls.radiance * (m.specular * std::pow(r_dot_l, m.shininess));
  }
  return result;
}

}  // namespace

Color trace_radiance(const RenderScene& scene, const Backend& backend, const Ray& camera_ray, RayCounts& counts,
                     PrimaryHit* primary) {
  Hit hit;
  const bool found = backend.intersect(camera_ray, hit);
  return trace_radiance_from(scene, backend, camera_ray, found, hit, counts, primary);
}

Color trace_radiance_from(const RenderScene& scene, const Backend& backend, const Ray& camera_ray,
                          bool camera_hit_found, const Hit& camera_hit, RayCounts& counts, PrimaryHit* primary) {
  Color result(0.0f);
  Color weight(1.0f);
  Ray ray = camera_ray;
  for (int depth = 0;; ++depth) {
    Hit hit = camera_hit;
    ++(depth == 0 ? counts.camera : counts.reflection);
    const bool found = depth == 0 ? camera_hit_found : backend.intersect(ray, hit);
    if (!found) {
      result += weight * scene.render.background;
      break;
    }
    const SurfacePoint sp = make_surface(scene, ray, hit);
    const Material& m = scene.materials[sp.material];
    const Vec3 mirror = reflect(normalize(ray.dir), sp.shading_normal);
    if (depth == 0 && primary) *primary = {true, m.color, sp.shading_normal, hit.t * length(ray.dir), sp.object_id};

    result += weight * direct_light(scene, backend, sp, m, mirror, counts);
    // A shading normal can tilt the mirror direction below the surface: nothing to reflect then.
    if (depth >= scene.render.max_depth || m.reflectivity <= 0.0f || dot(mirror, sp.geometric_normal) <= 0.0f) break;
    weight = weight * m.reflectivity;
    ray = spawn_ray(sp, mirror);
  }
  return result;
}

}  // namespace rtpro
