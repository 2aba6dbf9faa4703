#pragma once
// What the path integrator asks of a participating medium: the interface each kind of
// scene/medium_kinds.h implements (registered in render/media/medium.h). The shape is
// pbrt-v4's (src/pbrt/media.h): a medium describes itself at a point, and along a ray it yields majorant segments, intervals over which one number bounds its
// extinction; the tracking (render/media/medium_tracking.h) draws tentative collisions at that rate
// and decides at each what really happened, so a medium whose density varies costs in proportion
// to how tight its majorants are, and empty space whose majorant is 0 costs nothing.
//
// A kind K's render side, in render/media/K_medium.h, declares beside its scene side's data:
//   MediumPoint medium_point(const K&, const Vec3& p);
//       its coefficients at world point p;
//   KMajorants majorants(const K&, const Ray& ray, float t_max);
//       its majorant segments along the world-space ray (unit direction, t in scene units) over
//       [ray.tnear, t_max), t_max possibly infinite: an object with
//         std::optional<MajorantSegment> next();
//       yielding segments in increasing t that do not overlap; t covered by no segment has
//       extinction 0. A homogeneous medium yields one segment, a grid one per cell its DDA visits
//       (empty cells may be skipped or yielded with sigma_maj 0);
//   bool only_absorbs(const K&);
//       it neither scatters nor emits anywhere: a path through it is attenuated, never scattered;
//   std::optional<Color> closed_form_transmittance(const K&, const Ray& ray, float t_max);
//       exp(-∫σt) over [ray.tnear, t_max) when the kind knows it without sampling (homogeneous),
//       nothing otherwise (the integrator then estimates it by ratio tracking).
#include "rtpro/core/ray.h"
#include "rtpro/core/vec3.h"

#include <concepts>
#include <optional>

namespace rtpro {

// An interval [t_min, t_max) of a ray over which sigma_maj >= σt = σa + σs in every channel.
struct MajorantSegment {
  float t_min, t_max;
  float sigma_maj;  // per scene unit
};

// The majorants of a medium bounded by one number along the whole ray: one segment, then nothing.
class SingleMajorant {
 public:
  SingleMajorant(float t_min, float t_max, float sigma_maj) : segment_{t_min, t_max, sigma_maj} {}
  std::optional<MajorantSegment> next() {
    if (done_) return std::nullopt;
    done_ = true;
    return segment_;
  }

 private:
  MajorantSegment segment_;
  bool done_ = false;
};

// A medium's coefficients at a point (per scene unit; the phase function is Henyey–Greenstein).
struct MediumPoint {
  Color sigma_a, sigma_s;
  Color emission;  // radiance added per unit length
  float anisotropy;
};

// Every function the tracking calls on a kind, each by name, so that a kind missing one stops the
// build with what it lacks rather than in the visits that call it.
template <typename Kind>
constexpr bool has_render_side() {
  static_assert(
      requires(const Kind& kind, const Vec3& p) {
        { medium_point(kind, p) } -> std::same_as<MediumPoint>;
      },
      "a medium kind needs `MediumPoint medium_point(const Kind&, const Vec3& p)` (render/media/KIND_medium.h)");
  static_assert(
      requires(const Kind& kind, const Ray& ray, float t_max) {
        { majorants(kind, ray, t_max).next() } -> std::same_as<std::optional<MajorantSegment>>;
      },
      "a medium kind needs `KindMajorants majorants(const Kind&, const Ray&, float t_max)` whose "
      "`std::optional<MajorantSegment> next()` yields its segments (render/media/KIND_medium.h)");
  static_assert(
      requires(const Kind& kind) {
        { only_absorbs(kind) } -> std::same_as<bool>;
      },
      "a medium kind needs `bool only_absorbs(const Kind&)` (render/media/KIND_medium.h)");
  static_assert(
      requires(const Kind& kind, const Ray& ray, float t_max) {
        { closed_form_transmittance(kind, ray, t_max) } -> std::same_as<std::optional<Color>>;
      },
      "a medium kind needs `std::optional<Color> closed_form_transmittance(const Kind&, const Ray&, float t_max)` "
      "(render/media/KIND_medium.h)");
  return true;
}

}  // namespace rtpro
