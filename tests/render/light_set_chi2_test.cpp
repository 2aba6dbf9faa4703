// The light set's direction sampling against its own pdf, by pbrt's χ² test (bsdf_test_support.h):
// from points far from, close to, on and inside the lights of small scenes, the directions
// sample() returns are histogrammed over the sphere and compared with the pdf the path integrator
// weighs a BSDF-sampled direction by (pick probability × the light's solid-angle pdf), summed
// over every light the direction reaches. The test knows each light's world-space geometry itself
// (instances placed by their transforms, fronts where the surface's own normal points) and finds
// the point a direction reaches by intersecting it. Also: the pdf integrates to the pick share of
// the lights that send light to the point (delta lights take their pick probability, emitters
// turned away theirs), and lights are picked in proportion to their power.
#include "light_set.h"

#include "rtpro/core/transform.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <future>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rtpro {
namespace light_set_chi2_test {

constexpr double kPi = std::numbers::pi;
constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Intersections nearer than this are the surface the point lies on, not a light it sees.
constexpr float kTNear = 1e-4f;
// pbrt's protocol: about a million samples per scenario, shared among its points.
constexpr int kSamplesPerScenario = 1'000'000;

double average(const Color& c) { return (double(c.x) + c.y + c.z) / 3.0; }

Emission emission(const Color& radiance, bool two_sided) {
  Emission e;
  e.radiance = radiance;
  e.two_sided = two_sided;
  return e;
}

// Emitting surfaces in world space: a triangle or a parallelogram (corners in order around it;
// `front`, of any length, the side it emits to when one-sided), or a sphere (one-sided: outwards).
struct TestPolygon {
  std::vector<Vec3> corners;
  Vec3 front;
};
struct TestBall {
  Vec3 center;
  float radius;
};
using TestSurface = std::variant<TestPolygon, TestBall>;

// A light as the test knows it: its surface (none for a point light), how the light set names it
// and the power it emits.
struct TestLight {
  std::string name;
  std::optional<TestSurface> surface;
  bool two_sided = false;
  double power = 0.0;
  std::optional<Ray> seen_by;  // a ray that sees a light without geometry (seen_light), or
  Hit hit;                     // the primitive a ray that reaches an emissive surface hits

  bool delta() const { return !surface; }
};

// A small scene and what the test knows of its lights, built side by side.
class TestScene {
 public:
  void add_point_light(const Vec3& position, const Color& intensity) {
    scene_.lights.push_back(PointLight{position, intensity});
    lights_.push_back({"point", std::nullopt, false, 4.0 * kPi * average(intensity), std::nullopt, Hit{}});
  }

  void add_quad_light(const Vec3& corner, const Vec3& edge1, const Vec3& edge2, const Color& radiance) {
    const Vec3 n = cross(edge1, edge2);
    const float area = length(n);
    scene_.lights.push_back(QuadLight{corner, edge1, edge2, n / area, area, radiance, 1});
    const Vec3 middle = corner + (edge1 + edge2) * 0.5f;
    lights_.push_back({"quad", TestPolygon{{corner, corner + edge1, corner + edge1 + edge2, corner + edge2}, n}, false,
                       kPi * area * average(radiance), Ray{middle + n / area, 0.0f, -n / area}, Hit{}});
  }

  void add_sphere_light(const Vec3& center, float radius, const Color& radiance) {
    scene_.lights.push_back(SphereLight{center, radius, radiance, 1});
    const Vec3 outside = center + Vec3(0.0f, 0.0f, 2.0f * radius);
    lights_.push_back({"sphere light", TestBall{center, radius}, false,
                       kPi * 4.0 * kPi * double(radius) * radius * average(radiance),
                       Ray{outside, 0.0f, Vec3(0.0f, 0.0f, -1.0f)}, Hit{}});
  }

  // One top-level mesh; each triangle emits what its material does (a black emission: not at all).
  void add_mesh(const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<Emission>& emissions) {
    TriangleMesh mesh;
    Hit hit;
    hit.geom_id = static_cast<std::uint32_t>(scene_.top.geometries.size());
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
      for (const Vec3& p : triangles[t]) mesh.vertices.push_back({p.x, p.y, p.z, 0.0f});
      mesh.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
      mesh.triangle_materials.push_back(add_material(emissions[t]));
      hit.prim_id = t;
      const auto& [p0, p1, p2] = triangles[t];
      add_emissive_triangle("triangle " + std::to_string(t), {{p0, p1, p2}, cross(p1 - p0, p2 - p0)}, emissions[t],
                            hit);
    }
    scene_.top.geometries.emplace_back(std::move(mesh));
  }

