#pragma once
// The light set's direction sampling against its own pdf, by pbrt's χ² test (bsdf_test_support.h):
// from points far from, close to, on and inside the lights of a small scene, the directions
// sample() returns are histogrammed over the sphere and compared with the pdf the path integrator
// weighs a BSDF-sampled direction by (pick probability × the light's solid-angle pdf), summed
// over every light the direction reaches. The point a direction reaches is found by intersecting
// the test's own copy of each light's surface (light_set_test_scene.h). Each run also checks that
// the pdf integrates to the pick share of the lights that send light to the point (delta lights
// take their pick probability, emitters turned away theirs).
#include "light_set.h"

#include "bsdf_test_support.h"
#include "light_set_test_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rtpro::light_set_test {

// Intersections nearer than this are the surface the point lies on, not a light it sees.
inline constexpr float kTNear = 1e-4f;
// pbrt's protocol: about a million samples per scenario, shared among its points.
inline constexpr int kSamplesPerScenario = 1'000'000;

// Where an outline crosses a cell, the cell is split whatever its quarters say down to an eighth of
// a bin (three levels; its nodes then 1/40 of a bin apart), and further only where the quarters
// disagree: a sliver thinner than that carries too few samples to matter.
inline constexpr double kForcedSplitWidth = std::numbers::pi / test::kThetaBins / 5.0;

// The angle between unit vectors.
inline double angle_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0));
}

// The angle from unit `m` to the great-circle arc from unit `a` to unit `b` (shorter than π).
inline double angle_to_arc(const Vec3& m, const Vec3& a, const Vec3& b) {
  const Vec3 n = normalize(cross(a, b));
  const Vec3 in_plane = m - n * dot(m, n);
  if (dot(in_plane, in_plane) > 1e-12f && dot(cross(a, in_plane), n) >= 0.0f && dot(cross(in_plane, b), n) >= 0.0f)
    return std::asin(std::min(1.0, std::fabs(double(dot(m, n)))));
  return std::min(angle_between(m, a), angle_between(m, b));
}

// The scene's lights as seen from one point: the sum of their pdfs for a direction, and where on
// the sphere of directions each surface's outline runs. Intersections are set up once per point
// (the render module's tests do not see the geometry module's intersectors): a direction reaches a
// polygon when it is inside the planes through the point and the polygon's edges, and a sphere by
// the quadratic; a cone around each surface's bounding sphere skips most directions.
class View {
 public:
  View(const LightSet& set, const std::vector<TestLight>& lights, const Vec3& from) : set_(set), from_(from) {
    for (const TestLight& light : lights)
      if (light.surface) targets_.push_back(target(light, index_of(set, light)));
  }

  float pdf(const Vec3& w) const {
    float sum = 0.0f;
    for (const Target& t : targets_) {
      if (dot(w, t.axis) < t.cos_max) continue;
      if (const std::optional<Vec3> point = emitting_point(t, w)) sum += set_.pdf(t.index, from_, *point);
    }
    return sum;
  }

  // Whether the outline of a surface (where the pdf jumps, or where a surface seen edge-on is a
  // sliver no quadrature node may fall on) passes through the cell of directions (θ, φ ranges).
  bool outline_crosses(double theta0, double theta1, double phi0, double phi1) const {
    if (theta1 - theta0 < kForcedSplitWidth) return false;
    const double theta_mid = 0.5 * (theta0 + theta1), phi_mid = 0.5 * (phi0 + phi1);
    const Vec3 middle = direction(theta_mid, phi_mid);
    double radius = 0.0;  // of a cap around the cell: its corners and the middles of its sides
    for (const double theta : {theta0, theta_mid, theta1})
      for (const double phi : {phi0, phi_mid, phi1})
        radius = std::max(radius, angle_between(middle, direction(theta, phi)));
    radius = 1.05 * radius + 1e-6;
    for (const Target& t : targets_) {
      for (const auto& [a, b] : t.arcs)
        if (angle_to_arc(middle, a, b) <= radius) return true;
      if (t.cone_angle >= 0.0 && std::fabs(angle_between(middle, t.cone_axis) - t.cone_angle) <= radius) return true;
    }
    return false;
  }

