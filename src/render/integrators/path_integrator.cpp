#include "path_integrator.h"

#include "rtpro/core/append_ray.h"
#include "cosine_lanes.h"
#include "beer_lambert.h"
#include "light_linking.h"
#include "material_bsdf.h"
#include "texture.h"
#include "ray_offset.h"
#include "sample_dimensions.h"
#include "surface_batch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

using Path = PathWorkspace::Path;
using VertexSamples = PathWorkspace::VertexSamples;

// The power heuristic (β = 2) for a sample of pdf `a` against the other strategy's pdf `b`.
float power_heuristic(float a, float b) {
  if (std::isinf(a)) return 1.0f;
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// Shadow rays to a sampled point stop this fraction short of it, so the emitter's own surface
// (or a light's) does not occlude the point sampled on it.
constexpr float kShadowEpsilon = 1e-4f;

// No channel positive (NaN counts as nothing).
bool carries_no_light(const Color& c) { return !(c.x > 0.0f || c.y > 0.0f || c.z > 0.0f); }

// bsdf_eval, a Lambert surface's inline: most vertices of most scenes are, and its f is a
// comparison and a product, less than the call.
Color eval_bsdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  if (const auto* lambert = std::get_if<DiffuseBsdf>(&bsdf)) return lambert->eval(wo, wi);
  return bsdf_eval(bsdf, wo, wi);
}

// bsdf_sample, a Lambert surface's from its direction worked out beforehand.
std::optional<BsdfSample> sample_bsdf(const Bsdf& bsdf, const Vec3& wo, const VertexSamples& u,
                                      bool cosine_directions) {
  if (const auto* lambert = std::get_if<DiffuseBsdf>(&bsdf); lambert && cosine_directions)
    return lambert->sample_toward(wo, u.cosine_direction);
  return bsdf_sample(bsdf, wo, u.choices.y, u.bsdf_direction);
}

class PathTracer {
 public:
  // `cosine_directions`: the vertices' records hold their Lambert directions (VertexDraws);
  // `lone_point_light`: the workspace holds their light samples.
  PathTracer(const RenderScene& scene, const LightSet& lights, std::span<SampleResult> results, PathWorkspace& ws,
             const TextureLookup* textures, bool cosine_directions, bool lone_point_light)
      : scene_(scene), lights_(lights), results_(results), ws_(ws), textures_(textures),
        cosine_directions_(cosine_directions), lone_point_light_(lone_point_light) {}

  // Everything a path does at the surface (or miss) its ray reached: emission, then the light
  // sample (queued as a shadow ray), then the BSDF sample (queued as the path's next ray).
  // `sp` is the surface of a valid hit (make_surfaces), unread otherwise.
  // `u` are the vertex's random numbers (draw_vertex_samples), read only below max_depth.
  // `vertex`: the path's place in the generation, for the light samples made for all of it
  // (PathWorkspace::light_samples).
  void extend(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit, const SurfacePoint& sp,
              const VertexSamples& u) {
    SampleResult& result = results_[path.sample];
    const float t_hit = hit.valid() ? hit.t : ray.tfar;
    if (const std::optional<LightSet::SeenLight> seen = lights_.seen_light(ray, t_hit, path.group)) {
      const Vec3 on_light = ray.at(seen->t);
      add_emission(path, result, seen->radiance, seen->index, on_light, path.beta);
      return;  // lights without geometry absorb what reaches them
    }
    if (!hit.valid()) {
      escape(path, ray, result);
      return;
    }
    const Material& material = scene_.materials[sp.material];
    Color beta = path.beta;
    if (path.medium != PathWorkspace::kOutside) {
      const Dielectric& medium = *interior_of(scene_.materials[path.medium]);
      beta = beta *
             beer_lambert_transmittance(medium.transmittance, medium.transmittance_distance, hit.t * length(ray.dir));
    }
    if (material.emission.emits() && (material.emission.two_sided || sp.front_face))
      add_emission(path, result, emitted_radiance(material.emission, sp.tex_u, sp.tex_v, textures_),
                   lights_.light_of_hit(hit), sp.position, beta);

    const std::uint32_t group = link_group_of(scene_.links, hit);
    SurfaceBsdf& surface = surface_;
    material_bsdf(material, sp, textures_, surface);
    const bool delta = bsdf_is_delta(surface.bsdf);
    if (path.bounce == 0)
      result.primary = {true, surface.albedo, sp.shading_normal, hit.t * length(ray.dir), sp.object_id};
    bool aov_pending = path.aov_pending;
    if (aov_pending && !delta) {
      result.primary.albedo = surface.albedo;
      result.primary.normal = sp.shading_normal;
      aov_pending = false;
    }
    if (path.bounce >= scene_.render.max_depth) return;

    // The reciprocal length multiplied through: one division, not normalize's three.
    const Vec3 wo = surface.frame.to_local(ray.dir * (-1.0f / length(ray.dir)));
    SpawnOrigins origins(sp);
    if (!delta && !lights_.empty(group)) {
      if (lone_point_light_) {
        if (ws_.light_found[vertex])
          queue_shadow_ray(path.sample, origins, surface, wo, ws_.light_samples[vertex], beta);
      } else if (lights_.sample(sp.position, u.choices.x, u.light_point, textures_, group, light_sample_)) {
        queue_shadow_ray(path.sample, origins, surface, wo, light_sample_, beta);
      }
    }

    const std::optional<BsdfSample> bs = sample_bsdf(surface.bsdf, wo, u, cosine_directions_);
    if (!bs || !(bs->pdf > 0.0f) || carries_no_light(bs->f)) return;
    Color next_beta = beta * bs->f * (std::fabs(bs->wi.z) / bs->pdf);
    if (path.bounce >= kRouletteStart) {
      const float q = std::max(0.05f, 1.0f - max_component(next_beta));
      if (u.roulette < q) return;
      next_beta = next_beta * (1.0f / (1.0f - q));
    }
    if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
    const Vec3 direction = surface.frame.to_world(bs->wi);
    std::uint32_t medium = path.medium;
    if (bs->transmitted && interior_of(material)) medium = sp.front_face ? sp.material : PathWorkspace::kOutside;
    Path& next = ws_.next_paths.emplace_back();
    next.sample = path.sample;
    next.bounce = path.bounce + 1;
    next.beta = next_beta;
    next.origin = sp.position;
    next.bsdf_pdf = bs->pdf;
    next.specular = bs->delta;
    next.aov_pending = aov_pending;
    next.transmitted = bs->transmitted;
    next.medium = medium;
    next.group = group;
    append_ray(ws_.next_rays, spawn_ray(origins, direction));
  }

