#include "rtpro/render/shading.h"

#include "rtpro/render/beer_lambert.h"
#include "rtpro/render/dielectric.h"
#include "rtpro/render/light_sample.h"
#include "rtpro/render/ray_offset.h"
#include "rtpro/render/texture.h"

#include <cmath>

namespace rtpro {

namespace {

using Workspace = ShadingWorkspace;

// Branches of the ray tree carrying less than this (largest channel of the path weight) are not
// traced: below what an 8-bit output resolves even at full exposure, and it bounds the tree that
// glass (two children per hit) would otherwise double at every depth.
constexpr float kMinThroughput = 1.0f / 4096.0f;

float max_channel(const Color& c) { return std::max(c.x, std::max(c.y, c.z)); }

// Reads the hits of one generation: misses see the background, hits become shaded surfaces with
// their shadow rays queued (lights behind the surface, by either normal, need none).
void gather_surfaces(const RenderScene& scene, const Workspace::Generation& generation, int depth,
                     std::span<SampleResult> results, Workspace& ws) {
  ws.surfaces.clear();
  ws.shadow_queries.clear();
  ws.shadow_rays.clear();
  for (std::uint32_t i = 0; i < generation.tasks.size(); ++i) {
    const Workspace::RayTask& task = generation.tasks[i];
    const Hit& hit = ws.hits[i];
    if (!hit.valid()) {
      results[task.sample].radiance += task.weight * scene.render.background;
      continue;
    }
    const Ray& ray = generation.rays[i];
    Workspace::ShadedSurface& s = ws.surfaces.emplace_back();
    s.task = i;
    s.weight = task.weight;
    if (task.medium != Workspace::kOutside) {
      // Absorbed over the path inside the glass (t is in units of the ray's direction length).
      const Dielectric& glass = *scene.materials[task.medium].dielectric;
      s.weight = s.weight * beer_lambert_transmittance(glass.transmittance, glass.transmittance_distance,
                                                       hit.t * length(ray.dir));
    }
    s.point = make_surface(scene, ray, hit);
    s.mirror = reflect(normalize(ray.dir), s.point.shading_normal);
    s.albedo = evaluate(scene.materials[s.point.material].color, s.point.position);
    if (depth == 0)
      results[task.sample].primary = {true, s.albedo, s.point.shading_normal, hit.t * length(ray.dir), s.point.object_id};

    s.first_shadow = static_cast<std::uint32_t>(ws.shadow_queries.size());
    for (const Light& light : scene.lights) {
      const LightSample ls = sample_light(light, s.point.position);
      const float n_dot_l = dot(s.point.shading_normal, ls.direction);
      if (n_dot_l <= 0.0f || dot(s.point.geometric_normal, ls.direction) <= 0.0f) continue;
      ws.shadow_rays.push_back(std::isinf(ls.distance) ? spawn_ray(s.point, ls.direction)
                                                       : spawn_ray_to(s.point, s.point.position + ls.direction * ls.distance));
      ws.shadow_queries.push_back({ls.radiance, n_dot_l, dot(s.mirror, ls.direction)});
    }
    s.end_shadow = static_cast<std::uint32_t>(ws.shadow_queries.size());
  }
}

// Queues a child ray of the ray tree unless its weight is negligible.
void queue_child(Workspace& ws, const Workspace::RayTask& child, const Ray& ray) {
  if (!(max_channel(child.weight) >= kMinThroughput)) return;
  ws.next.tasks.push_back(child);
  ws.next.rays.push_back(ray);
}

// Glass: Fresnel-weighted reflection and refraction (total internal reflection included), the side
// told by the geometric normal; the refracted ray travels in the glass when it entered.
void queue_dielectric_children(const Material& m, const Workspace::ShadedSurface& s, const Workspace::RayTask& task,
                               const Ray& ray, Workspace& ws) {
  const Dielectric& glass = *m.dielectric;
  const Vec3 incident = normalize(ray.dir);
  const Vec3& normal = s.point.geometric_normal;  // on the incident side
  const float cos_incident = std::max(0.0f, -dot(incident, normal));
  const float eta = s.point.front_face ? glass.ior : 1.0f / glass.ior;
  const float reflectance = fresnel_dielectric(cos_incident, eta);
  const std::uint32_t inside = s.point.material, outside = Workspace::kOutside;
  // A reflected ray stays on the side it came from.
  if (dot(s.mirror, normal) > 0.0f)
    queue_child(ws, {task.sample, s.weight * reflectance, s.point.front_face ? outside : inside, false},
                spawn_ray(s.point, s.mirror));
  if (const auto refracted = refract(incident, normal, eta))
    queue_child(ws, {task.sample, s.weight * (1.0f - reflectance), s.point.front_face ? inside : outside, true},
                spawn_ray(s.point, *refracted));
}

// Adds each surface's direct light (ambient, then each unshadowed light in scene order) to its
// sample and queues the reflection and refraction rays of the next generation. Glass has no
// diffuse part: only highlights, then its two children.
void light_surfaces(const RenderScene& scene, const Workspace::Generation& generation, int depth,
                    std::span<SampleResult> results, Workspace& ws) {
  ws.next.clear();
  for (const Workspace::ShadedSurface& s : ws.surfaces) {
    const Workspace::RayTask& task = generation.tasks[s.task];
    const Material& m = scene.materials[s.point.material];
    const bool diffuse = !m.dielectric;
    Color direct = diffuse ? s.albedo * scene.render.ambient : Color(0.0f);
    for (std::uint32_t q = s.first_shadow; q < s.end_shadow; ++q) {
      if (ws.occluded[q]) continue;
      const Workspace::ShadowQuery& light = ws.shadow_queries[q];
      if (diffuse) direct += s.albedo * light.radiance * light.n_dot_l;
      if (light.r_dot_l > 0.0f && m.specular > 0.0f)
        direct += light.radiance * (m.specular * std::pow(light.r_dot_l, m.shininess));
    }
    results[task.sample].radiance += s.weight * direct;

    if (depth >= scene.render.max_depth) continue;
    if (m.dielectric) {
      queue_dielectric_children(m, s, task, generation.rays[s.task], ws);
      continue;
    }
    // A shading normal can tilt the mirror direction below the surface: nothing to reflect then.
    if (m.reflectivity <= 0.0f || dot(s.mirror, s.point.geometric_normal) <= 0.0f) continue;
    ws.next.tasks.push_back({task.sample, s.weight * m.reflectivity, task.medium, false});
    ws.next.rays.push_back(spawn_ray(s.point, s.mirror));
  }
}

}  // namespace

void shade_batch(const RenderScene& scene, const Backend& backend, std::span<const Ray> camera_rays,
                 std::span<SampleResult> results, RayCounts& counts, ShadingWorkspace& ws) {
  ws.current.clear();
  for (std::uint32_t i = 0; i < camera_rays.size(); ++i) {
    results[i] = SampleResult{};
    ws.current.tasks.push_back({i, Color(1.0f)});
  }
  ws.current.rays.assign(camera_rays.begin(), camera_rays.end());
  counts.camera += camera_rays.size();

  for (int depth = 0; !ws.current.rays.empty(); ++depth) {
    ws.hits.resize(ws.current.rays.size());
    backend.intersect(ws.current.rays, ws.hits, depth == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    gather_surfaces(scene, ws.current, depth, results, ws);

    ws.occluded.resize(ws.shadow_rays.size());
    backend.occluded(ws.shadow_rays, ws.occluded, depth == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    counts.shadow += ws.shadow_rays.size();

    light_surfaces(scene, ws.current, depth, results, ws);
    for (const Workspace::RayTask& task : ws.next.tasks) (task.refracted ? counts.refraction : counts.reflection) += 1;
    std::swap(ws.current, ws.next);
  }
}

}  // namespace rtpro