  // One triangle placed by an instance: its front is where its own normal, carried along by the
  // inverse transpose, points (as make_surface sees it, mirroring transforms included).
  void add_instanced_triangle(const std::array<Vec3, 3>& object, const Affine& placement, const Emission& emission) {
    TriangleMesh mesh;
    for (const Vec3& p : object) mesh.vertices.push_back({p.x, p.y, p.z, 0.0f});
    mesh.triangles.push_back({0, 1, 2});
    mesh.material = add_material(emission);
    const Affine to_object = *inverse(placement);
    const Vec3 front = to_object.apply_normal_of_inverse(cross(object[1] - object[0], object[2] - object[0]));
    add_emissive_triangle(
        "instanced triangle",
        {{placement.apply_point(object[0]), placement.apply_point(object[1]), placement.apply_point(object[2])}, front},
        emission, add_instance(std::move(mesh), placement, to_object));
  }

  // Top-level spheres; each emits what its material does.
  void add_spheres(const std::vector<TestBall>& balls, const std::vector<Emission>& emissions) {
    SphereSet set;
    Hit hit;
    hit.geom_id = static_cast<std::uint32_t>(scene_.top.geometries.size());
    for (std::uint32_t i = 0; i < balls.size(); ++i) {
      set.spheres.push_back({balls[i].center, balls[i].radius, add_material(emissions[i])});
      hit.prim_id = i;
      add_emissive_ball("sphere " + std::to_string(i), balls[i], emissions[i], hit);
    }
    scene_.top.geometries.emplace_back(std::move(set));
  }

  // A sphere placed by an instance that scales by `scale` in every direction after `placement`.
  void add_instanced_sphere(const TestBall& object, float scale, const Affine& placement, const Emission& emission) {
    SphereSet set;
    set.spheres.push_back({object.center, object.radius, add_material(emission)});
    const Affine to_world = compose(placement, Affine::scale(Vec3(scale)));
    add_emissive_ball("instanced sphere", {to_world.apply_point(object.center), object.radius * scale}, emission,
                      add_instance(std::move(set), to_world, *inverse(to_world)));
  }

  const RenderScene& scene() const { return scene_; }
  const std::vector<TestLight>& lights() const { return lights_; }

 private:
  RenderScene scene_;
  std::vector<TestLight> lights_;

  std::uint32_t add_material(const Emission& emission) {
    scene_.materials.push_back({.base_color = Color(0.0f),
                                .emission = emission,
                                .model = DiffuseSurface{},
                                .whitted = {Color(0.0f), 0.0f, 1.0f, 0.0f, {}}});
    return static_cast<std::uint32_t>(scene_.materials.size() - 1);
  }

  Hit add_instance(Geometry geometry, const Affine& to_world, const Affine& to_object) {
    Group prototype;
    prototype.geometries.push_back(std::move(geometry));
    scene_.prototypes.push_back(std::move(prototype));
    Hit hit;
    hit.inst_id = static_cast<std::uint32_t>(scene_.top.geometries.size());
    hit.geom_id = 0;
    hit.prim_id = 0;
    scene_.top.geometries.emplace_back(
        Instance{static_cast<std::uint32_t>(scene_.prototypes.size() - 1), to_world, to_object});
    return hit;
  }

  void add_emissive_triangle(const std::string& name, const TestPolygon& t, const Emission& e, const Hit& hit) {
    if (!e.emits()) return;
    const double area = 0.5 * length(cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]));
    lights_.push_back(
        {name, t, e.two_sided, kPi * area * average(e.radiance) * (e.two_sided ? 2 : 1), std::nullopt, hit});
  }

  void add_emissive_ball(const std::string& name, const TestBall& b, const Emission& e, const Hit& hit) {
    if (!e.emits()) return;
    const double area = 4.0 * kPi * double(b.radius) * b.radius;
    lights_.push_back(
        {name, b, e.two_sided, kPi * area * average(e.radiance) * (e.two_sided ? 2 : 1), std::nullopt, hit});
  }
};