 private:
  // Emission reaching the path: in full after the camera or a specular vertex, else weighted
  // against the light sampling that could have found the same point.
  void add_emission(const Path& path, SampleResult& result, const Color& radiance, std::uint32_t light,
                    const Vec3& on_light, const Color& beta) {
    float weight = 1.0f;
    if (!path.specular && light != kInvalidId) {
      switch (scene_.render.path_sampling) {
        case PathSampling::kMis:
          weight = power_heuristic(path.bsdf_pdf, lights_.pdf(light, path.origin, on_light, path.group));
          break;
        case PathSampling::kLight: weight = 0.0f; break;  // light sampling found it already
        case PathSampling::kBsdf: break;
      }
    }
    result.radiance += beta * radiance * weight;
  }

  // A ray that leaves the scene: the environment, weighted against light sampling as emission
  // is, or the background. Camera rays see the background where the environment is not visible.
  void escape(const Path& path, const Ray& ray, SampleResult& result) {
    const EnvironmentLight* environment = lights_.environment();
    if (!environment || (path.bounce == 0 && !environment->visible())) {
      result.radiance += path.beta * scene_.render.background;
      return;
    }
    const Color radiance = environment->radiance(ray.dir);
    float weight = 1.0f;
    if (!path.specular) {
      switch (scene_.render.path_sampling) {
        case PathSampling::kMis:
          weight = power_heuristic(path.bsdf_pdf, lights_.environment_pdf(ray.dir, path.group));
          break;
        case PathSampling::kLight: weight = 0.0f; break;
        case PathSampling::kBsdf: break;
      }
    }
    result.radiance += path.beta * radiance * weight;
  }

  void queue_shadow_ray(std::uint32_t sample, SpawnOrigins& origins, const SurfaceBsdf& surface, const Vec3& wo,
                        const PathLightSample& ls, const Color& beta) {
    const Vec3 wi = surface.frame.to_local(ls.direction);
    const Color f = eval_bsdf(surface.bsdf, wo, wi) * std::fabs(wi.z);
    if (carries_no_light(f)) return;
    float weight = 1.0f;
    if (!ls.delta) {
      switch (scene_.render.path_sampling) {
        case PathSampling::kMis: weight = power_heuristic(ls.pdf, bsdf_pdf(surface.bsdf, wo, wi)); break;
        case PathSampling::kLight: break;
        case PathSampling::kBsdf: return;  // BSDF samples find it
      }
    }
    const Color contribution = beta * f * ls.radiance * (weight / ls.pdf);
    if (!is_finite(contribution) || carries_no_light(contribution)) return;
    Ray ray;
    if (std::isinf(ls.distance)) {
      ray = spawn_ray(origins, ls.direction);
    } else {
      ray = spawn_ray_to(origins, origins.surface().position + ls.direction * ls.distance);
      ray.tfar = 1.0f - kShadowEpsilon;
    }
    PathWorkspace::ShadowQuery& query = ws_.shadow_queries.emplace_back();
    query.sample = sample;
    query.contribution = contribution;
    append_ray(ws_.shadow_rays, ray);
    // Read only under light linking (occluded_with_shadow_linking).
    if (scene_.links.linked()) ws_.shadow_lights.push_back(ls.light < scene_.lights.size() ? ls.light : kInvalidId);
  }

