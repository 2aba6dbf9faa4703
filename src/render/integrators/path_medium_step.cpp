// The path integrator's steps in a scene with media (path_vertex_step.h): a ray tracked through
// the media and interfaces it crosses, and the vertices where it scatters in a medium.
#include "path_vertex_step.h"

#include "hg_phase.h"
#include "light_linking.h"
#include "rtpro/core/append_ray.h"
#include "rtpro/core/random.h"

#include <bit>
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

std::uint64_t PathVertexStep::tracking_seed(std::size_t vertex, const VertexSamples& u) const {
  const SampleKey& key = ws_.path_keys[vertex];
  return hash_combine(hash_combine(key.pixel_key, static_cast<std::uint64_t>(key.sample_index)),
                      std::bit_cast<std::uint32_t>(u.medium));
}

void PathVertexStep::queue_medium_shadow(const MediumStack& media, std::uint64_t seed, std::uint32_t light) {
  ws_.medium_shadows.push_back({media, seed, light < scene_.lights.size() ? light : kInvalidId});
}

void PathVertexStep::extend_through_media(std::size_t vertex, const Path& path, const Ray& ray, const Hit& hit,
                                          const SurfacePoint& sp, const VertexSamples& u) {
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
    if (!(segment.tnear < segment.tfar) || !backend_.intersect(segment, reached)) reached = Hit{};
    if (reached.valid()) {
      make_surface(scene_, segment, reached, beyond);
      surface = &beyond;
    }
  }
  reach(vertex, path, segment, reached, *surface, u, beta, media);
}

void PathVertexStep::scatter_in_medium(std::size_t vertex, const Path& path, const Vec3& position,
                                       const Vec3& direction, const TrackedRay& tracked, const MediumStack& media,
                                       const VertexSamples& u) {
  if (ends_here(path)) return;
  const float g = tracked.anisotropy;
  const Color& beta = tracked.beta;  // σs/σ̄ already taken: the phase function is all that is left
  const std::uint64_t seed = tracking_seed(vertex, u);
  // Next-event estimation: β·p·Le·w_l/p_l, its shadow ray ratio-tracked from here.
  constexpr std::uint32_t kGroup = 0;  // a medium is no object: every light illuminates it
  if (!lights_.empty(kGroup))
    if (const PathLightSample* ls = sample_light(vertex, position, u, kGroup)) {
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

  // The phase function sample: p/pdf = 1, so β stays; Russian roulette as at a surface.
  const PhaseSample ps = sample_henyey_greenstein(direction, g, u.bsdf_direction);
  Color next_beta = beta;
  if (!survives_roulette(path.bounce, u.roulette, next_beta)) return;
  if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
  Path& next = ws_.next_paths.emplace_back(path);
  next.bounce = path.bounce + 1;
  next.beta = next_beta;
  next.origin = position;
  next.bsdf_pdf = ps.pdf;
  next.specular = false;
  next.transmitted = false;
  next.media = media;
  next.group = kGroup;
  next.min_pdf = std::min(path.min_pdf, ps.pdf);
  ++next.volume_bounces;
  append_ray(ws_.next_rays, Ray{position, 0.0f, ps.outgoing, kEndless});
}

}  // namespace rtpro
