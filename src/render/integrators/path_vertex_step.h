#pragma once
// One step of the path integrator's estimator, at the point a path's ray reaches (pbrt-v4's
// PathIntegrator::Li loop body, for a generation's paths side by side):
//   L += β·Le·w_b                the emission the ray found, MIS-weighted against light sampling
//   L += β·f·|cos θ|·Le·w_l/p_l  next-event estimation: a light sample, added if its shadow ray passes
//   β *= f·|cos θ|/p_b           the BSDF sample, the path's next ray if it survives Russian roulette
// In a scene with media the ray is first tracked through the media it crosses
// (path_medium_step.cpp), which may end it at a medium vertex, where the same three terms are
// taken with the phase function in place of f·|cos θ| (VolPathIntegrator's loop body).
// kLightPathControls: compiled with Cycles' controls (clamps, per-lobe depths, Filter Glossy); without
// them, a scene that sets none pays for none of their tests on its hottest loop. Both are compiled
// (path_vertex_step.cpp, path_medium_step.cpp), and PathIntegrator picks one per batch.
#include "light_set.h"
#include "medium_stack.h"
#include "medium_tracking.h"
#include "path_integrator.h"
#include "rtpro/backend/backend.h"
#include "rtpro/core/random.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/sample_result.h"
#include "rtpro/scene/render_scene.h"
#include "subsurface_medium.h"
#include "surface.h"
#include "surface_bsdf.h"
#include "vertex_samples.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace rtpro {

