#include "medium_tracking.h"

#include <cmath>
#include <optional>
#include <variant>

namespace rtpro {

namespace {

float channel_sum(const Color& c) { return c.x + c.y + c.z; }

// What a walk does after a tentative collision.
enum class Step : std::uint8_t {
  kGoOn,
  kStop,          // the walk ends here
  kLeaveSegment,  // nothing further in this segment can change anything: on to the next
};

// Calls at_collision(t, point, sigma_n, inverse_sigma_maj) at each tentative collision along the
// ray over [ray.tnear, t_max), the first at the distance `u` gives, the rest from `random`.
// Returns whether the walk got to the end: false when at_collision stopped it or the step limit
// did.
template <class Kind, class AtCollision>
bool walk_collisions(const Kind& kind, const Ray& ray, float t_max, float u, TrackingRandom& random,
                     AtCollision&& at_collision) {
  auto segments = majorants(kind, ray, t_max);
  int steps = 0;
  while (const std::optional<MajorantSegment> segment = segments.next()) {
    if (!(segment->sigma_maj > 0.0f)) continue;
    const float inverse = 1.0f / segment->sigma_maj;
    float t = segment->t_min;
    for (;;) {
      t += -std::log1p(-u) * inverse;  // exponential with rate σ̄, u in [0, 1)
      u = random.next();
      if (!(t < segment->t_max)) break;
      if (++steps > kMaxTrackingSteps) return false;
      const MediumPoint point = medium_point(kind, ray.at(t));
      const Color sigma_n = max(Color(segment->sigma_maj) - point.sigma_a - point.sigma_s, Color(0.0f));
      const Step step = at_collision(t, point, sigma_n, inverse);
      if (step == Step::kStop) return false;
      if (step == Step::kLeaveSegment) break;
    }
  }
  return true;
}

template <class Kind>
Color ratio_tracking_of(const Kind& kind, const Ray& ray, float t_max, TrackingRandom& random) {
  Color transmitted(1.0f);
  const bool reached = walk_collisions(kind, ray, t_max, random.next(), random,
                                       [&](float, const MediumPoint&, const Color& sigma_n, float inverse) {
                                         transmitted = transmitted * sigma_n * inverse;
                                         // pbrt-v4's roulette: a faint estimate ends with q = 3/4,
                                         // its survivors weighted by 4.
                                         const float most = max_component(transmitted);
                                         if (!(most > 0.0f)) return Step::kStop;
                                         if (most < 0.05f) {
                                           if (random.next() < 0.75f) return Step::kStop;
                                           transmitted = transmitted * 4.0f;
                                         }
                                         return Step::kGoOn;
                                       });
  return reached ? transmitted : Color(0.0f);
}

template <class Kind>
Color transmittance_of(const Kind& kind, const Ray& ray, float t_max, TrackingRandom& random) {
  if (const std::optional<Color> closed = closed_form_transmittance(kind, ray, t_max)) return *closed;
  return ratio_tracking_of(kind, ray, t_max, random);
}

template <class Kind>
TrackedRay delta_track_of(const Kind& kind, const Ray& ray, float t_max, float u, TrackingRandom& random,
                          const Color& beta) {
  TrackedRay tracked{TrackedRay::Event::kPassed, t_max, 0.0f, beta, Color(0.0f)};
  if (only_absorbs(kind)) {
    tracked.beta = beta * transmittance_of(kind, ray, t_max, random);
    return tracked;
  }
  const bool endless = std::isinf(t_max);
  const bool reached = walk_collisions(
      kind, ray, t_max, u, random, [&](float t, const MediumPoint& point, const Color& sigma_n, float inverse) {
        Color& b = tracked.beta;
        tracked.emitted += b * point.emission * inverse;
        // Σ_c β_c σ̄ = Σ_c β_c (σa + σs + σn): the three probabilities' common denominator.
        const float scatter = channel_sum(b * point.sigma_s), null = channel_sum(b * sigma_n);
        const float all = channel_sum(b * (point.sigma_a + point.sigma_s + sigma_n));
        if (!(all > 0.0f)) return Step::kStop;
        const float p_scatter = scatter / all, p_null = null / all;
        const float xi = random.next();
        if (xi < p_scatter) {
          b = b * point.sigma_s * (inverse / p_scatter);
          tracked.event = TrackedRay::Event::kScattered;
          tracked.t = t;
          tracked.anisotropy = point.anisotropy;
          return Step::kStop;
        }
        if (xi < p_scatter + p_null) {
          // Only channels the medium does not touch carry light: along a ray without end (a world
          // medium) nothing further changes them, so the walk goes on to infinity at once.
          if (endless && p_null >= 1.0f) return Step::kLeaveSegment;
          b = b * sigma_n * (inverse / p_null);
          return Step::kGoOn;
        }
        tracked.event = TrackedRay::Event::kAbsorbed;
        return Step::kStop;
      });
  if (!reached && tracked.event == TrackedRay::Event::kPassed) tracked.event = TrackedRay::Event::kAbsorbed;
  return tracked;
}

}  // namespace

TrackedRay delta_track(const Medium& medium, const Ray& ray, float t_max, float u, TrackingRandom& random,
                       const Color& beta) {
  return std::visit([&](const auto& kind) { return delta_track_of(kind, ray, t_max, u, random, beta); }, medium);
}

Color transmittance(const Medium& medium, const Ray& ray, float t_max, TrackingRandom& random) {
  return std::visit([&](const auto& kind) { return transmittance_of(kind, ray, t_max, random); }, medium);
}

Color ratio_tracking(const Medium& medium, const Ray& ray, float t_max, TrackingRandom& random) {
  return std::visit([&](const auto& kind) { return ratio_tracking_of(kind, ray, t_max, random); }, medium);
}

}  // namespace rtpro
