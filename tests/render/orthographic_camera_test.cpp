// Orthographic cameras (`camera.projection: orthographic`): parallel rays from the plane through
// the camera, so a sphere is a disc of its own radius on the film at any distance, on both
// backends; film_point inverts camera_ray for both projections; the scene reader refuses depth of
// field on an orthographic camera.
#include "rtpro/backend/backend.h"
#include "rtpro/render/camera.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace orthographic_camera_test {

// A 40 × 40 orthographic view 4 units high (0.1 per pixel) from z = -10 along +z, and an emissive
// sphere of radius 1 on the axis at `z`.
std::string sphere_scene(float z, const std::string& camera_extra = "") {
  return "rtpro: 1\ncamera: {position: [0, 0, -10], look_at: [0, 0, 0], projection: orthographic, ortho_height: 4, "
         "resolution: [40, 40]" +
         camera_extra +
         "}\nrender: {integrator: path, spp: 16, max_depth: 1}\nmaterials: {glow: {type: diffuse, color: [0, 0, 0], "
         "emission: [1, 1, 1]}}\nworld:\n  - {type: sphere, center: [0.5, 0, " +
         std::to_string(z) + "], radius: 1, material: glow}\n";
}

// Pixels more than half covered by the sphere.
int disc_pixels(float z, BackendKind kind) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
  const RenderScene scene = build_render_scene(parse_scene_text(sphere_scene(z), "ortho.yaml"));
  BackendOptions options;
  options.threads = 1;
  const Image image = render_image(scene, *make_backend(kind, scene, options), {}).image;
  int lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) lit += image.at(x, y, 0) > 0.5f;
  return lit;
}

TEST(OrthographicCamera, ASphereIsADiscOfItsRadiusAtAnyDistance) {
  // Radius 1 is 10 pixels: π·10² ≈ 314 pixels; a perspective camera would shrink the far one.
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const int near = disc_pixels(0.0f, kind), far = disc_pixels(40.0f, kind);
    EXPECT_NEAR(near, 314, 8) << backend_name(kind);
    EXPECT_NEAR(far, near, 2) << backend_name(kind);
  }
}

// Where a ray through film point (px, py) meets the plane 7 units ahead, film_point finds (px, py).
TEST(OrthographicCamera, FilmPointInvertsCameraRayForBothProjections) {
  for (const char* projection : {"perspective, fov: 50", "orthographic, ortho_height: 3"}) {
    const std::string text = std::string("rtpro: 1\ncamera: {position: [1, 2, -3], look_at: [0, 0, 4], projection: ") +
                             projection + ", resolution: [64, 48]}\n";
    const RenderCamera camera = make_render_camera(parse_scene_text(text, "c.yaml").camera);
    for (const auto& [px, py] : {std::pair{0.5f, 0.5f}, std::pair{63.0f, 10.25f}, std::pair{32.0f, 47.5f}}) {
      const Ray ray = camera_ray(camera, px, py, {0.5f, 0.5f});
      const float t = 7.0f / dot(ray.dir, camera.forward);
      const std::optional<FilmPoint> film = film_point(camera, camera.pose(), ray.org + ray.dir * t);
      ASSERT_TRUE(film.has_value()) << projection;
      EXPECT_NEAR(film->x, px, 1e-3f) << projection;
      EXPECT_NEAR(film->y, py, 1e-3f) << projection;
    }
  }
}

TEST(OrthographicCamera, TheReaderRefusesDepthOfFieldAndABadHeight) {
  const auto message = [](const std::string& text) {
    try {
      parse_scene_text(text, "bad.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(sphere_scene(0.0f, ", aperture: 0.1")).find("needs a perspective camera"), std::string::npos);
  EXPECT_EQ(parse_scene_text(sphere_scene(0.0f, ", aperture: 0"), "ok.yaml").camera.projection,
            CameraProjection::kOrthographic);
  for (const char* height : {"0", "-2", ".inf"}) {
    std::string text = sphere_scene(0.0f);
    text.replace(text.find("ortho_height: 4"), 15, std::string("ortho_height: ") + height);
    EXPECT_NE(message(text).find("bad.yaml:2:"), std::string::npos) << height;
    EXPECT_NE(message(text).find("camera.ortho_height"), std::string::npos) << height;
  }
  std::string fisheye = sphere_scene(0.0f);
  fisheye.replace(fisheye.find("orthographic"), 12, "fisheye");
  EXPECT_NE(message(fisheye).find("camera.projection"), std::string::npos);
}

}  // namespace orthographic_camera_test
}  // namespace rtpro
