#pragma once
// Tracking a ray through a medium by its majorants (render/media/medium_interface.h): delta
// tracking for the path's own rays and ratio tracking for shadow rays, the null-scattering
// formulation of Miller, Georgiev and Jarosz 2019 as pbrt-v4's VolPathIntegrator has it, with one
// majorant for the three channels. Tentative collisions come at rate σ̄ (the segment's majorant);
// at each the medium's emission is added (β·ε/σ̄), then absorption, real scattering or a null
// collision is chosen with probabilities in proportion to σa, σs and σn = σ̄ − σt weighted by the
// path's throughput in each channel (Σ β_c σ_c / Σ β_c σ̄), the path weighted by σ/(σ̄ p) per
// channel: exactly analogue (weights 1) in a grey medium, unbiased in a coloured one.
//
// Random numbers: the first distance is the sampler's value for the vertex (so it keeps the
// sampler's stratification); the rest come from a counter-based stream seeded from that vertex's
// sample key, so every value stays a pure function of (pixel, sample, dimension, seed).
#include "medium.h"
#include "rtpro/core/random.h"

#include <cstdint>

namespace rtpro {

// SplitMix64 from a seed: the tracking's numbers after the first.
class TrackingRandom {
 public:
  explicit TrackingRandom(std::uint64_t seed) : state_(seed) {}
  float next() { return to_unit_float(mix64(state_++)); }

 private:
  std::uint64_t state_;
};

// A tracking walk gives up after this many tentative collisions (an absorbed path, a transmittance
// of 0): the cost of a ray is bounded even through a medium a million mean free paths thick.
inline constexpr int kMaxTrackingSteps = 1 << 20;

struct TrackedRay {
  enum class Event : std::uint8_t {
    kPassed,     // reached t_max: the path goes on to what the ray hit (or escaped to)
    kScattered,  // scattered at t: a medium vertex
    kAbsorbed,   // ended in the medium
  };
  Event event;
  float t;           // where it scattered
  float anisotropy;  // the phase function's g there
  Color beta;        // the path's throughput after the walk
  Color emitted;     // the medium's emission it collected, already weighted by the throughput
};

// Delta tracking along `ray` (unit direction) over [ray.tnear, t_max) for a path of throughput
// `beta`; `u` is the first distance's number. A medium that only absorbs attenuates in closed form
// where its kind has one, else by ratio tracking, and never scatters.
TrackedRay delta_track(const Medium& medium, const Ray& ray, float t_max, float u, TrackingRandom& random,
                       const Color& beta);

// The transmittance along `ray` (unit direction) over [ray.tnear, t_max): in closed form where the
// kind has one, else ratio tracking's unbiased estimate.
Color transmittance(const Medium& medium, const Ray& ray, float t_max, TrackingRandom& random);

// Ratio tracking's estimate (Novák et al. 2014), with pbrt-v4's Russian roulette once it falls
// below 0.05, even where a closed form exists (for tests).
Color ratio_tracking(const Medium& medium, const Ray& ray, float t_max, TrackingRandom& random);

}  // namespace rtpro
