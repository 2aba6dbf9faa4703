#include "whitted_integrator.h"

#include "rtpro/core/append_ray.h"
#include "rtpro/core/avx2_clones.h"
#include "beer_lambert.h"
#include "dielectric.h"
#include "film_motion.h"
#include "hit_prefetch.h"
#include "light_linking.h"
#include "light_sample.h"
#include "ray_offset.h"
#include "surface_batch.h"
#include "sample_times.h"
#include "texture.h"
#include "whitted_light_units.h"
#include "whitted_shadow_rays.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

namespace rtpro {

namespace {

using Workspace = ShadingWorkspace;

// Branches of the ray tree carrying less than this (largest channel of the path weight) are not
// traced: below what an 8-bit output resolves even at full exposure, and it bounds the tree that
// glass (two children per hit) would otherwise double at every depth.
constexpr float kMinThroughput = 1.0f / 4096.0f;

// The emission of the nearest area light `ray` sees before t_max, if any, and where along the ray.
struct SeenEmitter {
  Color emission;
  float t;
};
std::optional<SeenEmitter> seen_emitter(const RenderScene& scene, const Workspace& ws, const Ray& ray, float t_max) {
  std::optional<SeenEmitter> seen;
  for (const std::uint32_t l : ws.emitters)
    if (const float t = hit_light(scene.lights[l], ray, t_max); t < t_max) {
      t_max = t;
      seen = SeenEmitter{light_emission(scene.lights[l]), t};
    }
  return seen;
}

// The path weight after the ray's length inside glass (absorption), for a segment of parameter t.
Color through_medium(const RenderScene& scene, const Workspace::RayTask& task, const Ray& ray, float t) {
  if (task.medium == Workspace::kOutside) return task.weight;
  const Dielectric& glass = *scene.materials[task.medium].whitted.glass;
  return task.weight *
         beer_lambert_transmittance(glass.transmittance, glass.transmittance_distance, t * length(ray.dir));
}

// Reads the hits of one generation: misses see the background (or an area light), hits become
// shaded surfaces with their shadow rays queued, one per light or samples² per area light (lights
// behind the surface, by either normal, need none); at depth 0 a hit is the sample's primary hit
// where records_primary (with its film motion where records_motion).
RTPRO_AVX2_CLONES
void gather_surfaces(const RenderScene& scene, const StratifiedSampler& sampler, std::span<const SampleKey> keys,
                     const Workspace::GenerationView& generation, int depth, bool records_primary, bool records_motion,
                     bool prefetch_hits, std::span<SampleResult> results, Workspace& ws) {
  ws.surfaces.clear();
  ws.shadow_queries.clear();
  ws.shadow_rays.clear();
  ws.shadow_lights.clear();
  // What follows the surface point and its mirror direction: the albedo and the camera hit's AOVs.
  auto complete = [&](Workspace::ShadedSurface& s) {
    const Ray& ray = generation.rays[s.task];
    const ColorTexture& color = scene.materials[s.point.material].whitted.color;
    const Color* plain = std::get_if<Color>(&color);
    s.albedo = plain ? *plain : evaluate(color, s.point, ws.textures);
    if (depth == 0 && records_primary)
      results[generation.tasks[s.task].sample].primary = {true, s.albedo, s.point.shading_normal,
                                                          ws.hits[s.task].t * length(ray.dir), s.point.object_id};
    if (depth == 0 && records_motion)
      results[generation.tasks[s.task].sample].primary.motion =
          film_motion(scene, ws.hits[s.task], ws.ray_times.empty() ? 0.0f : ws.ray_times[s.task], s.point.position);
  };
  // Plain sphere hits and plain triangle hits wait in fours for make_sphere_surfaces4 and
  // make_triangle_surfaces4 (the same surfaces, bit for bit).
  struct Waiting {
    std::uint32_t surfaces[4];
    unsigned count = 0;
  };
  Waiting spheres, triangles;
  auto make_waiting_surfaces = [&](Waiting& waiting, auto make_four) {
    const Ray* rays[4];
    const Hit* hits[4];
    SurfacePoint* points[4];
    Vec3* mirrors[4];
    for (unsigned k = 0; k < 4; ++k) {
      Workspace::ShadedSurface& s = ws.surfaces[waiting.surfaces[k]];
      rays[k] = &generation.rays[s.task];
      hits[k] = &ws.hits[s.task];
      points[k] = &s.point;
      mirrors[k] = &s.mirror;
    }
    make_four(scene, rays, hits, points, mirrors);
    for (unsigned k = 0; k < 4; ++k) complete(ws.surfaces[waiting.surfaces[k]]);
    waiting.count = 0;
  };
  // Any other hit, and plain hits left over from the last four: one at a time.
  auto make_one_surface = [&](Workspace::ShadedSurface& s) {
    const Ray& ray = generation.rays[s.task];
    if (!ws.ray_times.empty()) make_surface_at(scene, ray, ws.ray_times[s.task], ws.hits[s.task], s.point);
    else make_surface(scene, ray, ws.hits[s.task], s.point);
    s.mirror = reflect(normalize(ray.dir), s.point.shading_normal);
    complete(s);
  };
  const HitPrefetch prefetch(scene, prefetch_hits, ws.hits, ws.ray_times);
  for (std::uint32_t i = 0; i < generation.tasks.size(); ++i) {
    prefetch.before(i);
    const Workspace::RayTask& task = generation.tasks[i];
    const Hit& hit = ws.hits[i];
    const Ray& ray = generation.rays[i];
    if (!ws.emitters.empty())
      if (const std::optional<SeenEmitter> seen = seen_emitter(scene, ws, ray, hit.valid() ? hit.t : ray.tfar)) {
        results[task.sample].radiance += through_medium(scene, task, ray, seen->t) * seen->emission;
        continue;
      }
    if (!hit.valid()) {
      const bool shows_environment = ws.environment && (depth > 0 || ws.environment->visible());
      results[task.sample].radiance +=
          task.weight * (shows_environment ? ws.environment->radiance(ray.dir) : scene.render.background);
      continue;
    }
    Workspace::ShadedSurface& s = ws.surfaces.emplace_back();
    s.task = i;
    // Absorbed over the path inside glass (t is in units of the ray's direction length).
    s.weight = through_medium(scene, task, ray, hit.t);
    const std::uint32_t index = static_cast<std::uint32_t>(ws.surfaces.size() - 1);
    if (is_plain_sphere_hit(scene, hit)) {
      spheres.surfaces[spheres.count++] = index;
      if (spheres.count == 4) make_waiting_surfaces(spheres, [](auto&&... four) { make_sphere_surfaces4(four...); });
      continue;
    }
    if (is_plain_triangle_hit(scene, hit)) {
      triangles.surfaces[triangles.count++] = index;
      if (triangles.count == 4)
        make_waiting_surfaces(triangles, [](auto&&... four) { make_triangle_surfaces4(four...); });
      continue;
    }
    make_one_surface(s);
  }
  for (const Waiting* waiting : {&spheres, &triangles})
    for (unsigned k = 0; k < waiting->count; ++k) make_one_surface(ws.surfaces[waiting->surfaces[k]]);
  queue_shadow_rays(scene, sampler, keys, generation, depth, ws);
}

// Queues a child ray of the ray tree unless its weight is negligible.
void queue_child(Workspace& ws, const Workspace::RayTask& child, const Ray& ray) {
  if (!(max_component(child.weight) >= kMinThroughput)) return;
  ws.next.tasks.push_back(child);
  append_ray(ws.next.rays, ray);
}

// Glass: Fresnel-weighted reflection and refraction (total internal reflection included), the side
// told by the geometric normal; the refracted ray travels in the glass when it entered.
void queue_dielectric_children(const Dielectric& glass, const Workspace::ShadedSurface& s,
                               const Workspace::RayTask& task, const Ray& ray, Workspace& ws) {
  const Vec3 incident = normalize(ray.dir);
  const Vec3& normal = s.point.geometric_normal;  // on the incident side
  const float cos_incident = std::max(0.0f, -dot(incident, normal));
  const float eta = s.point.front_face ? glass.ior : 1.0f / glass.ior;
  const float reflectance = fresnel_dielectric(cos_incident, eta);
  // One medium is tracked, the glass entered last: leaving another glass by its back (the wall
  // of a tumbler whose liquid reaches into it) keeps it, so the liquid keeps absorbing.
  const std::uint32_t inside = s.point.material;
  const std::uint32_t outside = task.medium == inside ? Workspace::kOutside : task.medium;
  // A reflected ray stays on the side it came from.
  if (dot(s.mirror, normal) > 0.0f)
    queue_child(ws, {task.sample, s.weight * reflectance, s.point.front_face ? task.medium : inside, false},
                spawn_ray(s.point, s.mirror));
  if (const auto refracted = refract(incident, normal, eta))
    queue_child(ws, {task.sample, s.weight * (1.0f - reflectance), s.point.front_face ? inside : outside, true},
                spawn_ray(s.point, *refracted));
}

// Adds each surface's direct light (ambient, then each unshadowed light in scene order) to its
// sample and queues the reflection and refraction rays of the next generation. Glass has no
// diffuse part: only highlights, then its two children.
RTPRO_AVX2_CLONES
void light_surfaces(const RenderScene& scene, const Workspace::GenerationView& generation, int depth,
                    std::span<SampleResult> results, Workspace& ws) {
  ws.next.clear();
  for (const Workspace::ShadedSurface& s : ws.surfaces) {
    const Workspace::RayTask& task = generation.tasks[s.task];
    const WhittedMaterial& m = scene.materials[s.point.material].whitted;
    const bool diffuse = !m.glass;
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
    if (m.glass) {
      queue_dielectric_children(*m.glass, s, task, generation.rays[s.task], ws);
      continue;
    }
    // A shading normal can tilt the mirror direction below the surface: nothing to reflect then.
    if (m.reflectivity <= 0.0f || dot(s.mirror, s.point.geometric_normal) <= 0.0f) continue;
    ws.next.tasks.push_back({task.sample, s.weight * m.reflectivity, task.medium, false});
    // The mirror ray leaves by the front (checked above): spawn_ray's origin.
    Ray& mirror = ws.next.rays.emplace_back();
    mirror.org = s.front_origin_known ? s.front_origin : offset_ray_origin_on_side(s.point, true);
    mirror.dir = s.mirror;
  }
}

// Each shadow ray's sample's time (nothing while the shutter is closed).
void times_of_shadow_rays(std::span<const float> sample_times, const Workspace::GenerationView& generation,
                          Workspace& ws) {
  ws.shadow_times.resize(sample_times.empty() ? 0 : ws.shadow_rays.size());
  for (const Workspace::ShadedSurface& s : ws.surfaces)
    if (!sample_times.empty())
      std::fill(ws.shadow_times.begin() + s.first_shadow, ws.shadow_times.begin() + s.end_shadow,
                sample_times[generation.tasks[s.task].sample]);
}

}  // namespace

void WhittedIntegrator::trace(const CameraBatch& batch, RayCounts& counts, Workspace& ws) const {
  const RenderScene& scene = scene_;
  const std::span<const Ray> camera_rays = batch.rays;
  const std::span<const SampleKey> keys = batch.keys;
  const std::span<SampleResult> results = batch.results;
  ws.textures = textures_;
  ws.environment = environment_;
  ws.emitters.clear();
  ws.is_emitter.assign(scene.lights.size(), 0);
  ws.light_samples_per_axis.resize(scene.lights.size());
  for (std::uint32_t l = 0; l < scene.lights.size(); ++l) {
    ws.light_samples_per_axis[l] = light_samples_per_axis(scene.lights[l]);
    if (!is_black(light_emission(scene.lights[l]))) {
      ws.emitters.push_back(l);
      ws.is_emitter[l] = 1;
    }
  }
  ws.current.clear();
  ws.current.tasks.resize(camera_rays.size());
  for (std::uint32_t i = 0; i < camera_rays.size(); ++i) {
    results[i] = SampleResult{};
    ws.current.tasks[i] = {i, Color(1.0f)};
  }
  counts[RayKind::kCamera] += camera_rays.size();

  for (int depth = 0;; ++depth) {
    const Workspace::GenerationView generation{ws.current.tasks,
                                               depth == 0 ? camera_rays : std::span<const Ray>(ws.current.rays)};
    if (generation.rays.empty()) break;
    ws.hits.resize(generation.rays.size());
    times_of_samples(
        batch.times, generation.tasks, [](const Workspace::RayTask& task) { return task.sample; }, ws.ray_times);
    backend_.intersect(generation.rays, ws.ray_times, ws.hits,
                       depth == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    gather_surfaces(scene, sampler_, keys, generation, depth, records_primary_, records_motion_, prefetch_hits_,
                    results, ws);

    ws.occluded.resize(ws.shadow_rays.size());
    times_of_shadow_rays(batch.times, generation, ws);
    occluded_with_shadow_linking(backend_, scene.links, ws.shadow_rays, ws.shadow_times, ws.shadow_lights, ws.occluded,
                                 depth == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    counts[RayKind::kShadow] += ws.shadow_rays.size();

    light_surfaces(scene, generation, depth, results, ws);
    // Summed in a local: a store to the counts in the loop would reload every task's field.
    std::uint64_t refracted = 0;
    for (const Workspace::RayTask& task : ws.next.tasks) refracted += task.refracted;
    counts[RayKind::kRefraction] += refracted;
    counts[RayKind::kReflection] += ws.next.tasks.size() - refracted;
    std::swap(ws.current, ws.next);
  }
}

}  // namespace rtpro
