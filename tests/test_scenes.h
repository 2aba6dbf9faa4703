#pragma once
// Deterministic synthetic render scenes for tests: random spheres, triangle soups, instances.
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <random>

namespace rtpro::test {

// A camera at (0, 0, 10) looking at the origin, `width`×`height` pixels.
void set_camera(RenderScene& scene, int width, int height);

// A Phong material (scene/phong_material.h) of colour `color`, as the builder makes it of a scene
// file's.
Material phong_material(const Color& color, float specular, float shininess, float reflectivity);

// A render scene with one default material, one point light and a camera looking at the origin.
RenderScene empty_scene(int width = 32, int height = 24);

// `count` spheres with centres in [-extent, extent]³ and radii in [0.01, 0.1]·extent.
SphereSet random_spheres(std::mt19937& rng, int count, float extent);
// `count` triangles with vertices in [-extent, extent]³, shared-vertex free.
TriangleMesh random_triangles(std::mt19937& rng, int count, float extent);

// Spheres and a triangle mesh at the top level, plus `instances` instances of a prototype holding
// both (only spheres when `triangles` is 0), under random rotation, non-uniform scale and
// translation.
RenderScene random_mixed_scene(std::uint32_t seed, int spheres, int triangles, int instances);

// A random ray with origin in [-extent, extent]³ and a uniformly distributed direction.
Ray random_ray(std::mt19937& rng, float extent);

}  // namespace rtpro::test