 private:
  struct Target {
    std::uint32_t index;
    bool two_sided;
    bool is_polygon;
    Vec3 axis;
    float cos_max = -2.0f;  // below: every direction
    // A polygon: the planes through the point and each edge, facing inwards; its plane's normal
    // (front side) and that normal · (corner − point).
    std::vector<Vec3> edge_planes;
    Vec3 front;
    float front_offset = 0.0f;
    // A sphere: its centre, the point − centre and |point − centre|² − radius².
    Vec3 center, offset;
    float c = 0.0f;
    // The outline, where the surface sends light to the point: a polygon's edges as arcs between
    // its corners' directions, or the circle a sphere's silhouette (or, from on it, its tangent
    // plane) traces (cone_angle < 0: none).
    std::vector<std::pair<Vec3, Vec3>> arcs;
    Vec3 cone_axis;
    double cone_angle = -1.0;
  };

  const LightSet& set_;
  Vec3 from_;
  std::vector<Target> targets_;

  static Vec3 direction(double theta, double phi) {
    return {static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::sin(theta) * std::sin(phi)),
            static_cast<float>(std::cos(theta))};
  }

  // The point where unit `w` first reaches the surface, if the surface emits back along it.
  std::optional<Vec3> emitting_point(const Target& t, const Vec3& w) const {
    float distance = 0.0f;
    if (t.is_polygon) {
      for (const Vec3& plane : t.edge_planes)
        if (dot(plane, w) < 0.0f) return std::nullopt;
      const float facing = dot(t.front, w);
      if (!(facing < 0.0f) && !(t.two_sided && facing > 0.0f)) return std::nullopt;
      distance = t.front_offset / facing;
    } else {
      const float half_b = dot(t.offset, w);
      const float discriminant = half_b * half_b - t.c;
      if (!(discriminant >= 0.0f)) return std::nullopt;
      const float root = std::sqrt(discriminant);
      distance = -half_b - root > kTNear ? -half_b - root : -half_b + root;
    }
    if (!(distance > kTNear)) return std::nullopt;
    const Vec3 point = from_ + w * distance;
    if (!t.is_polygon && !t.two_sided && !(dot(point - t.center, w) < 0.0f)) return std::nullopt;
    return point;
  }

  Target target(const TestLight& light, std::uint32_t index) const {
    Target t{};
    t.index = index;
    t.two_sided = light.two_sided;
    const bool sends_light = sends_light_to(light, from_);
    Vec3 center;
    float radius = 0.0f;
    if (const auto* polygon = std::get_if<TestPolygon>(&*light.surface)) {
      t.is_polygon = true;
      const std::size_t n = polygon->corners.size();
      for (const Vec3& p : polygon->corners) center += p / static_cast<float>(n);
      for (const Vec3& p : polygon->corners) radius = std::max(radius, length(p - center));
      const Vec3 to_middle = center - from_;
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 a = polygon->corners[i] - from_, b = polygon->corners[(i + 1) % n] - from_;
        const Vec3 plane = cross(a, b);
        t.edge_planes.push_back(dot(plane, to_middle) > 0.0f ? plane : -plane);
        if (sends_light) t.arcs.emplace_back(normalize(a), normalize(b));
      }
      t.front = polygon->front;
      t.front_offset = dot(t.front, polygon->corners[0] - from_);
    } else {
      const auto& ball = std::get<TestBall>(*light.surface);
      center = ball.center;
      radius = ball.radius;
      t.center = ball.center;
      t.offset = from_ - ball.center;
      t.c = dot(t.offset, t.offset) - ball.radius * ball.radius;
      const float distance = length(center - from_);
      t.cone_axis = normalize(center - from_);
      if (!sends_light) t.cone_angle = -1.0;
      else if (distance > ball.radius * 1.001f) t.cone_angle = std::asin(double(ball.radius) / distance);
      else if (distance > ball.radius * 0.999f) t.cone_angle = 0.5 * std::numbers::pi;
    }
    radius *= 1.01f;
    const float distance = length(center - from_);
    if (distance <= radius) return t;
    const float sin_max = radius / distance;
    t.axis = (center - from_) / distance;
    t.cos_max = std::sqrt(1.0f - sin_max * sin_max);
    return t;
  }
};

struct Viewpoint {
  std::string name;
  Vec3 point;
};

