// The path integrator's steps in a scene with media (path_vertex_step.h): a ray tracked through
// the media and interfaces it crosses, and the vertices where it scatters in a medium.
#include "path_vertex_step.h"

#include "hg_phase.h"
#include "light_linking.h"
#include "rtpro/core/append_ray.h"
#include "rtpro/core/random.h"

#include <cmath>
#include <limits>

namespace rtpro {

namespace {

// A ray crosses at most this many interfaces before what it reaches counts as an opaque surface:
// a bound on its cost however the scene nests its boundaries.
constexpr int kMaxInterfaceCrossings = 256;

constexpr float kEndless = std::numeric_limits<float>::infinity();

// `ray` with a unit direction, its parameters in scene units (the tracking's convention).
Ray unit_ray(const Ray& ray) {
  const float length = rtpro::length(ray.dir);
  return Ray{ray.org, ray.tnear * length, ray.dir * (1.0f / length), kEndless};
}

}  // namespace

template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::extend_through_media(std::size_t vertex, const Path& path, const Ray& ray,
                                                              const Hit& hit, const SurfacePoint& sp,
                                                              const VertexSamples& u) {
  Color beta = path.beta;
  MediumStack media = path.media;
  TrackingRandom random(tracking_seed(vertex, u));
  float u_first = u.medium;
  Ray segment = ray;
  Hit reached = hit;
  SurfacePoint beyond;  // the surface past the interfaces crossed, once one is
  const SurfacePoint* surface = &sp;
  for (int crossings = 0;; ++crossings) {
    const float t_end = reached.valid() ? reached.t : segment.tfar;
    const std::optional<LightSet::SeenLight> seen = lights_.seen_light(segment, t_end, path.group);
    const std::uint32_t medium = media.current(scene_.world_medium);
    if (medium != kNoMedium) {
      const Ray unit = unit_ray(segment);
      const float scale = length(segment.dir);
      const TrackedRay tracked =
          delta_track(scene_.media[medium], unit, (seen ? seen->t : t_end) * scale, u_first, random, beta);
      if (!carries_no_light(tracked.emitted))
        results_[path.sample].radiance += clamp(tracked.emitted, emission_limit(path));
      switch (tracked.event) {
        case TrackedRay::Event::kAbsorbed: return;
        case TrackedRay::Event::kScattered:
          scatter_in_medium(vertex, path, unit.at(tracked.t), unit.dir, tracked, media, u);
          return;
        case TrackedRay::Event::kPassed: beta = tracked.beta; break;
      }
      if (carries_no_light(beta)) return;
      u_first = random.next();
    }
    if (seen || !reached.valid() || crossings == kMaxInterfaceCrossings) break;
    const Material& material = scene_.materials[surface->material];
    if (!material.index_matched) break;
    // An interface: into or out of its medium, and on along the same ray past it.
    media.cross(*material.interior, surface->front_face);
    segment.tnear = std::nextafter(reached.t, kEndless);
    // The path's time (an open shutter), so moving shapes are met where its other rays meet them.
    const float time = ws_.ray_times.empty() ? 0.0f : ws_.ray_times[vertex];
    if (!(segment.tnear < segment.tfar) || !backend_.intersect(segment, time, reached)) reached = Hit{};
    if (reached.valid()) {
      if (ws_.ray_times.empty()) make_surface(scene_, segment, reached, beyond);
      else make_surface_at(scene_, segment, time, reached, beyond);
      surface = &beyond;
    }
  }
  Path through = path;
  through.beta = beta;
  through.media = media;
  extend(vertex, through, segment, reached, *surface, u);
}

template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::scatter_in_medium(std::size_t vertex, const Path& path, const Vec3& position,
                                                           const Vec3& direction, const TrackedRay& tracked,
                                                           const MediumStack& media, const VertexSamples& u) {
  if (ends_here(path)) return;
  const float g = tracked.anisotropy;
  const Color& beta = tracked.beta;  // σs/σ̄ already taken: the phase function is all that is left
  const std::uint64_t seed = tracking_seed(vertex, u);
  // Next-event estimation: β·p·Le·w_l/p_l, its shadow ray ratio-tracked from here.
  constexpr std::uint32_t kGroup = 0;  // a medium is no object: every light illuminates it
  if (!lights_.empty(kGroup))
    if (const PathLightSample* ls = sample_light(vertex, position, u, kGroup, EnvironmentRadiance::kNow)) {
      const float phase = henyey_greenstein(dot(direction, ls->direction), g);
      const std::optional<float> w_l = light_sample_weight(*ls, phase);
      const Color contribution = clamp(beta * ls->radiance * (w_l.value_or(0.0f) * phase / ls->pdf),
                                       path.bounce == 0 ? direct_limit_ : indirect_limit_);
      if (w_l && is_finite(contribution) && !carries_no_light(contribution)) {
        const bool infinite = std::isinf(ls->distance);
        const Ray shadow{position, 0.0f, infinite ? ls->direction : ls->direction * ls->distance,
                         infinite ? kEndless : 1.0f - kShadowEpsilon};
        queue_shadow(path.sample, contribution, shadow, ls->light);
        queue_medium_shadow(media, seed ^ 0x5ad0, ls->light);
      }
    }

  // The phase function sample: p/pdf = 1, so β stays; Russian roulette as at a surface, with
  // the path's eta_scale (a medium vertex refracts nothing).
  const PhaseSample ps = sample_henyey_greenstein(direction, g, u.bsdf_direction);
  Color next_beta = beta;
  if (path.bounce >= kRouletteStart && !russian_roulette(next_beta, path.eta_scale, u.roulette)) return;
  if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
  Path& next = ws_.next_paths.emplace_back(path.bounced(next_beta, position, ps.pdf));
  next.group = kGroup;
  next.media = media;
  if (kLightPathControls && filtering_glossy_) next.min_pdf = std::min(path.min_pdf, ps.pdf);
  if (kLightPathControls && lobe_limits_) ++next.volume_bounces;
  append_ray(ws_.next_rays, Ray{position, 0.0f, ps.outgoing, kEndless});
}

// The members defined here, for both of PathIntegrator's steps (path_vertex_step.cpp instantiates
// the rest).
template void PathVertexStep<true>::extend_through_media(std::size_t, const Path&, const Ray&, const Hit&,
                                                         const SurfacePoint&, const VertexSamples&);
template void PathVertexStep<false>::extend_through_media(std::size_t, const Path&, const Ray&, const Hit&,
                                                          const SurfacePoint&, const VertexSamples&);

}  // namespace rtpro