// The index the light set gives `light`, found the way the path integrator finds it for a BSDF
// sample that reaches it.
std::uint32_t index_of(const LightSet& set, const TestLight& light) {
  if (light.seen_by) {
    const std::optional<LightSet::SeenLight> seen = set.seen_light(*light.seen_by, kInfinity);
    return seen ? seen->index : kInvalidId;
  }
  if (light.delta()) {  // the scenes here have one point light at most
    for (std::uint32_t i = 0; i < set.lights().size(); ++i)
      if (std::holds_alternative<PointLight>(set.lights()[i])) return i;
    return kInvalidId;
  }
  return set.light_of_hit(light.hit);
}

// Whether any of `light` reaches `from` (one-sided surfaces turned away, and the inside of
// one-sided spheres, do not).
bool sends_light_to(const TestLight& light, const Vec3& from) {
  if (light.delta()) return false;
  if (light.two_sided) return true;
  if (const auto* polygon = std::get_if<TestPolygon>(&*light.surface))
    return dot(polygon->front, from - polygon->corners[0]) > 0.0f;
  const auto& ball = std::get<TestBall>(*light.surface);
  return length(from - ball.center) > ball.radius;
}

// Where an outline crosses a cell, the cell is split whatever its quarters say down to an eighth of
// a bin (three levels; its nodes then 1/40 of a bin apart), and further only where the quarters
// disagree: a sliver thinner than that carries too few samples to matter.
constexpr double kForcedSplitWidth = std::numbers::pi / test::kThetaBins / 5.0;

// The angle between unit vectors.
double angle_between(const Vec3& a, const Vec3& b) { return std::acos(std::clamp(double(dot(a, b)), -1.0, 1.0)); }

