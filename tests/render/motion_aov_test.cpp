// The motion AOV (`--aov motion`, render/aov.h): a shape moving at a known speed shows its film
// velocity in pixels per frame on both backends and both integrators, whichever way it moves
// (instance, sphere centre, deforming vertices); a scene that stands still shows none.
#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <string>
#include <vector>

namespace rtpro {
namespace motion_aov_test {

constexpr BackendKind kBackends[] = {BackendKind::kNative, BackendKind::kEmbree};

// A camera at z = -10 looking along +z whose pixels are 0.1 scene units wide on the plane z = 0
// (image x along world −x, image y along world −y), an emissive material (index 1), a half-frame
// shutter centred on the frame.
constexpr float kPixel = 0.1f;
constexpr int kWidth = 32, kHeight = 16;
RenderScene camera_scene(const std::string& integrator, const std::string& shutter = "[-0.25, 0.25]") {
  const double fov = 2.0 * std::atan(kPixel * kHeight / 2.0 / 10.0) * 180.0 / 3.14159265358979323846;
  const std::string text = "rtpro: 1\ncamera: {position: [0, 0, -10], look_at: [0, 0, 0], fov: " + std::to_string(fov) +
                           ", resolution: [" + std::to_string(kWidth) + ", " + std::to_string(kHeight) +
                           "], shutter: " + shutter + "}\nrender: {integrator: " + integrator +
                           ", spp: 4, max_depth: 1}\nmaterials: {glow: {type: diffuse, color: [0, 0, 0], emission: "
                           "[1, 1, 1]}}\n";
  return build_render_scene(parse_scene_text(text, "motion_aov.yaml", {}));
}

// A 1 × 1 square in the plane z = 0 centred on the origin, facing the camera.
TriangleMesh square() {
  TriangleMesh mesh;
  mesh.vertices = {{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
  mesh.material = 1;
  return mesh;
}

Image render_motion(const RenderScene& scene, BackendKind kind) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
  BackendOptions backend_options;
  backend_options.threads = 1;
  const auto backend = make_backend(kind, scene, backend_options);
  RenderOptions options;
  options.aovs = {Aov::kMotion};
  const Image image = render_image(scene, *backend, options).image;
  EXPECT_EQ(image.channels, (std::vector<std::string>{"R", "G", "B", "motion.X", "motion.Y", "motion.Z", "motion.W"}));
  return image;
}

// The centre pixel's motion (forward x, y, back x, y), the square or sphere covering it.
std::vector<float> centre_motion(const Image& image) {
  std::vector<float> m;
  for (int c = 3; c < 7; ++c) m.push_back(image.at(kWidth / 2, kHeight / 2, c));
  return m;
}

// Both halves of the shutter move the point at (x, y) pixels per frame, within `relative`.
void expect_motion(const std::vector<float>& m, float x, float y, const std::string& what, float relative = 1e-4f) {
  for (int half = 0; half < 2; ++half) {
    EXPECT_NEAR(m[2 * half], x, relative * std::fabs(x) + 1e-4f) << what;
    EXPECT_NEAR(m[2 * half + 1], y, relative * std::fabs(y) + 1e-4f) << what;
  }
}

// The square carried 0.8 along +x during the half-frame shutter (1.6 scene units, 16 pixels per
// frame, towards the image's −x) by its instance and by its own vertices, and a sphere of radius
// 0.5 whose centre rises 0.4 (8 pixels per frame at the plane z = 0, up the image: −y).
TEST(MotionAov, MovingShapesShowTheirFilmVelocity) {
  for (const char* integrator : {"path", "whitted"})
    for (BackendKind kind : kBackends) {
      const std::string what = std::string(integrator) + " on " + std::string(backend_name(kind));
      RenderScene by_instance = camera_scene(integrator);
      by_instance.prototypes.push_back(Group{{square()}});
      const Affine start = Affine::translate({-0.4f, 0, 0});
      by_instance.top.geometries.emplace_back(Instance{0, Affine::translate({0, 0, 0}),
                                                       *inverse(Affine::translate({0, 0, 0})),
                                                       std::vector<Affine>{start, Affine::translate({0.4f, 0, 0})}});
      expect_motion(centre_motion(render_motion(by_instance, kind)), -16.0f, 0.0f, "instance, " + what);

      RenderScene deformed = camera_scene(integrator);
      TriangleMesh mesh = square();
      VertexArray before = mesh.vertices, after = mesh.vertices;
      for (MeshVertex& v : before) v.x -= 0.4f;
      for (MeshVertex& v : after) v.x += 0.4f;
      mesh.vertex_steps = {before, after};
      deformed.top.geometries.emplace_back(std::move(mesh));
      expect_motion(centre_motion(render_motion(deformed, kind)), -16.0f, 0.0f, "deforming mesh, " + what);

      RenderScene rising = camera_scene(integrator);
      SphereSet set;
      set.spheres = {{{0.0f, 0.0f, 0.0f}, 0.5f, 1}};
      set.step_count = 2;
      set.center_steps = {{0.0f, -0.2f, 0.0f}, {0.0f, 0.2f, 0.0f}};
      rising.top.geometries.emplace_back(std::move(set));
      // The sphere's near side is 9.5 from the camera (up to 9.53 where the pixel sees it as it
      // rises): its pixels there are 0.095 wide, 8.4 of them a frame (8 at its centre's depth).
      expect_motion(centre_motion(render_motion(rising, kind)), 0.0f, -8.0f * 10.0f / 9.5f, "sphere, " + what, 5e-3f);
    }
}

// An open shutter over a scene where nothing moves: every pixel's motion is exactly zero (and the
// background's, which no hit covers).
TEST(MotionAov, StillSceneShowsNoMotion) {
  for (BackendKind kind : kBackends) {
    RenderScene scene = camera_scene("path", "[-0.5, 0.5]");
    scene.top.geometries.emplace_back(square());
    const Image image = render_motion(scene, kind);
    ASSERT_GT(image.at(kWidth / 2, kHeight / 2, 0), 0.5f);  // the square is seen
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        for (int c = 3; c < 7; ++c) ASSERT_EQ(image.at(x, y, c), 0.0f) << x << "," << y << " " << backend_name(kind);
  }
}

}  // namespace motion_aov_test
}  // namespace rtpro