  const RenderScene& scene_;
  const LightSet& lights_;
  std::span<SampleResult> results_;
  PathWorkspace& ws_;
  const TextureLookup* textures_;
  bool cosine_directions_;
  bool lone_point_light_;
  // The current vertex's BSDF and light sample, filled in place (material_bsdf, LightSet::sample).
  SurfaceBsdf surface_;
  PathLightSample light_sample_;
};

// Which of a vertex's random numbers the scene reads: the choices when its lights need picking or
// a material chooses among lobes, the light point when a light has an extent. Each value is a
// function of its own dimension, so leaving out a draw nothing reads changes no other value.
// The Lambert surfaces' cosine-weighted directions are worked out for every vertex at once
// (cosine_lanes.h) when some material makes them.
struct VertexDraws {
  bool choices;
  bool light_point;
  bool cosine_directions;
};

VertexDraws vertex_draws(const RenderScene& scene, const LightSet& lights) {
  const auto any_material = [&](bool (*which)(const Material&)) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), which);
  };
  return {any_material(reads_lobe_choice) || lights.reads_pick_number(), lights.reads_point_numbers(),
          any_material(makes_lambert_bsdf)};
}

// sample_cosine_hemisphere of every vertex's BSDF numbers, into its record.
void draw_cosine_directions(std::vector<VertexSamples>& samples) {
  if (samples.empty()) return;
  sample_cosine_hemispheres(samples.size(), &samples.front().bsdf_direction, &samples.front().cosine_direction,
                            sizeof(VertexSamples));
}

// The random numbers of the vertices the generation's rays reach (all at bounce `bounce`), drawn
// for every path together: the same values a draw per vertex gives, bit for bit, but a batch lets
// the sampler hash many keys side by side. A path that reaches no surface leaves its draw unused,
// and the fields `needed` leaves out keep whatever they held.
template <class Sampler>
void draw_vertex_samples(const Sampler& sampler, std::span<const SampleKey> keys, int bounce, VertexDraws needed,
                         PathWorkspace& ws) {
  const std::size_t n = ws.paths.size();
  ws.path_keys.resize(n);
  for (std::size_t i = 0; i < n; ++i) ws.path_keys[i] = keys[ws.paths[i].sample];
  ws.draws.resize(n);
  ws.vertex_samples.resize(n);
  const auto draw = [&](int offset, Sample2D VertexSamples::*field) {
    sampler.sample_2d(ws.path_keys, sample_dimension::at_bounce(bounce, offset), ws.draws);
    for (std::size_t i = 0; i < n; ++i) ws.vertex_samples[i].*field = ws.draws[i];
  };
  // The light's pick and the BSDF's lobe choice as one 2D sample: one draw instead of two.
  if (needed.choices) draw(path_dimension::kChoices, &VertexSamples::choices);
  if (needed.light_point) draw(path_dimension::kLightPoint, &VertexSamples::light_point);
  draw(path_dimension::kBsdfDirection, &VertexSamples::bsdf_direction);
  if (needed.cosine_directions) draw_cosine_directions(ws.vertex_samples);
  if (bounce < kRouletteStart) return;
  ws.roulette_draws.resize(n);
  sampler.sample_1d(ws.path_keys, sample_dimension::at_bounce(bounce, path_dimension::kRoulette), ws.roulette_draws);
  for (std::size_t i = 0; i < n; ++i) ws.vertex_samples[i].roulette = ws.roulette_draws[i];
}

