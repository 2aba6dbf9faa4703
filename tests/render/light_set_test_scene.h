#pragma once
// Small scenes for the light set's tests, built side by side with what the test knows of their
// lights: each light's world-space surface (instances placed by their transforms, fronts where the
// surface's own normal points), the index the light set gives it and the power it emits.
#include "light_set.h"

#include "rtpro/core/transform.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rtpro::light_set_test {

inline constexpr double kPi = std::numbers::pi;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline double average(const Color& c) { return (double(c.x) + c.y + c.z) / 3.0; }

inline Emission emission(const Color& radiance, bool two_sided) {
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
      for (const Vec3& p : triangles[t]) mesh.vertices.push_back({p.x, p.y, p.z});
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
    for (const Vec3& p : object) mesh.vertices.push_back({p.x, p.y, p.z});
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
inline std::uint32_t index_of(const LightSet& set, const TestLight& light) {
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
inline bool sends_light_to(const TestLight& light, const Vec3& from) {
  if (light.delta()) return false;
  if (light.two_sided) return true;
  if (const auto* polygon = std::get_if<TestPolygon>(&*light.surface))
    return dot(polygon->front, from - polygon->corners[0]) > 0.0f;
  const auto& ball = std::get<TestBall>(*light.surface);
  return length(from - ball.center) > ball.radius;
}

inline double total_power(const std::vector<TestLight>& lights) {
  double total = 0.0;
  for (const TestLight& light : lights) total += light.power;
  return total;
}

// A point at `distance` from `center` in the direction of `towards`.
inline Vec3 at_distance(const Vec3& center, float distance, const Vec3& towards) {
  return center + normalize(towards) * distance;
}

// Lights each kind's test places alone and the mixed scene (light_set_chi2_test.cpp) together.
inline const Vec3 kQuadCorner(1.5f, -0.5f, 0.2f), kQuadEdge1(0.2f, 0.0f, 0.9f), kQuadEdge2(0.0f, 1.2f, 0.1f);
inline const std::array<Vec3, 3> kSmallTriangle{Vec3(1.2f, 0.3f, 1.0f), Vec3(1.5f, 0.5f, 1.1f), Vec3(1.3f, 0.2f, 1.4f)};

// A mesh of a black triangle, a large one-sided emitter and a small, bright two-sided one, and a
// one-sided triangle under a rotating, mirroring, unevenly scaling instance.
inline void add_emissive_triangles(TestScene& scene, const Vec3& offset) {
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

inline const TestBall kTwoSidedBall{Vec3(0.3f, -0.2f, 0.4f), 0.8f};

// A two-sided emissive sphere beside a black one, and a one-sided sphere under a uniformly scaling
// instance.
inline void add_emissive_spheres(TestScene& scene, const Vec3& offset) {
  scene.add_spheres({{Vec3(3.0f, 3.0f, 3.0f) + offset, 0.3f}, {kTwoSidedBall.center + offset, kTwoSidedBall.radius}},
                    {Emission(), emission(Color(1.0f, 1.0f, 2.0f), true)});
  const Affine placement =
      compose(Affine::translate(Vec3(2.5f, 1.0f, -0.5f) + offset), Affine::rotate(Vec3(0.0f, 0.0f, 1.0f), 30.0f));
  scene.add_instanced_sphere({Vec3(0.2f, 0.0f, 0.0f), 0.5f}, 1.5f, placement, emission(Color(2.0f, 1.5f, 1.0f), false));
}

}  // namespace rtpro::light_set_test
