#include "subsurface_walk.h"

#include "hg_phase.h"

#include <cmath>

namespace rtpro {

namespace {

constexpr float kThroughputEpsilon = 1e-6f;

Color exp(const Color& c) { return {std::exp(c.x), std::exp(c.y), std::exp(c.z)}; }
float sum(const Color& c) { return c.x + c.y + c.z; }

// The channel whose σt places the next flight, in proportion to throughput × albedo, and the
// probabilities of all three (uniform when every weight is 0).
int choose_channel(const Color& throughput, const Color& albedo, float u, Color& probability) {
  const Color weights = abs(throughput * albedo);
  const float total = sum(weights);
  probability = total > 0.0f ? weights / total : Color(1.0f / 3.0f);
  float cumulative = 0.0f;
  for (int c = 0; c < 2; ++c) {
    cumulative += probability[c];
    if (u < cumulative) return c;
  }
  return 2;
}

}  // namespace

std::optional<SubsurfaceExit> subsurface_walk(const Backend& backend, const SubsurfaceMedium& medium, const Ray& entry,
                                              std::optional<float> time, const Color& beta, TrackingRandom& random) {
  const Color sigma_s = medium.sigma_t * medium.albedo;
  // The similarity relation's isotropic medium, for the walk's later flights.
  const Color sigma_s_star = sigma_s * (1.0f - medium.anisotropy);
  const Color sigma_t_star = medium.sigma_t - sigma_s + sigma_s_star;
  Color throughput = beta * medium.weight;
  Ray ray = entry;
  for (int step = 0; step < kMaxWalkSteps; ++step) {
    const bool similar = step > kSimilarityBounces;
    const Color& sigma_t = similar ? sigma_t_star : medium.sigma_t;
    const Color& scattering = similar ? sigma_s_star : sigma_s;
    if (step > 0) {
      const float u1 = random.next();
      ray.dir = sample_henyey_greenstein(ray.dir, similar ? 0.0f : medium.anisotropy, {u1, random.next()}).outgoing;
    }
    Color probability;
    const int channel = choose_channel(throughput, medium.albedo, random.next(), probability);
    float t = -std::log1p(-random.next()) / sigma_t[channel];
    ray.tfar = t;
    Hit hit;
    const bool leaves = (time ? backend.intersect(ray, *time, hit) : backend.intersect(ray, hit)) && hit.valid();
    if (leaves) t = hit.t;
    // Per channel, the density of this flight (a collision at t, or passing t where it left),
    // combined over the channels by the balance heuristic.
    const Color transmittance = exp(sigma_t * -t);
    const Color density = leaves ? transmittance : sigma_t * transmittance;
    throughput = throughput * (leaves ? transmittance : scattering * transmittance) / sum(probability * density);
    if (leaves) return SubsurfaceExit{ray, hit, throughput};
    if (!is_finite(throughput) || max_component(throughput) < kThroughputEpsilon) return std::nullopt;
    ray.org = ray.at(t);
    ray.tnear = 0.0f;
  }
  return std::nullopt;
}

}  // namespace rtpro