// The power heuristic (β = 2) for a sample of pdf `a` against the other strategy's pdf `b`.
inline float power_heuristic(float a, float b) {
  if (std::isinf(a)) return 1.0f;
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// No channel positive (NaN counts as nothing).
inline bool carries_no_light(const Color& c) { return !(c.x > 0.0f || c.y > 0.0f || c.z > 0.0f); }

// w_l, the weight of a sample of a light with an extent, of pdf `light_pdf`, against the BSDF or
// phase sampling of pdf `scatter_pdf` that could find the same direction; nothing when BSDF
// sampling alone counts.
inline std::optional<float> light_weight(PathSampling sampling, float light_pdf, float scatter_pdf) {
  switch (sampling) {
    case PathSampling::kMis: return power_heuristic(light_pdf, scatter_pdf);
    case PathSampling::kLight: return 1.0f;
    case PathSampling::kBsdf: return std::nullopt;  // BSDF samples find it
  }
  return 1.0f;
}

// Russian roulette (pbrt-v4's rule): where β·eta_scale, the throughput without the 1/η² by which
// the path's refractions scaled radiance, is below 1 in its largest channel m, the path ends with
// probability q = 1 − m and a survivor's β is divided by 1 − q; a path with m >= 1 goes on as it
// is. Read with the scale, roulette would end more than half of the paths inside glass (1/2.25 at
// ior 1.5) and give the survivors 2.25; a floor on q would multiply β by 1/(1 − q) at every bounce
// of the long chains of internal reflections in rough glass. Either spreads a white furnace,
// where every path through glass brings back exactly 1, into pixels up to 1.17 at 256 spp. A
// medium vertex scales nothing: its eta_scale is the path's. Returns whether the path goes on.
inline bool russian_roulette(Color& beta, float eta_scale, float u) {
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
inline Color clamped(const Color& contribution, float sum_limit) {
  const float sum = std::fabs(contribution.x) + std::fabs(contribution.y) + std::fabs(contribution.z);
  return sum > sum_limit ? contribution * (sum_limit / sum) : contribution;
}

// For an environment sample whose radiance and pdf were left unfound: β·f·Le·w_l/p_l clamped,
// found now in the order queue_light_sample computes it for other lights, into `out`; false when
// that sample would have been none (a direction of pdf 0) or carries nothing finite, as
// queue_light_sample queues no such sample.
bool found_environment_contribution(const PathWorkspace::ShadowQuery& query, const PathWorkspace& ws,
                                    PathSampling sampling, Color& out);

// What a shadow query adds when its ray passes, into `out`: its contribution, or an environment
// sample's found now; false when it adds nothing. Inline, and not an optional: every shadow ray
// that passes asks, and an optional<Color> returned from out of line is put together on the stack
// a field at a time and loaded back whole, a store-forwarding stall.
inline bool found_contribution(const PathWorkspace::ShadowQuery& query, const PathWorkspace& ws, PathSampling sampling,
                               Color& out) {
  if (query.unfound != PathWorkspace::kFound) return found_environment_contribution(query, ws, sampling, out);
  out = query.contribution;
  return true;
}

class SpawnOrigins;  // render/surface/ray_offset.h

template <bool kLightPathControls>
class PathVertexStep {
 public:
  using Path = PathWorkspace::Path;

  // `cosine_directions`: the vertices' samples hold their Lambert directions (VertexDraws);
  // `lone_point_light`: they hold their light samples (GenerationSamples::lone_light_sample);
  // `records_motion`: the camera hits' film motion is read (the motion AOV).
  PathVertexStep(const RenderScene& scene, const Backend& backend, const LightSet& lights,
                 std::span<SampleResult> results, PathWorkspace& ws, const TextureLookup* textures,
                 bool cosine_directions, bool lone_point_light, bool records_motion);

  // Whether the scene sets any of Cycles' controls this step is compiled for.
  bool controls_apply() const { return clamping_ || lobe_limits_ || filtering_glossy_; }

  // The step of a path whose ray travels in no medium but the vacuum: what the ray reaches, a
  // light without geometry, the environment, or a surface. `vertex`: the path's place in the
  // generation; `sp` the surface of a valid hit (make_surfaces), unread otherwise; `u` the vertex's
  // random numbers, read only below max_depth. Flattened: its helpers (the light sample's queueing,
  // the clamps, the path's copy) are worth the call they would otherwise cost at every vertex of
  // every path (path_vertex_step.cpp).
  [[gnu::flatten]] void extend(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit,
                               const SurfacePoint& sp, const VertexSamples& u);

  // The step in a scene with media: the ray tracked through the media and interfaces it crosses,
  // up to what it reaches (extend, with the path's throughput and media there) or a medium vertex
  // (path_medium_step.cpp). `u` is read at every generation: the tracking's first number.
  void extend_through_media(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit,
                            const SurfacePoint& sp, const VertexSamples& u);

 private:
  // A medium vertex at `position`, the ray having travelled along unit `direction`.
  void scatter_in_medium(std::size_t vertex, const Path& path, const Vec3& position, const Vec3& direction,
                         const TrackedRay& tracked, const MediumStack& media, const VertexSamples& u);
  // The random walk under the surface `sp` after its subsurface sample `entry`, and the path's
  // next ray from where the walk leaves (path_subsurface_step.cpp).
  void walk_under_surface(std::size_t vertex, const Path& path, const SurfacePoint& sp, const BsdfSample& entry,
                          const VertexSamples& u, const Color& beta, const MediumStack& media, bool aov_pending);
  // The seed of the vertex's tracking numbers after the first (render/media/medium_tracking.h).
  std::uint64_t tracking_seed(std::size_t vertex, const VertexSamples& u) const {
    const SampleKey& key = ws_.path_keys[vertex];
    return hash_combine(hash_combine(key.pixel_key, static_cast<std::uint64_t>(key.sample_index)),
                        std::bit_cast<std::uint32_t>(u.medium));
  }
  // A shadow ray's start in a scene with media, queued beside it.
  void queue_medium_shadow(const MediumStack& media, std::uint64_t seed, std::uint32_t light) {
    ws_.medium_shadows.push_back({media, seed, light < scene_.lights.size() ? light : kInvalidId});
  }

  // Whether the vertex adds its emission and nothing more: the path has made max_depth bounces,
  // or as many of one lobe kind (or of phase function samples) as that kind's limit (Cycles'
  // per-kind bounce limits, which end a path at the vertex after the bounce that reached one).
  bool ends_here(const Path& path) const {
    if (path.bounce >= max_depth_) return true;
    return kLightPathControls && lobe_limits_ &&
           (path.diffuse_bounces >= depths_.diffuse || path.glossy_bounces >= depths_.glossy ||
            path.transmission_bounces >= depths_.transmission || path.volume_bounces >= depths_.volume);
  }

  // Cycles' Filter Glossy (path_vertex_step.cpp).
  void filter_glossy(const Path& path, Bsdf& bsdf) const;

  // The clamp of light reaching the camera through the ray that found it: direct for the camera
  // ray and the first vertex's rays (at most one scattering), indirect after.
  float emission_limit(const Path& path) const { return path.bounce <= 1 ? direct_limit_ : indirect_limit_; }
  Color clamp(const Color& contribution, float sum_limit) const {
    return kLightPathControls && clamping_ ? clamped(contribution, sum_limit) : contribution;
  }

  // w_b, the weight of emission a BSDF or phase sample found: in full after the camera or a
  // specular vertex, else against the light sampling that could have found the same point, whose
  // pdf `light_pdf()` gives (asked only under MIS).
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
  // w_l, the weight of a light sample of pdf `light_pdf` against the BSDF or phase sampling of
  // pdf `scatter_pdf` that could find the same direction; nothing when BSDF sampling alone counts.
  std::optional<float> light_sample_weight(const PathLightSample& ls, float scatter_pdf) const;

  void add_emission(const Path& path, SampleResult& result, const Color& radiance, std::uint32_t light,
                    const Vec3& on_light, const Color& beta);
  void add_escaped_light(const Path& path, const Ray& ray, SampleResult& result);
  const PathLightSample* sample_light(std::size_t vertex, const Vec3& position, const VertexSamples& u,
                                      std::uint32_t group, EnvironmentRadiance environment);
  void queue_light_sample(std::uint32_t sample, SpawnOrigins& origins, const SurfaceBsdf& surface, const Vec3& wo,
                          const PathLightSample& ls, const Color& beta, float clamp_limit);
  // Queues a shadow ray with what it adds when it passes.
  void queue_shadow(std::uint32_t sample, const Color& contribution, const Ray& ray, std::uint32_t light);

  const RenderScene& scene_;
  const Backend& backend_;
  const LightSet& lights_;
  std::span<SampleResult> results_;
  PathWorkspace& ws_;
  const TextureLookup* textures_;
  bool cosine_directions_;
  bool lone_point_light_;
  bool records_motion_;
  bool has_media_;
  // The current vertex's BSDF and light sample, filled in place (material_bsdf, LightSet::sample).
  SurfaceBsdf surface_;
  PathLightSample light_sample_;
  SurfacePoint exit_surface_;  // where a walk under a surface leaves
  SubsurfaceMediumCache subsurface_media_;
  LobeDepths depths_;
  float direct_limit_, indirect_limit_;  // clamp_sum_limit of the clamps
  bool clamping_;                        // either clamp on: a contribution's sum is worth computing
  float filter_glossy_;                  // 0: off
  int max_depth_;
  // Work only some scenes ask for: the per-kind counts (a limit below max_depth), Filter Glossy.
  bool lobe_limits_;
  bool filtering_glossy_;
};

// Shadow rays nearer than this fraction of the way to a sampled point stop short of it, so the
// emitter's own surface (or a light's) does not occlude the point sampled on it.
inline constexpr float kShadowEpsilon = 1e-4f;

}  // namespace rtpro
