// A camera that moves during the shutter (keyframed in YAML, or a glTF camera node's animation):
// each camera ray leaves the camera posed at the ray's time, so a static quad seen by a camera
// sliding across it blurs into the box filter's trapezoid on both backends; a closed shutter
// gives the frame's posed camera bit for bit; and the motion AOV of the static quad is the
// camera's motion.
#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "box_filtered_coverage.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace rtpro {
namespace camera_motion_test {

// 64 × 4 pixels 0.1 scene units wide on the plane z = 0 (image x along world −x), an emissive
// quad 0.8 wide at the origin. `camera` is the camera's position and look_at.
constexpr int kWidth = 64, kHeight = 4;
constexpr float kPixel = 0.1f;
RenderScene quad_scene(const std::string& camera, const std::string& shutter) {
  const double fov = 2.0 * std::atan(kPixel * kHeight / 2.0 / 10.0) * 180.0 / 3.14159265358979323846;
  const std::string text =
      "rtpro: 1\ncamera: {" + camera + ", fov: " + std::to_string(fov) + ", resolution: [" + std::to_string(kWidth) +
      ", " + std::to_string(kHeight) + "], shutter: " + shutter +
      "}\nrender: {integrator: path, spp: 256, max_depth: 1}\nmaterials: {glow: {type: diffuse, color: [0, 0, 0], "
      "emission: [1, 1, 1]}}\n";
  RenderScene scene = build_render_scene(parse_scene_text(text, "camera_motion.yaml", {}));
  TriangleMesh quad;
  quad.vertices = {{-0.4f, -1, 0}, {0.4f, -1, 0}, {0.4f, 1, 0}, {-0.4f, 1, 0}};
  quad.triangles = {{0, 2, 1}, {0, 3, 2}};  // facing the camera (−z)
  quad.material = 1;
  scene.top.geometries.emplace_back(std::move(quad));
  return scene;
}

// The camera slides along +x from -3.2 at frame 0 to 3.2 at frame 2: over the shutter [-0.5, 0.5]
// of frame 1 (the default frame) from -1.6 to 1.6, 32 pixels in a frame.
const std::string kSlidingCamera =
    "position: {keyframes: {0: [-3.2, 0, -10], 2: [3.2, 0, -10]}}, look_at: {keyframes: {0: [-3.2, 0, 0], 2: [3.2, 0, "
    "0]}}";

Image render(const RenderScene& scene, BackendKind kind, std::vector<Aov> aovs = {}) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
  BackendOptions backend_options;
  backend_options.threads = 1;
  const auto backend = make_backend(kind, scene, backend_options);
  RenderOptions options;
  options.aovs = std::move(aovs);
  return render_image(scene, *backend, options).image;
}

// The fraction of the shutter during which the quad covers world x = s seen from a camera at x = 0:
// relative to the camera, passing from -1.6 to 1.6, the quad's left edge goes from 1.2 to -2.
double covered_time(double s) {
  const double from = std::max(0.0, (1.2 - s) / 3.2);
  const double to = std::min(1.0, (2.0 - s) / 3.2);
  return std::max(0.0, to - from);
}

// Pixel x's expected value: the covered time averaged over the pixel's footprint (box filter).
double expected_pixel(int x) { return test::box_filtered_coverage(x, kWidth, kPixel, covered_time); }

TEST(CameraMotion, ACameraSlidingPastAStillQuadBlursItIntoTheTrapezoid) {
  const RenderScene scene = quad_scene(kSlidingCamera, "[-0.5, 0.5]");
  ASSERT_TRUE(scene.camera.moving());
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const Image image = render(scene, kind);
    double worst = 0.0, energy = 0.0;
    for (int x = 0; x < kWidth; ++x) {
      double column = 0.0;
      for (int y = 0; y < kHeight; ++y) column += image.at(x, y, 0) / kHeight;
      energy += column;
      worst = std::max(worst, std::fabs(column - expected_pixel(x)));
    }
    EXPECT_LT(worst, 0.01) << backend_name(kind);
    EXPECT_NEAR(energy, 8.0, 0.04) << backend_name(kind);  // the quad's 8 pixels, spread
  }
}

TEST(CameraMotion, AClosedShutterGivesTheFramesPosedCameraBitForBit) {
  const RenderScene keyed = quad_scene(kSlidingCamera, "[0, 0]");
  EXPECT_FALSE(keyed.camera.moving());
  const RenderScene posed = quad_scene("position: [0, 0, -10], look_at: [0, 0, 0]", "[0, 0]");
  const Image a = render(keyed, BackendKind::kNative), b = render(posed, BackendKind::kNative);
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0);
}

// The still quad moves on the film as the camera does: +32 pixels a frame along the image's x.
TEST(CameraMotion, TheMotionAovOfAStillQuadIsTheCamerasMotion) {
  const RenderScene scene = quad_scene(kSlidingCamera, "[-0.5, 0.5]");
  for (BackendKind kind : {BackendKind::kNative, BackendKind::kEmbree}) {
    const Image image = render(scene, kind, {Aov::kMotion});
    ASSERT_EQ(image.channel_count(), 7);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(image.at(kWidth / 2, 2, 3 + c), c % 2 == 0 ? 32.0f : 0.0f, 0.01f) << backend_name(kind) << " " << c;
  }
}

}  // namespace camera_motion_test
}  // namespace rtpro
