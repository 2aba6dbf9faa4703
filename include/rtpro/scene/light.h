#pragma once
// Lights as the renderer uses them: what arrives from each, worked out once from the scene file's
// description (make_light in build_render_scene.h). Adding a kind means a struct here, an overload
// in src/scene/build/light.cpp and its overloads in render/light_sample.h and light_sample.cpp; every
// std::visit over Light fails to compile until then.
#include "rtpro/core/vec3.h"

#include <variant>

namespace rtpro {

struct PointLight {
  Vec3 position;
  Color radiance;  // colour × intensity; `whitted` shades it without distance falloff, `path` over d²
};

// A point light whose intensity falls off away from its axis, as pbrt-v4's SpotLight: full within
// the inner cone, none outside the outer one, smoothstep(cos_outer, cos_inner, cos θ) between.
struct SpotLight {
  Vec3 position;
  Vec3 axis;        // unit: the direction light travels along
  Color radiance;   // colour × intensity, on the axis (as a point light's)
  float cos_inner;  // cosine of the inner cone's half-angle
  float cos_outer;  // cosine of the outer cone's half-angle, <= cos_inner

  // The share of `radiance` sent along unit `outward` (from the light): exactly 0 outside the
  // outer cone. Equal cones are a hard edge.
  float falloff(const Vec3& outward) const {
    const float cos_theta = dot(axis, outward);
    if (cos_inner == cos_outer) return cos_theta < cos_outer ? 0.0f : 1.0f;
    float t = (cos_theta - cos_outer) / (cos_inner - cos_outer);
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    return t * t * (3.0f - 2.0f * t);
  }
};

struct DirectionalLight {
  Vec3 to_light;   // unit, against the direction light travels in
  Color radiance;  // colour × intensity
};

// A sphere that emits `radiance` from its surface; shading samples the cone it fills as seen from
// the point, samples_per_axis² stratified directions.
struct SphereLight {
  Vec3 center;
  float radius;
  Color radiance;
  int samples_per_axis;
};

// A one-sided parallelogram: corner + [0,1]·edge1 + [0,1]·edge2, emitting towards `normal`
// (unit edge1 × edge2); sampled uniformly by area, samples_per_axis² stratified points.
struct QuadLight {
  Vec3 corner, edge1, edge2;
  Vec3 normal;
  float area;
  Color radiance;
  int samples_per_axis;
};

using Light = std::variant<PointLight, SpotLight, DirectionalLight, SphereLight, QuadLight>;

}  // namespace rtpro