// The angle from unit `m` to the great-circle arc from unit `a` to unit `b` (shorter than π).
double angle_to_arc(const Vec3& m, const Vec3& a, const Vec3& b) {
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

double total_power(const std::vector<TestLight>& lights) {
  double total = 0.0;
  for (const TestLight& light : lights) total += light.power;
  return total;
}

// How far the integral of the pdf over the sphere may be from its exact value.
constexpr double kIntegralTolerance = 1e-4;

// The standard deviation of the fraction of `n` samples that fall with probability `p`.
double binomial_sigma(double p, int n) { return std::sqrt(p * (1.0 - p) / n); }

struct Run {
  test::Chi2Outcome outcome;
  double delta_fraction = 0.0;  // of all sample() calls, those that returned a delta light
};

// One χ² run per viewpoint, at the Šidák-corrected level, ~10⁶ samples in all. Each run also
// checks the pdf's integral over the sphere against the pick share of the lights that send light
// to the point and against the fraction of samples that returned a direction, and the fraction of
// delta samples against the delta lights' share of the power.
void expect_light_sampler_matches_pdf(const std::string& label, const TestScene& test_scene,
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

// A point at `distance` from `center` in the direction of `towards`.
Vec3 at_distance(const Vec3& center, float distance, const Vec3& towards) {
  return center + normalize(towards) * distance;
}

const Vec3 kQuadCorner(1.5f, -0.5f, 0.2f), kQuadEdge1(0.2f, 0.0f, 0.9f), kQuadEdge2(0.0f, 1.2f, 0.1f);
const Vec3 kSphereLightCenter(0.5f, 1.5f, 0.8f);
constexpr float kSphereLightRadius = 0.7f;

const std::array<Vec3, 3> kSmallTriangle{Vec3(1.2f, 0.3f, 1.0f), Vec3(1.5f, 0.5f, 1.1f), Vec3(1.3f, 0.2f, 1.4f)};

// A mesh of a black triangle, a large one-sided emitter and a small, bright two-sided one, and a
// one-sided triangle under a rotating, mirroring, unevenly scaling instance.
void add_emissive_triangles(TestScene& scene, const Vec3& offset) {
  const auto moved = [&](const std::array<Vec3, 3>& t) {
    return std::array<Vec3, 3>{t[0] + offset, t[1] + offset, t[2] + offset};
  };
  scene.add_mesh(
      {moved({Vec3(3.0f, 3.0f, 3.0f), Vec3(3.5f, 3.0f, 3.0f), Vec3(3.0f, 3.5f, 3.0f)}),
       moved({Vec3(-1.0f, 2.0f, -1.0f), Vec3(1.5f, 2.3f, -0.6f), Vec3(-0.2f, 2.6f, 1.4f)}), moved(kSmallTriangle)},
      {Emission(), emission(Color(3.0f, 2.0f, 1.0f), false), emission(Color(12.0f, 10.0f, 8.0f), true)});
  const Affine placement =
      compose(Affine::translate(Vec3(-1.6f, 0.2f, 0.6f) + offset),
              compose(Affine::rotate(Vec3(1.0f, 0.5f, 0.0f), 110.0f), Affine::scale(Vec3(-0.9f, 1.4f, 1.1f))));
  scene.add_instanced_triangle({Vec3(0.0f, 0.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)}, placement,
                               emission(Color(1.0f, 4.0f, 2.0f), false));
}

const TestBall kTwoSidedBall{Vec3(0.3f, -0.2f, 0.4f), 0.8f};

// A two-sided emissive sphere beside a black one, and a one-sided sphere under a uniformly scaling
// instance.
void add_emissive_spheres(TestScene& scene, const Vec3& offset) {
  scene.add_spheres({{Vec3(3.0f, 3.0f, 3.0f) + offset, 0.3f}, {kTwoSidedBall.center + offset, kTwoSidedBall.radius}},
                    {Emission(), emission(Color(1.0f, 1.0f, 2.0f), true)});
  const Affine placement =
      compose(Affine::translate(Vec3(2.5f, 1.0f, -0.5f) + offset), Affine::rotate(Vec3(0.0f, 0.0f, 1.0f), 30.0f));
  scene.add_instanced_sphere({Vec3(0.2f, 0.0f, 0.0f), 0.5f}, 1.5f, placement, emission(Color(2.0f, 1.5f, 1.0f), false));
}

TEST(LightSetChi2, QuadLightSamplerMatchesPdf) {
  TestScene scene;
  scene.add_quad_light(kQuadCorner, kQuadEdge1, kQuadEdge2, Color(4.0f, 3.0f, 2.0f));
  const Vec3 normal = normalize(cross(kQuadEdge1, kQuadEdge2));
  const Vec3 middle = kQuadCorner + (kQuadEdge1 + kQuadEdge2) * 0.5f;
  expect_light_sampler_matches_pdf("quad light", scene,
                                   {{"far", Vec3(-3.0f, 0.5f, 1.5f)},
                                    {"grazing", Vec3(1.0f, 2.5f, -1.0f)},
                                    {"0.02 above its middle", middle + normal * 0.02f}});
}

TEST(LightSetChi2, SphereLightSamplerMatchesPdf) {
  TestScene scene;
  scene.add_sphere_light(kSphereLightCenter, kSphereLightRadius, Color(4.0f, 3.0f, 2.0f));
  const Vec3& c = kSphereLightCenter;
  const float r = kSphereLightRadius;
  expect_light_sampler_matches_pdf("sphere light", scene,
                                   {{"far", c + Vec3(-3.0f, -2.5f, 1.2f)},
                                    {"1.01 radii", at_distance(c, 1.01f * r, Vec3(-0.3f, 0.2f, 1.0f))},
                                    {"1.002 radii", at_distance(c, 1.002f * r, Vec3(0.6f, 0.7f, -0.2f))}});
}

// A sphere light emits outwards only: from inside it or on it nothing is sampled, seen or given a pdf.
TEST(LightSetChi2, SphereLightSendsNothingInsideOrOnIt) {
  TestScene scene;
  scene.add_sphere_light(kSphereLightCenter, kSphereLightRadius, Color(4.0f, 3.0f, 2.0f));
  const LightSet set(scene.scene());
  test::Uniforms uniforms(17);
  for (const float radii : {0.0f, 0.5f, 0.99f, 1.0f})
    for (int i = 0; i < 1000; ++i) {
      const Vec3 from = kSphereLightCenter + uniforms.next_direction() * (radii * kSphereLightRadius);
      const float u_pick = uniforms.next();
      EXPECT_FALSE(set.sample(from, u_pick, uniforms.next_2d())) << radii << " radii";
      const Vec3 w = uniforms.next_direction();
      EXPECT_FALSE(set.seen_light(Ray{from, 0.0f, w}, kInfinity)) << radii << " radii";
      EXPECT_EQ(set.pdf(0, from, kSphereLightCenter + w * kSphereLightRadius), 0.0f) << radii << " radii";
    }
}

TEST(LightSetChi2, EmissiveTrianglesSamplerMatchesPdf) {
  TestScene scene;
  add_emissive_triangles(scene, Vec3(0.0f));
  const auto& [a, b, c] = kSmallTriangle;
  const Vec3 small_middle = (a + b + c) * (1.0f / 3.0f);
  const Vec3 small_normal = normalize(cross(b - a, c - a));
  expect_light_sampler_matches_pdf("emissive triangles", scene,
                                   {{"origin", Vec3(0.0f)},
                                    {"0.03 behind the small two-sided one", small_middle - small_normal * 0.03f},
                                    {"behind the large one", Vec3(0.0f, 3.2f, 0.3f)}});
}

TEST(LightSetChi2, EmissiveSpheresSamplerMatchesPdf) {
  TestScene scene;
  add_emissive_spheres(scene, Vec3(0.0f));
  const Vec3& c = kTwoSidedBall.center;
  const float r = kTwoSidedBall.radius;
  expect_light_sampler_matches_pdf(
      "emissive spheres", scene,
      {{"far", Vec3(-2.5f, 1.5f, 2.0f)},
       {"1.01 radii from the two-sided one", at_distance(c, 1.01f * r, Vec3(-1.0f, 0.4f, 0.3f))},
       {"on the two-sided one", at_distance(c, r, Vec3(0.2f, -1.0f, 0.5f))},
       {"inside the two-sided one", at_distance(c, 0.4f * r, Vec3(0.5f, 0.5f, -1.0f))},
       {"inside the one-sided instanced one", Vec3(2.6f, 1.1f, -0.4f)}});
}

// Every kind at once, with a point light: its share of the picks returns delta samples.
TestScene mixed_scene() {
  TestScene scene;
  scene.add_point_light(Vec3(1.0f, -1.5f, -1.8f), Color(5.0f, 4.0f, 6.0f));
  scene.add_quad_light(kQuadCorner, kQuadEdge1, kQuadEdge2, Color(4.0f, 3.0f, 2.0f));
  scene.add_sphere_light(Vec3(-1.5f, -2.0f, -1.0f), 0.5f, Color(6.0f, 6.0f, 5.0f));
  add_emissive_triangles(scene, Vec3(0.0f, 0.5f, 0.0f));
  add_emissive_spheres(scene, Vec3(-0.5f, -1.0f, 2.5f));
  return scene;
}

TEST(LightSetChi2, MixedLightsSamplerMatchesPdf) {
  expect_light_sampler_matches_pdf("mixed lights", mixed_scene(),
                                   {{"origin", Vec3(0.0f)},
                                    {"behind the quad", Vec3(2.5f, 0.2f, 0.6f)},
                                    {"inside the sphere light", Vec3(-1.4f, -2.1f, -1.0f)}});
}

// Under render.light_sampler: power, over a fine grid of u_pick, each light is picked with its
// share of the power, and a delta sample reports exactly that share as its pdf.
TEST(LightSetChi2, PicksLightsInProportionToPower) {
  const TestScene scene = mixed_scene();
  RenderScene by_power = scene.scene();
  by_power.render.light_sampler = LightSamplerKind::kPower;
  const LightSet set(by_power);
  const std::vector<TestLight>& lights = scene.lights();
  ASSERT_EQ(set.lights().size(), lights.size());
  const Vec3 from(0.0f);
  for (const TestLight& light : lights)
    if (!light.delta()) {
      ASSERT_TRUE(sends_light_to(light, from)) << light.name;
    }
  const double total = total_power(lights);
  std::vector<double> share(lights.size(), 0.0);
  for (const TestLight& light : lights) share[index_of(set, light)] = light.power / total;
  constexpr int kPicks = 1 << 18;
  std::vector<int> picked(lights.size(), 0);
  for (int i = 0; i < kPicks; ++i) {
    const float u_pick = (static_cast<float>(i) + 0.5f) / kPicks;
    const std::optional<PathLightSample> s = set.sample(from, u_pick, {0.37f, 0.61f});
    ASSERT_TRUE(s) << "u_pick " << i;
    ASSERT_LT(s->light, picked.size());
    ++picked[s->light];
    if (s->delta) {
      ASSERT_NEAR(s->pdf, share[s->light], 1e-6 * share[s->light]);
    }
  }
  for (const TestLight& light : lights) {
    const std::uint32_t index = index_of(set, light);
    const double frequency = static_cast<double>(picked[index]) / kPicks;
    std::cout << "[pick] " << light.name << ": power share " << share[index] << ", picked " << frequency << "\n";
    EXPECT_NEAR(frequency, share[index], static_cast<double>(lights.size()) / kPicks + 1e-6) << light.name;
  }
}

}  // namespace light_set_chi2_test
}  // namespace rtpro
