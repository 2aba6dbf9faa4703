#include "path_integrator.h"

#include "rtpro/core/append_ray.h"
#include "beer_lambert.h"
#include "lambert_fast_paths.h"
#include "light_linking.h"
#include "material_bsdf.h"
#include "texture.h"
#include "ray_offset.h"
#include "surface_batch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rtpro {

namespace {

using Path = PathWorkspace::Path;

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

// The path's bounce counts after one more of kind `lobe`.
void count_bounce(BsdfLobe lobe, Path& next) {
  switch (lobe) {
    case BsdfLobe::kDiffuse: ++next.diffuse_bounces; return;
    case BsdfLobe::kGlossy: ++next.glossy_bounces; return;
    case BsdfLobe::kTransmission: ++next.transmission_bounces; return;
  }
}

// Russian roulette (pbrt-v4's rule): where β·eta_scale, the throughput without the 1/η² by which
// the path's refractions scaled radiance, is below 1 in its largest channel m, the path ends with
// probability q = 1 − m and a survivor's β is divided by 1 − q; a path with m >= 1 goes on as it
// is. Read with the scale, roulette would end more than half of the paths inside glass (1/2.25 at
// ior 1.5) and give the survivors 2.25; a floor on q would multiply β by 1/(1 − q) at every bounce
// of the long chains of internal reflections in rough glass. Either spreads a white furnace,
// where every path through glass brings back exactly 1, into pixels up to 1.17 at 256 spp.
// Returns whether the path goes on.
bool russian_roulette(Color& beta, float eta_scale, float u) {
  const float survival = max_component(beta) * eta_scale;
  if (!(survival < 1.0f)) return true;
  const float q = 1.0f - survival;
  if (u < q) return false;
  beta = beta * (1.0f / (1.0f - q));
  return true;
}

// Cycles' sample clamp: a contribution whose channels sum to more than `sum_limit` (3 × the
// clamp, so that the channel mean is capped) is scaled down to it, its hue kept. An infinite
// limit, clamping off, leaves every contribution as it was.
Color clamped(const Color& contribution, float sum_limit) {
  const float sum = std::fabs(contribution.x) + std::fabs(contribution.y) + std::fabs(contribution.z);
  return sum > sum_limit ? contribution * (sum_limit / sum) : contribution;
}

float clamp_sum_limit(float clamp) { return clamp > 0.0f ? 3.0f * clamp : std::numeric_limits<float>::infinity(); }

// The primary hit's AOVs: the camera ray's hit, with the albedo and normal of the path's first
// vertex that is not purely specular. Returns whether those still wait after this vertex.
bool record_aovs(const Path& path, const Ray& ray, const Hit& hit, const SurfacePoint& sp, const SurfaceBsdf& surface,
                 bool delta, PrimaryHit& primary) {
  if (path.bounce == 0) primary = {true, surface.albedo, sp.shading_normal, hit.t * length(ray.dir), sp.object_id};
  if (!path.aov_pending || delta) return path.aov_pending;
  primary.albedo = surface.albedo;
  primary.normal = sp.shading_normal;
  return false;
}

// One step of the estimator, at the point a path's ray reaches (pbrt-v4's PathIntegrator::Li
// loop body, for a generation's paths side by side):
//   L += β·Le·w_b                the emission the ray found, MIS-weighted against light sampling
//   L += β·f·|cos θ|·Le·w_l/p_l  next-event estimation: a light sample, added if its shadow ray passes
//   β *= f·|cos θ|/p_b           the BSDF sample, the path's next ray if it survives Russian roulette
// kLightPathControls: compiled with Cycles' controls (clamps, per-lobe depths, Filter Glossy); without
// them, a scene that sets none pays for none of their tests on its hottest loop.
template <bool kLightPathControls>
class PathVertexStep {
 public:
  // `cosine_directions`: the vertices' samples hold their Lambert directions (VertexDraws);
  // `lone_point_light`: they hold their light samples (GenerationSamples::lone_light_sample).
  PathVertexStep(const RenderScene& scene, const LightSet& lights, std::span<SampleResult> results, PathWorkspace& ws,
                 const TextureLookup* textures, bool cosine_directions, bool lone_point_light)
      : scene_(scene), lights_(lights), results_(results), ws_(ws), textures_(textures),
        cosine_directions_(cosine_directions), lone_point_light_(lone_point_light), depths_(lobe_depths(scene.render)),
        direct_limit_(clamp_sum_limit(scene.render.path.clamp_direct)),
        indirect_limit_(clamp_sum_limit(scene.render.path.clamp_indirect)),
        clamping_(scene.render.path.clamp_direct > 0.0f || scene.render.path.clamp_indirect > 0.0f),
        filter_glossy_(scene.render.path.filter_glossy), max_depth_(scene.render.max_depth),
        lobe_limits_(depths_.diffuse < max_depth_ || depths_.glossy < max_depth_ || depths_.transmission < max_depth_),
        filtering_glossy_(filter_glossy_ > 0.0f) {}

