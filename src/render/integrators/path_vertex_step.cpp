#include "path_vertex_step.h"

#include "film_motion.h"
#include "rtpro/core/append_ray.h"
#include "lambert_fast_paths.h"
#include "light_linking.h"
#include "material_bsdf.h"
#include "ray_offset.h"
#include "texture.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace rtpro {

namespace {

using Path = PathWorkspace::Path;

// The path's bounce counts after one more of kind `lobe`.
void count_bounce(BsdfLobe lobe, Path& next) {
  switch (lobe) {
    case BsdfLobe::kDiffuse: ++next.diffuse_bounces; return;
    case BsdfLobe::kGlossy: ++next.glossy_bounces; return;
    case BsdfLobe::kTransmission: ++next.transmission_bounces; return;
    case BsdfLobe::kSubsurface: return;  // the walk's exit counts its own bounce
  }
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

}  // namespace

template <bool kLightPathControls>
PathVertexStep<kLightPathControls>::PathVertexStep(const RenderScene& scene, const Backend& backend,
                                                   const LightSet& lights, std::span<SampleResult> results,
                                                   PathWorkspace& ws, const TextureLookup* textures,
                                                   bool cosine_directions, bool lone_point_light, bool records_motion)
    : scene_(scene), backend_(backend), lights_(lights), results_(results), ws_(ws), textures_(textures),
      cosine_directions_(cosine_directions), lone_point_light_(lone_point_light), records_motion_(records_motion),
      has_media_(!scene.media.empty()), depths_(lobe_depths(scene.render)),
      direct_limit_(clamp_sum_limit(scene.render.path.clamp_direct)),
      indirect_limit_(clamp_sum_limit(scene.render.path.clamp_indirect)),
      clamping_(scene.render.path.clamp_direct > 0.0f || scene.render.path.clamp_indirect > 0.0f),
      filter_glossy_(scene.render.path.filter_glossy), max_depth_(scene.render.max_depth),
      lobe_limits_(depths_.diffuse < max_depth_ || depths_.glossy < max_depth_ || depths_.transmission < max_depth_ ||
                   depths_.volume < max_depth_),
      filtering_glossy_(filter_glossy_ > 0.0f) {}

template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::extend(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit,
                                                const SurfacePoint& sp, const VertexSamples& u) {
  const Color& beta = path.beta;
  SampleResult& result = results_[path.sample];
  // Le the ray reaches: a light without geometry before the surface, the environment, or the
  // surface's own emission.
  const float t_hit = hit.valid() ? hit.t : ray.tfar;
  if (const std::optional<LightSet::SeenLight> seen = lights_.seen_light(ray, t_hit, path.group)) {
    add_emission(path, result, seen->radiance, seen->index, ray.at(seen->t), beta);
    return;  // lights without geometry absorb what reaches them
  }
  if (!hit.valid()) {
    add_escaped_light(path, ray, result);
    return;
  }
  const Material& material = scene_.materials[sp.material];
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
  if (records_motion_ && path.bounce == 0)
    result.primary.motion = film_motion(scene_, hit, ws_.ray_times.empty() ? 0.0f : ws_.ray_times[vertex], sp.position);
  if (ends_here(path)) return;

  // The reciprocal length multiplied through: one division, not normalize's three.
  const Vec3 wo = surface.frame.to_local(ray.dir * (-1.0f / length(ray.dir)));
  SpawnOrigins origins(sp);
  // Next-event estimation, where the BSDF is not purely specular; in a scene with media its
  // shadow ray starts in the medium on its side of the surface.
  if (!delta && !lights_.empty(group))
    // Outside media a shadow ray is passed or stopped: an environment sample's radiance and pdf wait.
    if (const PathLightSample* light = sample_light(
            vertex, sp.position, u, group, has_media_ ? EnvironmentRadiance::kNow : EnvironmentRadiance::kLater)) {
      const std::size_t queued = ws_.shadow_queries.size();
      queue_light_sample(path.sample, origins, surface, wo, *light, beta,
                         path.bounce == 0 ? direct_limit_ : indirect_limit_);
      if (has_media_ && ws_.shadow_queries.size() > queued) {
        MediumStack shadow_media = path.media;
        if (material.interior && dot(light->direction, sp.geometric_normal) < 0.0f)
          shadow_media.cross(*material.interior, sp.front_face);
        queue_medium_shadow(shadow_media, tracking_seed(vertex, u) ^ 0x5ad0, light->light);
      }
    }

  // The BSDF sample: β·f·|cos θ|/p_b, then Russian roulette (russian_roulette).
  const std::optional<BsdfSample> bs = sample_bsdf(surface.bsdf, wo, u, cosine_directions_);
  if (!bs || !(bs->pdf > 0.0f) || carries_no_light(bs->f)) return;
  if (bs->lobe == BsdfLobe::kSubsurface)
    return walk_under_surface(vertex, path, sp, *bs, u, beta, path.media, aov_pending);
  Color next_beta = beta * bs->f * (std::fabs(bs->wi.z) / bs->pdf);
  const float eta_scale = bs->transmitted ? path.eta_scale * (bs->eta * bs->eta) : path.eta_scale;
  if (path.bounce >= kRouletteStart && !russian_roulette(next_beta, eta_scale, u.roulette)) return;
  if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
  // The path's next ray, inside the medium it was refracted into, or outside it again.
  const Vec3 direction = surface.frame.to_world(bs->wi);
  Path& next = ws_.next_paths.emplace_back(path.bounced(next_beta, sp.position, bs->pdf));
  next.eta_scale = eta_scale;
  next.group = group;
  next.specular = bs->delta;
  next.aov_pending = aov_pending;
  next.transmitted = bs->transmitted;
  if (has_media_ && bs->transmitted && material.interior) next.media.cross(*material.interior, sp.front_face);
  // A delta sample's pdf is the lobe's probability, not a density: it roughens nothing.
  if (kLightPathControls && filtering_glossy_ && !bs->delta) next.min_pdf = std::min(path.min_pdf, bs->pdf);
  if (kLightPathControls && lobe_limits_) count_bounce(bs->lobe, next);
  append_ray(ws_.next_rays, spawn_ray(origins, direction));
}

// Cycles' Filter Glossy: after BSDF samples of small pdf (diffuse or rough bounces), the
// vertex's microfacet lobes are given GGX α >= 0.5·sqrt(1 − p_min / filter_glossy), so a sharp
// highlight seen through a diffuse bounce becomes a blur the BSDF samples find, not a caustic
// only rare samples do. Off (0), or after the camera and delta bounces only, nothing changes.
template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::filter_glossy(const Path& path, Bsdf& bsdf) const {
  if (kLightPathControls && filtering_glossy_ && path.min_pdf < filter_glossy_)
    roughen_bsdf(bsdf, 0.5f * std::sqrt(1.0f - path.min_pdf / filter_glossy_));
}

template <bool kLightPathControls>
std::optional<float> PathVertexStep<kLightPathControls>::light_sample_weight(const PathLightSample& ls,
                                                                             float scatter_pdf) const {
  if (ls.delta) return 1.0f;  // only light sampling finds a delta light
  return light_weight(scene_.render.path_sampling, ls.pdf, scatter_pdf);
}

// L += β·Le·w_b for the radiance Le emitted at `on_light` (of light `light`, kInvalidId for an
// emitter light sampling never picks: that counts in full).
template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::add_emission(const Path& path, SampleResult& result, const Color& radiance,
                                                      std::uint32_t light, const Vec3& on_light, const Color& beta) {
  const float w_b = light == kInvalidId ? 1.0f : bsdf_sample_weight(path, [&] {
    return lights_.pdf(light, path.origin, on_light, path.group);
  });
  result.radiance += clamp(beta * radiance * w_b, emission_limit(path));
}

// A ray that leaves the scene: the environment, weighted as emission is, or the background.
// Camera rays see the background where the environment is not visible.
template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::add_escaped_light(const Path& path, const Ray& ray, SampleResult& result) {
  const EnvironmentLight* environment = lights_.environment();
  if (!environment || (path.bounce == 0 && !environment->visible())) {
    result.radiance += clamp(path.beta * scene_.render.background, emission_limit(path));
    return;
  }
  const EnvironmentLight::ImageCoordinates uv = environment->image_coordinates(ray.dir);
  const Color radiance = environment->radiance_at(uv);
  const float w_b = bsdf_sample_weight(path, [&] { return lights_.environment_pdf_at(uv, path.group); });
  result.radiance += clamp(path.beta * radiance * w_b, emission_limit(path));
}

// A point on a light for next-event estimation: the lone point light's sample, made for the
// whole generation, or the light set's pick and sample with the vertex's numbers. Null when
// the light sends nothing there.
template <bool kLightPathControls>
const PathLightSample* PathVertexStep<kLightPathControls>::sample_light(std::size_t vertex, const Vec3& position,
                                                                        const VertexSamples& u, std::uint32_t group,
                                                                        EnvironmentRadiance environment) {
  if (lone_point_light_) return ws_.samples.lone_light_sample(vertex);
  return lights_.sample(position, u.choices.x, u.light_point, textures_, group, light_sample_, environment)
             ? &light_sample_
             : nullptr;
}

// β·f·|cos θ|·Le·w_l/p_l of a light sample, queued with its shadow ray: added when that passes.
// `clamp_limit`: the vertex's (clamped).
template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::queue_light_sample(std::uint32_t sample, SpawnOrigins& origins,
                                                            const SurfaceBsdf& surface, const Vec3& wo,
                                                            const PathLightSample& ls, const Color& beta,
                                                            float clamp_limit) {
  const Vec3 wi = surface.frame.to_local(ls.direction);
  const Color f = eval_bsdf(surface.bsdf, wo, wi) * std::fabs(wi.z);
  if (carries_no_light(f)) return;
  const float scatter_pdf = ls.delta ? 0.0f : bsdf_pdf(surface.bsdf, wo, wi);
  Color contribution;
  if (ls.environment) {
    // β·f now, the rest once the shadow ray passes (found_contribution), in the same order; its
    // weight depends on its pdf only where BSDF samples do not find it alone.
    if (scene_.render.path_sampling == PathSampling::kBsdf) return;  // BSDF samples alone find it
    contribution = beta * f;
    // clamped() leaves everything below an infinite limit as it is, as clamp() does unclamped.
    const float limit = kLightPathControls && clamping_ ? clamp_limit : std::numeric_limits<float>::infinity();
    ws_.unfound_lights.push_back({ls.environment, ls.direction, ls.pdf, scatter_pdf, limit});
  } else {
    const std::optional<float> w_l = light_sample_weight(ls, scatter_pdf);
    if (!w_l) return;
    contribution = clamp(beta * f * ls.radiance * (*w_l / ls.pdf), clamp_limit);
    if (!is_finite(contribution) || carries_no_light(contribution)) return;
  }
  Ray ray;
  if (std::isinf(ls.distance)) {
    ray = spawn_ray(origins, ls.direction);
  } else {
    ray = spawn_ray_to(origins, origins.surface().position + ls.direction * ls.distance);
    ray.tfar = 1.0f - kShadowEpsilon;
  }
  queue_shadow(sample, contribution, ray, ls.light);
  if (ls.environment) ws_.shadow_queries.back().unfound = static_cast<std::uint32_t>(ws_.unfound_lights.size() - 1);
}

bool found_environment_contribution(const PathWorkspace::ShadowQuery& query, const PathWorkspace& ws,
                                    PathSampling sampling, Color& out) {
  const PathWorkspace::UnfoundLight& light = ws.unfound_lights[query.unfound];
  // EnvironmentLight::sample's pdf and radiance, then LightSet::sample's pick.
  const EnvironmentLight::ImageCoordinates uv = light.environment->image_coordinates(light.direction);
  float pdf = light.environment->pdf_at(uv);
  if (!(pdf > 0.0f) || !std::isfinite(pdf)) return false;
  pdf *= light.pick_pmf;
  const std::optional<float> w_l = light_weight(sampling, pdf, light.scatter_pdf);
  if (!w_l) return false;
  const Color contribution =
      clamped(query.contribution * light.environment->radiance_at(uv) * (*w_l / pdf), light.clamp_limit);
  if (!is_finite(contribution) || carries_no_light(contribution)) return false;
  out = contribution;
  return true;
}

template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::queue_shadow(std::uint32_t sample, const Color& contribution, const Ray& ray,
                                                      std::uint32_t light) {
  ws_.shadow_queries.push_back({sample, contribution});
  append_ray(ws_.shadow_rays, ray);
  // Read only under light linking (occluded_with_shadow_linking).
  if (scene_.links.linked()) ws_.shadow_lights.push_back(light < scene_.lights.size() ? light : kInvalidId);
}

template class PathVertexStep<true>;
template class PathVertexStep<false>;

}  // namespace rtpro
