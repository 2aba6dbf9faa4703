#pragma once
// Lights as the renderer uses them: what arrives from each, worked out once from the scene file's
// description (make_light in build_render_scene.h). Adding a kind means a struct here, an overload
// in src/scene/light.cpp and its overloads in render/light_sample.h and light_sample.cpp; every
// std::visit over Light fails to compile until then.
#include "rtpro/core/vec3.h"

#include <variant>

namespace rtpro {

struct PointLight {
  Vec3 position;
  Color radiance;  // colour × intensity; no falloff (the seed's model)
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

using Light = std::variant<PointLight, DirectionalLight, SphereLight, QuadLight>;

}  // namespace rtpro