  // Whether the scene sets any of Cycles' controls this step is compiled for.
  bool controls_apply() const { return clamping_ || lobe_limits_ || filtering_glossy_; }

  // `vertex`: the path's place in the generation; `sp` the surface of a valid hit (make_surfaces),
  // unread otherwise; `u` the vertex's random numbers, read only below max_depth.
  void extend(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit, const SurfacePoint& sp,
              const VertexSamples& u) {
    SampleResult& result = results_[path.sample];
    // Le the ray reaches: a light without geometry before the surface, the environment, or the
    // surface's own emission (seen through the medium the ray crossed).
    const float t_hit = hit.valid() ? hit.t : ray.tfar;
    if (const std::optional<LightSet::SeenLight> seen = lights_.seen_light(ray, t_hit, path.group)) {
      add_emission(path, result, seen->radiance, seen->index, ray.at(seen->t), path.beta);
      return;  // lights without geometry absorb what reaches them
    }
    if (!hit.valid()) {
      add_escaped_light(path, ray, result);
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

    // The vertex's BSDF, roughened by Filter Glossy; a path ends after max_depth vertices, or when
    // its bounces of one lobe kind reach their limit, having added their emission.
    const std::uint32_t group = link_group_of(scene_.links, hit);
    SurfaceBsdf& surface = surface_;
    material_bsdf(material, sp, textures_, surface);
    filter_glossy(path, surface.bsdf);
    const bool delta = bsdf_is_delta(surface.bsdf);
    const bool aov_pending = record_aovs(path, ray, hit, sp, surface, delta, result.primary);
    if (ends_here(path)) return;

    // The reciprocal length multiplied through: one division, not normalize's three.
    const Vec3 wo = surface.frame.to_local(ray.dir * (-1.0f / length(ray.dir)));
    SpawnOrigins origins(sp);
    // Next-event estimation, where the BSDF is not purely specular.
    if (!delta && !lights_.empty(group))
      if (const PathLightSample* light = sample_light(vertex, sp.position, u, group))
        queue_light_sample(path.sample, origins, surface, wo, *light, beta,
                           path.bounce == 0 ? direct_limit_ : indirect_limit_);

    // The BSDF sample: β·f·|cos θ|/p_b, then Russian roulette (russian_roulette).
    const std::optional<BsdfSample> bs = sample_bsdf(surface.bsdf, wo, u, cosine_directions_);
    if (!bs || !(bs->pdf > 0.0f) || carries_no_light(bs->f)) return;
    Color next_beta = beta * bs->f * (std::fabs(bs->wi.z) / bs->pdf);
    const float eta_scale = bs->transmitted ? path.eta_scale * (bs->eta * bs->eta) : path.eta_scale;
    if (path.bounce >= kRouletteStart && !russian_roulette(next_beta, eta_scale, u.roulette)) return;
    if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
    // The path's next ray, inside the dielectric it was refracted into, or outside again.
    const Vec3 direction = surface.frame.to_world(bs->wi);
    std::uint32_t medium = path.medium;
    if (bs->transmitted && interior_of(material)) medium = sp.front_face ? sp.material : PathWorkspace::kOutside;
    Path& next = ws_.next_paths.emplace_back(Path{.sample = path.sample,
                                                  .bounce = static_cast<std::uint16_t>(path.bounce + 1),
                                                  .diffuse_bounces = path.diffuse_bounces,
                                                  .glossy_bounces = path.glossy_bounces,
                                                  .transmission_bounces = path.transmission_bounces,
                                                  .beta = next_beta,
                                                  .eta_scale = eta_scale,
                                                  .origin = sp.position,
                                                  .bsdf_pdf = bs->pdf,
                                                  .min_pdf = path.min_pdf,
                                                  .medium = medium,
                                                  .group = group,
                                                  .specular = bs->delta,
                                                  .aov_pending = aov_pending,
                                                  .transmitted = bs->transmitted});
    // A delta sample's pdf is the lobe's probability, not a density: it roughens nothing.
    if (kLightPathControls && filtering_glossy_ && !bs->delta) next.min_pdf = std::min(path.min_pdf, bs->pdf);
    if (kLightPathControls && lobe_limits_) count_bounce(bs->lobe, next);
    append_ray(ws_.next_rays, spawn_ray(origins, direction));
  }

 private:
  // Whether the vertex adds its emission and nothing more: the path has made max_depth bounces,
  // or as many of one lobe kind as that kind's limit (Cycles' per-kind bounce limits, which end a
  // path at the surface after the bounce that reached one).
  bool ends_here(const Path& path) const {
    if (path.bounce >= max_depth_) return true;
    return kLightPathControls && lobe_limits_ &&
           (path.diffuse_bounces >= depths_.diffuse || path.glossy_bounces >= depths_.glossy ||
            path.transmission_bounces >= depths_.transmission);
  }

  // Cycles' Filter Glossy: after BSDF samples of small pdf (diffuse or rough bounces), the
  // vertex's microfacet lobes are given GGX α >= 0.5·sqrt(1 − p_min / filter_glossy), so a sharp
  // highlight seen through a diffuse bounce becomes a blur the BSDF samples find, not a caustic
  // only rare samples do. Off (0), or after the camera and delta bounces only, nothing changes.
  void filter_glossy(const Path& path, Bsdf& bsdf) const {
    if (kLightPathControls && filtering_glossy_ && path.min_pdf < filter_glossy_)
      roughen_bsdf(bsdf, 0.5f * std::sqrt(1.0f - path.min_pdf / filter_glossy_));
  }

  // The clamp of light reaching the camera through the ray that found it: direct for the camera
  // ray and the first vertex's rays (at most one scattering), indirect after.
  float emission_limit(const Path& path) const { return path.bounce <= 1 ? direct_limit_ : indirect_limit_; }
  Color clamp(const Color& contribution, float sum_limit) const {
    return kLightPathControls && clamping_ ? clamped(contribution, sum_limit) : contribution;
  }

  // w_b, the weight of emission a BSDF sample found: in full after the camera or a specular
  // vertex, else against the light sampling that could have found the same point, whose pdf
  // `light_pdf()` gives (asked only under MIS).
  template <class LightPdf>
  float bsdf_sample_weight(const Path& path, const LightPdf& light_pdf) const {
    if (path.specular) return 1.0f;
    switch (scene_.render.path_sampling) {
      case PathSampling::kMis: return power_heuristic(path.bsdf_pdf, light_pdf());
      case PathSampling::kLight: return 0.0f;  // light sampling found it already
      case PathSampling::kBsdf: return 1.0f;
    }
    return 1.0f;
  }

  // L += β·Le·w_b for the radiance Le emitted at `on_light` (of light `light`, kInvalidId for an
  // emitter light sampling never picks: that counts in full).
  void add_emission(const Path& path, SampleResult& result, const Color& radiance, std::uint32_t light,
                    const Vec3& on_light, const Color& beta) {
    const float w_b = light == kInvalidId ? 1.0f : bsdf_sample_weight(path, [&] {
      return lights_.pdf(light, path.origin, on_light, path.group);
    });
    result.radiance += clamp(beta * radiance * w_b, emission_limit(path));
  }

  // A ray that leaves the scene: the environment, weighted as emission is, or the background.
  // Camera rays see the background where the environment is not visible.
  void add_escaped_light(const Path& path, const Ray& ray, SampleResult& result) {
    const EnvironmentLight* environment = lights_.environment();
    if (!environment || (path.bounce == 0 && !environment->visible())) {
      result.radiance += clamp(path.beta * scene_.render.background, emission_limit(path));
      return;
    }
    const Color radiance = environment->radiance(ray.dir);
    const float w_b = bsdf_sample_weight(path, [&] { return lights_.environment_pdf(ray.dir, path.group); });
    result.radiance += clamp(path.beta * radiance * w_b, emission_limit(path));
  }

  // A point on a light for next-event estimation: the lone point light's sample, made for the
  // whole generation, or the light set's pick and sample with the vertex's numbers. Null when
  // the light sends nothing there.
  const PathLightSample* sample_light(std::size_t vertex, const Vec3& position, const VertexSamples& u,
                                      std::uint32_t group) {
    if (lone_point_light_) return ws_.samples.lone_light_sample(vertex);
    return lights_.sample(position, u.choices.x, u.light_point, textures_, group, light_sample_) ? &light_sample_
                                                                                                 : nullptr;
  }

  // β·f·|cos θ|·Le·w_l/p_l of a light sample, queued with its shadow ray: added when that passes.
  // w_l weighs it against the BSDF sampling that could have found the same direction; only light
  // sampling finds a delta light. `clamp_limit`: the vertex's (clamped).
  void queue_light_sample(std::uint32_t sample, SpawnOrigins& origins, const SurfaceBsdf& surface, const Vec3& wo,
                          const PathLightSample& ls, const Color& beta, float clamp_limit) {
    const Vec3 wi = surface.frame.to_local(ls.direction);
    const Color f = eval_bsdf(surface.bsdf, wo, wi) * std::fabs(wi.z);
    if (carries_no_light(f)) return;
    float w_l = 1.0f;
    if (!ls.delta) {
      switch (scene_.render.path_sampling) {
        case PathSampling::kMis: w_l = power_heuristic(ls.pdf, bsdf_pdf(surface.bsdf, wo, wi)); break;
        case PathSampling::kLight: break;
        case PathSampling::kBsdf: return;  // BSDF samples find it
      }
    }
    const Color contribution = clamp(beta * f * ls.radiance * (w_l / ls.pdf), clamp_limit);
    if (!is_finite(contribution) || carries_no_light(contribution)) return;
    Ray ray;
    if (std::isinf(ls.distance)) {
      ray = spawn_ray(origins, ls.direction);
    } else {
      ray = spawn_ray_to(origins, origins.surface().position + ls.direction * ls.distance);
      ray.tfar = 1.0f - kShadowEpsilon;
    }
    ws_.shadow_queries.push_back({sample, contribution});
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
  LobeDepths depths_;
  float direct_limit_, indirect_limit_;  // clamp_sum_limit of the clamps
  bool clamping_;                        // either clamp on: a contribution's sum is worth computing
  float filter_glossy_;                  // 0: off
  int max_depth_;
  // Work only some scenes ask for: the per-lobe counts (a limit below max_depth), Filter Glossy.
  bool lobe_limits_;
  bool filtering_glossy_;
};

// Every camera ray as the first ray of its sample's path, every result cleared.
void start_camera_paths(const CameraBatch& batch, PathWorkspace& ws) {
  ws.paths.clear();
  ws.rays.assign(batch.rays.begin(), batch.rays.end());
  for (std::uint32_t i = 0; i < batch.rays.size(); ++i) {
    batch.results[i] = SampleResult{};
    ws.paths.push_back({.sample = i,
                        .bounce = 0,
                        .diffuse_bounces = 0,
                        .glossy_bounces = 0,
                        .transmission_bounces = 0,
                        .beta = Color(1.0f),
                        .eta_scale = 1.0f,
                        .origin = batch.rays[i].org,
                        .bsdf_pdf = 0.0f,
                        .min_pdf = std::numeric_limits<float>::infinity(),
                        .medium = PathWorkspace::kOutside,
                        .group = 0,
                        .specular = true,
                        .aov_pending = true,
                        .transmitted = false});
  }
}

// Each item's sample's time (an item is a path or a shadow query), or nothing while the shutter is
// closed: every ray of a path is traced at its camera sample's time.
template <typename Item, typename SampleOf>
void times_of_samples(std::span<const float> sample_times, const std::vector<Item>& items, SampleOf&& sample_of,
                      std::vector<float>& times) {
  times.clear();
  if (sample_times.empty()) return;
  times.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) times[i] = sample_times[sample_of(items[i])];
}

// Each path's camera sample key, for its vertex's draws.
std::span<const SampleKey> path_keys(std::span<const SampleKey> keys, PathWorkspace& ws) {
  ws.path_keys.resize(ws.paths.size());
  for (std::size_t i = 0; i < ws.paths.size(); ++i) ws.path_keys[i] = keys[ws.paths[i].sample];
  return ws.path_keys;
}

}  // namespace

void PathIntegrator::trace(const CameraBatch& batch, RayCounts& counts, Workspace& ws) const {
  samplers_.with_chosen([&](const auto& sampler) { trace_with(sampler, batch, counts, ws); });
}

template <class Sampler>
void PathIntegrator::trace_with(const Sampler& sampler, const CameraBatch& batch, RayCounts& counts,
                                Workspace& ws) const {
  const RenderScene& scene = scene_;
  start_camera_paths(batch, ws);
  counts[RayKind::kCamera] += batch.rays.size();
  // Asked per batch, not kept: it points into lights_, which a copy of the integrator would not share.
  const std::optional<LightSet::LonePointLight> lone_point_light = lights_.lone_point_light();
  PathVertexStep<true> controlled_step(scene, lights_, batch.results, ws, textures_, draws_.cosine_directions,
                                       lone_point_light.has_value());
  PathVertexStep<false> plain_step(scene, lights_, batch.results, ws, textures_, draws_.cosine_directions,
                                   lone_point_light.has_value());
  const bool controlled = controlled_step.controls_apply();
  const auto extend_generation = [&](auto& step) {
    for (std::size_t i = 0; i < ws.paths.size(); ++i)
      step.extend(i, ws.paths[i], ws.rays[i], ws.hits[i], ws.surfaces[i], ws.samples[i]);
  };
  for (int generation = 0; !ws.paths.empty(); ++generation) {
    ws.hits.resize(ws.rays.size());
    times_of_samples(
        batch.times, ws.paths, [](const Path& path) { return path.sample; }, ws.ray_times);
    backend_.intersect(ws.rays, ws.ray_times, ws.hits,
                       generation == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    ws.next_paths.clear();
    ws.next_rays.clear();
    ws.shadow_queries.clear();
    ws.shadow_rays.clear();
    ws.shadow_lights.clear();
    ws.surfaces.resize(ws.rays.size());
    make_surfaces(scene, ws.rays, ws.ray_times, ws.hits, ws.surfaces);
    if (generation < scene.render.max_depth) {
      ws.samples.draw(sampler, path_keys(batch.keys, ws), generation, draws_);
      if (lone_point_light) ws.samples.sample_lone_point_light(*lone_point_light, ws.surfaces);
    }
    if (controlled) extend_generation(controlled_step);
    else extend_generation(plain_step);

    ws.occluded.resize(ws.shadow_rays.size());
    times_of_samples(
        batch.times, ws.shadow_queries, [](const PathWorkspace::ShadowQuery& q) { return q.sample; }, ws.shadow_times);
    occluded_with_shadow_linking(backend_, scene.links, ws.shadow_rays, ws.shadow_times, ws.shadow_lights, ws.occluded,
                                 RayCoherence::kIncoherent);
    counts[RayKind::kShadow] += ws.shadow_rays.size();
    for (std::size_t i = 0; i < ws.shadow_queries.size(); ++i)
      if (!ws.occluded[i]) batch.results[ws.shadow_queries[i].sample].radiance += ws.shadow_queries[i].contribution;
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