// The same for the Sobol sampler, which draws all of a vertex's dimensions in one pass over the
// keys (hashing each key once) and writes them straight into the VertexSamples.
void draw_vertex_samples(const SobolSampler& sampler, std::span<const SampleKey> keys, int bounce, VertexDraws needed,
                         PathWorkspace& ws) {
  const std::size_t n = ws.paths.size();
  if (n == 0) return;  // the draws below point at the first record
  ws.path_keys.resize(n);
  for (std::size_t i = 0; i < n; ++i) ws.path_keys[i] = keys[ws.paths[i].sample];
  ws.vertex_samples.resize(n);
  VertexSamples* const first = ws.vertex_samples.data();
  const auto pair = [&](int offset, Sample2D VertexSamples::*field) {
    return SobolSampler::Draw<Sample2D>{sample_dimension::at_bounce(bounce, offset), &(first->*field),
                                        sizeof(VertexSamples)};
  };
  // The light's pick and the BSDF's lobe choice as one 2D sample: one draw instead of two.
  SobolSampler::Draw<Sample2D> pairs[3];
  std::size_t pair_count = 0;
  if (needed.choices) pairs[pair_count++] = pair(path_dimension::kChoices, &VertexSamples::choices);
  if (needed.light_point) pairs[pair_count++] = pair(path_dimension::kLightPoint, &VertexSamples::light_point);
  pairs[pair_count++] = pair(path_dimension::kBsdfDirection, &VertexSamples::bsdf_direction);
  const SobolSampler::Draw<float> roulette[] = {
      {sample_dimension::at_bounce(bounce, path_dimension::kRoulette), &first->roulette, sizeof(VertexSamples)}};
  sampler.sample(ws.path_keys, {pairs, pair_count},
                 bounce < kRouletteStart ? std::span<const SobolSampler::Draw<float>>() : roulette);
  if (needed.cosine_directions) draw_cosine_directions(ws.vertex_samples);
}

}  // namespace

void PathIntegrator::trace(const CameraBatch& batch, RayCounts& counts, Workspace& ws) const {
  samplers_.with_chosen([&](const auto& sampler) { trace_with(sampler, batch, counts, ws); });
}

template <class Sampler>
void PathIntegrator::trace_with(const Sampler& sampler, const CameraBatch& batch, RayCounts& counts,
                                Workspace& ws) const {
  const RenderScene& scene = scene_;
  const LightSet& lights = lights_;
  const std::span<const Ray> camera_rays = batch.rays;
  const std::span<const SampleKey> keys = batch.keys;
  const std::span<SampleResult> results = batch.results;
  ws.paths.clear();
  ws.rays.assign(camera_rays.begin(), camera_rays.end());
  for (std::uint32_t i = 0; i < camera_rays.size(); ++i) {
    results[i] = SampleResult{};
    Path& path = ws.paths.emplace_back();
    path.sample = i;
    path.bounce = 0;
    path.beta = Color(1.0f);
    path.origin = camera_rays[i].org;
    path.bsdf_pdf = 0.0f;
    path.specular = true;
    path.aov_pending = true;
    path.transmitted = false;
    path.medium = PathWorkspace::kOutside;
    path.group = 0;
  }
  counts[RayKind::kCamera] += camera_rays.size();
  const VertexDraws needed = vertex_draws(scene, lights);
  const std::optional<LightSet::LonePointLight> lone_point_light = lights.lone_point_light();
  PathTracer tracer(scene, lights, results, ws, textures_, needed.cosine_directions, lone_point_light.has_value());
  for (int generation = 0; !ws.paths.empty(); ++generation) {
    ws.hits.resize(ws.rays.size());
    backend_.intersect(ws.rays, ws.hits, generation == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    ws.next_paths.clear();
    ws.next_rays.clear();
    ws.shadow_queries.clear();
    ws.shadow_rays.clear();
    ws.shadow_lights.clear();
    ws.surfaces.resize(ws.rays.size());
    make_surfaces(scene, ws.rays, ws.hits, ws.surfaces);
    if (generation < scene.render.max_depth) {
      draw_vertex_samples(sampler, keys, generation, needed, ws);
      if (lone_point_light) {
        // Made for every path, the ones that hit nothing included (their samples go unread).
        ws.light_samples.resize(ws.paths.size());
        ws.light_found.resize(ws.paths.size());
        LightSet::sample_lone_point_light(*lone_point_light, ws.surfaces, ws.light_samples, ws.light_found);
      }
    }
    for (std::size_t i = 0; i < ws.paths.size(); ++i)
      tracer.extend(i, ws.paths[i], ws.rays[i], ws.hits[i], ws.surfaces[i], ws.vertex_samples[i]);

    ws.occluded.resize(ws.shadow_rays.size());
    occluded_with_shadow_linking(backend_, scene.links, ws.shadow_rays, ws.shadow_lights, ws.occluded,
                                 RayCoherence::kIncoherent);
    counts[RayKind::kShadow] += ws.shadow_rays.size();
    for (std::size_t i = 0; i < ws.shadow_queries.size(); ++i)
      if (!ws.occluded[i]) results[ws.shadow_queries[i].sample].radiance += ws.shadow_queries[i].contribution;
    // Summed in a local: a store to the counts in the loop would reload every path's field.
    std::uint64_t transmitted = 0;
    for (const Path& next : ws.next_paths) transmitted += next.transmitted;
    counts[RayKind::kRefraction] += transmitted;
    counts[RayKind::kReflection] += ws.next_paths.size() - transmitted;
    std::swap(ws.paths, ws.next_paths);
    std::swap(ws.rays, ws.next_rays);
  }
}

}  // namespace rtpro
