#include "whitted_shadow_rays.h"

#include "rtpro/core/append_ray.h"
#include "point_light_lanes.h"
#include "rtpro/core/avx2_clones.h"
#include "light_linking.h"
#include "light_sample.h"
#include "ray_offset.h"
#include "whitted_light_units.h"

#include <cmath>
#include <variant>

namespace rtpro {

namespace {

using Workspace = ShadingWorkspace;

// The shadow ray and query of a one-sample light (point, spot or directional) for surface `s`,
// written to `ray` and `query`; false (both left unspecified) when there is none: the light is
// behind the surface by either normal, or a spot light's cone leaves it dark.
bool one_sample_shadow_ray(const Light& light, bool radiometric, const Workspace::ShadedSurface& s, Ray& ray,
                           Workspace::ShadowQuery& query) {
  const LightSample ls =
      in_whitted_units(light, sample_light(light, s.point.position, Sample2D{0.5f, 0.5f}), radiometric);
  if (is_black(ls.radiance)) return false;  // outside a spot light's cone
  const float n_dot_l = dot(s.point.shading_normal, ls.direction);
  if (n_dot_l <= 0.0f || dot(s.point.geometric_normal, ls.direction) <= 0.0f) return false;
  copy_ray(std::isinf(ls.distance) ? spawn_ray(s.point, ls.direction)
                                   : spawn_ray_to(s.point, s.point.position + ls.direction * ls.distance),
           ray);
  query = {ls.radiance, n_dot_l, dot(s.mirror, ls.direction)};
  return true;
}

// The shadow rays of light `l` for surface `s`: one for a point, spot or directional light, samples²
// for an area light (none for a light behind the surface, by either normal, or sending nothing).
void queue_light_shadow_rays(const RenderScene& scene, const StratifiedSampler& sampler, const SampleKey& key,
                             int depth, const Workspace::ShadedSurface& s, std::uint32_t l, Workspace& ws) {
  const Light& light = scene.lights[l];
  const bool radiometric = is_radiometric(scene);
  const int per_axis = ws.light_samples_per_axis[l];
  if (per_axis == 1 && !ws.is_emitter[l]) {
    if (!one_sample_shadow_ray(light, radiometric, s, ws.shadow_rays.emplace_back(),
                               ws.shadow_queries.emplace_back())) {
      ws.shadow_rays.pop_back();
      ws.shadow_queries.pop_back();
      return;
    }
    if (scene.links.linked()) ws.shadow_lights.push_back(l);
    return;
  }
  const int count = per_axis * per_axis;
  const float share = 1.0f / static_cast<float>(count);
  for (int j = 0; j < count; ++j) {
    const Sample2D u = sampler.light_sample(key.pixel_key, key.sample_index, depth, int(l), j, per_axis);
    const LightSample ls = in_whitted_units(light, sample_light(light, s.point.position, u), radiometric);
    if (is_black(ls.radiance)) continue;
    const float n_dot_l = dot(s.point.shading_normal, ls.direction);
    if (n_dot_l <= 0.0f || dot(s.point.geometric_normal, ls.direction) <= 0.0f) continue;
    append_ray(ws.shadow_rays, std::isinf(ls.distance)
                                   ? spawn_ray(s.point, ls.direction)
                                   : spawn_ray_to(s.point, s.point.position + ls.direction * ls.distance));
    ws.shadow_queries.push_back({ls.radiance * share, n_dot_l, dot(s.mirror, ls.direction)});
    if (scene.links.linked()) ws.shadow_lights.push_back(l);
  }
}

// Lights a batch of four surfaces takes through point_light_lanes at most (a scene with more
// takes the one-by-one path).
constexpr std::size_t kMaxLanedLights = 8;

}  // namespace

// Where every light is a point, spot or directional light (one ray a surface at most), the rays
// and queries are written in place at a cursor, an unneeded slot taken by the next one, and four
// surfaces at a time take each point light through point_light_lanes (the same rays, bit for bit;
// the other lights one surface at a time). Under light linking a surface takes only the lights
// that illuminate its object, one surface at a time.
RTPRO_AVX2_CLONES
void queue_shadow_rays(const RenderScene& scene, const StratifiedSampler& sampler, std::span<const SampleKey> keys,
                       const Workspace::GenerationView& generation, int depth, Workspace& ws) {
  const std::size_t light_count = scene.lights.size();
  const bool radiometric = is_radiometric(scene);
  bool laned = light_count <= kMaxLanedLights && !scene.links.linked() && !radiometric;
  for (std::size_t l = 0; l < light_count && laned; ++l) laned = ws.light_samples_per_axis[l] == 1 && !ws.is_emitter[l];
  if (!laned) {
    for (Workspace::ShadedSurface& s : ws.surfaces) {
      s.front_origin_known = false;
      s.first_shadow = static_cast<std::uint32_t>(ws.shadow_queries.size());
      const std::uint32_t group = link_group_of(scene.links, ws.hits[s.task]);
      for (std::uint32_t l = 0; l < light_count; ++l)
        if (scene.links.illuminates(group, l))
          queue_light_shadow_rays(scene, sampler, keys[generation.tasks[s.task].sample], depth, s, l, ws);
      s.end_shadow = static_cast<std::uint32_t>(ws.shadow_queries.size());
    }
    return;
  }
  ws.shadow_rays.resize(ws.surfaces.size() * light_count);
  ws.shadow_queries.resize(ws.shadow_rays.size());
  Ray* const rays = ws.shadow_rays.data();
  Workspace::ShadowQuery* const queries = ws.shadow_queries.data();
  std::uint32_t cursor = 0;
  PointLightLanes lanes[kMaxLanedLights];
  const PointLight* point_lights[kMaxLanedLights] = {};
  for (std::size_t l = 0; l < light_count; ++l) point_lights[l] = std::get_if<PointLight>(&scene.lights[l]);
  std::size_t i = 0;
  for (; i + 4 <= ws.surfaces.size(); i += 4) {
    const SurfacePoint* points[4];
    const Vec3* mirrors[4];
    for (int k = 0; k < 4; ++k) {
      points[k] = &ws.surfaces[i + k].point;
      mirrors[k] = &ws.surfaces[i + k].mirror;
    }
    Vec3 front_origins[4];
    point_light_lanes(std::span(point_lights, light_count), points, mirrors, lanes, front_origins);
    for (unsigned k = 0; k < 4; ++k) {
      Workspace::ShadedSurface& s = ws.surfaces[i + k];
      s.front_origin = front_origins[k];
      s.front_origin_known = true;
      s.first_shadow = cursor;
      for (std::uint32_t l = 0; l < light_count; ++l) {
        const PointLight* point = point_lights[l];
        if (!point || (lanes[l].infinite >> k & 1u)) {
          cursor += one_sample_shadow_ray(scene.lights[l], radiometric, s, rays[cursor], queries[cursor]);
          continue;
        }
        store_ray(lanes[l], k, rays[cursor]);
        queries[cursor] = {point->radiance, lanes[l].n_dot_l[k], lanes[l].r_dot_l[k]};
        cursor += lanes[l].lit >> k & 1u;
      }
      s.end_shadow = cursor;
    }
  }
  for (; i < ws.surfaces.size(); ++i) {
    Workspace::ShadedSurface& s = ws.surfaces[i];
    s.front_origin_known = false;
    s.first_shadow = cursor;
    for (std::uint32_t l = 0; l < light_count; ++l)
      cursor += one_sample_shadow_ray(scene.lights[l], radiometric, s, rays[cursor], queries[cursor]);
    s.end_shadow = cursor;
  }
  ws.shadow_rays.resize(cursor);
  ws.shadow_queries.resize(cursor);
}

}  // namespace rtpro
