#include "test_scenes.h"

#include "rtpro/scene/build_render_scene.h"

#include <cmath>
#include <optional>

namespace rtpro::test {

namespace {
float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
Vec3 uniform_point(std::mt19937& rng, float extent) {
  return {uniform(rng, -extent, extent), uniform(rng, -extent, extent), uniform(rng, -extent, extent)};
}
Vec3 uniform_direction(std::mt19937& rng) {
  for (;;) {
    const Vec3 d = uniform_point(rng, 1.0f);
    const float l = length(d);
    if (l > 1e-3f && l <= 1.0f) return d / l;
  }
}
}  // namespace

Material phong_material(const Color& color, float specular, float shininess, float reflectivity) {
  return {.base_color = color,
          .model = PhongSurface{specular, shininess, reflectivity, {}},
          .whitted = {color, specular, shininess, reflectivity, {}}};
}

void set_camera(RenderScene& scene, int width, int height) {
  CameraDesc camera;
  camera.position = {0.0f, 0.0f, 10.0f};
  camera.look_at = {0.0f, 0.0f, 0.0f};
  camera.width = width;
  camera.height = height;
  scene.camera = make_render_camera(camera);
}

RenderScene empty_scene(int width, int height) {
  RenderScene scene;
  set_camera(scene, width, height);
  scene.render.spp = 4;
  scene.render.max_depth = 3;
  scene.materials.push_back(phong_material(Color{0.8f, 0.8f, 0.8f}, 0.5f, 10.0f, 0.0f));
  scene.materials.push_back(phong_material(Color{0.9f, 0.2f, 0.2f}, 0.8f, 20.0f, 0.5f));
  scene.material_names = {"default", "mirror-red"};
  scene.lights.push_back(make_light(PointLightDesc{{5.0f, 8.0f, 10.0f}, {1.0f, 1.0f, 1.0f}, 1.0f}));
  scene.lights.push_back(make_light(DirectionalLightDesc{{-1.0f, -1.0f, -0.5f}, {0.4f, 0.4f, 0.5f}, 1.0f}));
  return scene;
}

SphereSet random_spheres(std::mt19937& rng, int count, float extent) {
  SphereSet set;
  for (int i = 0; i < count; ++i)
    set.spheres.push_back(
        {uniform_point(rng, extent), uniform(rng, 0.01f, 0.1f) * extent, static_cast<std::uint32_t>(i % 2)});
  return set;
}

TriangleMesh random_triangles(std::mt19937& rng, int count, float extent) {
  TriangleMesh mesh;
  for (int i = 0; i < count; ++i) {
    const Vec3 center = uniform_point(rng, extent);
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = center + uniform_point(rng, 0.2f * extent);
      mesh.vertices.push_back({p.x, p.y, p.z});
    }
    const auto base = static_cast<std::uint32_t>(3 * i);
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

RenderScene random_mixed_scene(std::uint32_t seed, int spheres, int triangles, int instances) {
  std::mt19937 rng(seed);
  RenderScene scene = empty_scene();
  if (spheres > 0) scene.top.geometries.emplace_back(random_spheres(rng, spheres, 4.0f));
  if (triangles > 0) scene.top.geometries.emplace_back(random_triangles(rng, triangles, 4.0f));
  if (instances > 0) {
    Group prototype;
    prototype.geometries.emplace_back(random_spheres(rng, std::max(1, spheres / 4), 1.0f));
    if (triangles > 0) prototype.geometries.emplace_back(random_triangles(rng, std::max(1, triangles / 4), 1.0f));
    scene.prototypes.push_back(std::move(prototype));
    for (int i = 0; i < instances; ++i) {
      // One draw per statement: the order in which function arguments are evaluated is
      // unspecified (gcc and clang differ), and the scene must not depend on the compiler.
      const Vec3 offset = uniform_point(rng, 4.0f);
      const Vec3 axis = uniform_direction(rng);
      const float angle = uniform(rng, 0.0f, 360.0f);
      const Vec3 scale{uniform(rng, 0.3f, 1.5f), uniform(rng, 0.3f, 1.5f), uniform(rng, 0.3f, 1.5f)};
      const Affine placement =
          compose(Affine::translate(offset), compose(Affine::rotate(axis, angle), Affine::scale(scale)));
      scene.top.geometries.emplace_back(Instance{0, placement, *inverse(placement)});
    }
  }
  return scene;
}

Ray random_ray(std::mt19937& rng, float extent) {
  Ray ray;
  ray.org = uniform_point(rng, extent);
  ray.dir = uniform_direction(rng);
  return ray;
}

}  // namespace rtpro::test