// How far the integral of the pdf over the sphere may be from its exact value.
inline constexpr double kIntegralTolerance = 1e-4;

// The standard deviation of the fraction of `n` samples that fall with probability `p`.
inline double binomial_sigma(double p, int n) { return std::sqrt(p * (1.0 - p) / n); }

struct Run {
  test::Chi2Outcome outcome;
  double delta_fraction = 0.0;  // of all sample() calls, those that returned a delta light
};

// One χ² run per viewpoint, at the Šidák-corrected level, ~10⁶ samples in all. Each run also
// checks the pdf's integral over the sphere against the pick share of the lights that send light
// to the point and against the fraction of samples that returned a direction, and the fraction of
// delta samples against the delta lights' share of the power.
inline void expect_light_sampler_matches_pdf(const std::string& label, const TestScene& test_scene,
                                             const std::vector<Viewpoint>& viewpoints) {
  const LightSet set(test_scene.scene());
  const std::vector<TestLight>& lights = test_scene.lights();
  ASSERT_EQ(set.lights().size(), lights.size()) << label;
  for (const TestLight& light : lights) ASSERT_NE(index_of(set, light), kInvalidId) << label << ": " << light.name;
  const int sample_count = kSamplesPerScenario / static_cast<int>(viewpoints.size());

  std::vector<std::future<Run>> runs;
  for (std::size_t v = 0; v < viewpoints.size(); ++v)
    runs.push_back(std::async(std::launch::async, [&, from = viewpoints[v].point, seed = 104729 * (v + 1)] {
      const View view(set, lights, from);
      int delta_samples = 0;
      Run run;
      run.outcome = test::chi2_test(
          [&](float u_pick, Sample2D u) -> std::optional<Vec3> {
            const std::optional<PathLightSample> s = set.sample(from, u_pick, u);
            if (!s) return std::nullopt;
            if (s->delta) {
              ++delta_samples;
              return std::nullopt;
            }
            return s->direction;
          },
          [&](const Vec3& w) { return view.pdf(w); }, sample_count, seed,
          [&](double theta0, double theta1, double phi0, double phi1) {
            return view.outline_crosses(theta0, theta1, phi0, phi1);
          });
      run.delta_fraction = static_cast<double>(delta_samples) / sample_count;
      return run;
    }));

  const double level = test::sidak_level(test::kChi2Significance, static_cast<int>(viewpoints.size()));
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    const Run run = runs[v].get();
    const test::Chi2Outcome& outcome = run.outcome;
    const Vec3& from = viewpoints[v].point;
    // The light tree picks by what each light may send to the point, not by power.
    double reaching_share = 0.0, delta_share = 0.0;
    for (const TestLight& light : lights) {
      const double share = set.pick_probability(index_of(set, light), from);
      if (sends_light_to(light, from)) reaching_share += share;
      if (light.delta()) delta_share += share;
    }
    std::ostringstream line;
    line << "[chi2] light set " << label << ", " << viewpoints[v].name << ": p=" << outcome.p_value
         << " chi2=" << outcome.chi2 << " dof=" << outcome.dof << " pdf_integral=" << outcome.pdf_integral
         << " reaching_share=" << reaching_share << " sampled=" << outcome.sampled_fraction
         << " delta=" << run.delta_fraction << " (share " << delta_share << ")\n";
    std::cout << line.str();
    SCOPED_TRACE(label + ", " + viewpoints[v].name);
    EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
    EXPECT_GE(outcome.p_value, level) << "chi2 " << outcome.chi2 << " with " << outcome.dof << " dof";
    // The integral carries only the quadrature's error (below 2e-5 here), so it pins down each
    // light's pick probability in the pdf: one light's pdf 0.3% too high already fails it. The
    // fractions carry the samples' binomial noise: five standard deviations.
    EXPECT_NEAR(outcome.pdf_integral, reaching_share, kIntegralTolerance);
    EXPECT_NEAR(outcome.sampled_fraction, outcome.pdf_integral,
                5.0 * binomial_sigma(reaching_share, sample_count) + kIntegralTolerance);
    EXPECT_NEAR(run.delta_fraction, delta_share, 5.0 * binomial_sigma(delta_share, sample_count) + 1e-6);
  }
}

}  // namespace rtpro::light_set_test
