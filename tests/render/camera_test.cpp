// The camera: the pinhole ray unchanged by the lens sample, the thin lens's focus and circle of
// confusion against the thin-lens formula, the concentric disk map, and whole renders in which
// the plane of focus stays sharp while what lies off it blurs.
#include "rtpro/render/camera.h"
#include "rtpro/backend/backend.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace rtpro {
namespace camera_test {

RenderCamera lens_camera(float aperture, float focus_distance) {
  CameraDesc desc;
  desc.position = {0.0f, 0.0f, 10.0f};
  desc.look_at = {0.0f, 0.0f, 0.0f};
  desc.width = 64;
  desc.height = 48;
  desc.aperture = aperture;
  desc.focus_distance = focus_distance;
  return make_render_camera(desc);
}

// Where a ray meets the plane at `distance` in front of the camera (the camera looks along -z).
Vec3 at_depth(const Ray& ray, const RenderCamera& camera, float distance) {
  const float t = distance / dot(ray.dir, camera.forward);
  return ray.org + ray.dir * t;
}

// Pinhole rays four at a time are camera_ray's, bit for bit, for oblique cameras and film points
// all over (and beyond) the image.
TEST(Camera, FourPinholeRaysAtATimeAreCameraRaysBitForBit) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> coordinate(-20.0f, 20.0f);
  std::uniform_real_distribution<float> film(-8.0f, 1100.0f);
  const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v); };
  for (int c = 0; c < 50; ++c) {
    CameraDesc desc;
    desc.position = {coordinate(rng), coordinate(rng), coordinate(rng)};
    desc.look_at = {coordinate(rng), coordinate(rng), coordinate(rng)};
    desc.fov_degrees = 10.0f + static_cast<float>(c) * 3.0f;
    desc.width = 1000 + c;
    desc.height = 700 + 3 * c;
    const RenderCamera camera = make_render_camera(desc);
    for (int group = 0; group < 500; ++group) {
      alignas(16) float px[4], py[4];
      for (int i = 0; i < 4; ++i) {
        px[i] = film(rng);
        py[i] = film(rng);
      }
      Ray four[4];
      pinhole_rays4(camera, px, py, four);
      for (int i = 0; i < 4; ++i) {
        const Ray one = camera_ray(camera, px[i], py[i], {0.5f, 0.5f});
        for (int axis = 0; axis < 3; ++axis) {
          ASSERT_EQ(bits(four[i].org[axis]), bits(one.org[axis]));
          ASSERT_EQ(bits(four[i].dir[axis]), bits(one.dir[axis])) << "camera " << c << " lane " << i;
        }
        ASSERT_EQ(bits(four[i].tnear), bits(one.tnear));
        ASSERT_EQ(bits(four[i].tfar), bits(one.tfar));
      }
    }
  }
}

TEST(Camera, WithoutAnApertureTheLensSampleChangesNothing) {
  const RenderCamera camera = lens_camera(0.0f, 0.0f);
  const Ray a = camera_ray(camera, 10.3f, 20.7f, {0.1f, 0.9f});
  const Ray b = camera_ray(camera, 10.3f, 20.7f, {0.8f, 0.2f});
  EXPECT_EQ(a.org, camera.position);
  EXPECT_EQ(a.org, b.org);
  EXPECT_EQ(a.dir, b.dir);
}

TEST(Camera, TheFocusDistanceDefaultsToTheLookAtPoint) {
  EXPECT_FLOAT_EQ(lens_camera(0.5f, 0.0f).focus_distance, 10.0f);
  EXPECT_FLOAT_EQ(lens_camera(0.5f, 4.0f).focus_distance, 4.0f);
}

TEST(Camera, EveryLensPointSeesTheSamePointOfThePlaneInFocus) {
  const RenderCamera camera = lens_camera(0.5f, 6.0f);
  const RenderCamera pinhole = lens_camera(0.0f, 6.0f);
  const Vec3 sharp = at_depth(camera_ray(pinhole, 40.25f, 9.5f, {0.5f, 0.5f}), pinhole, 6.0f);
  for (const Sample2D lens :
       {Sample2D{0.0f, 0.0f}, Sample2D{0.99f, 0.5f}, Sample2D{0.3f, 0.8f}, Sample2D{0.7f, 0.1f}}) {
    const Ray ray = camera_ray(camera, 40.25f, 9.5f, lens);
    EXPECT_GT(length(ray.org - camera.position), 0.0f);
    EXPECT_LE(length(ray.org - camera.position), 0.5f * (1.0f + 1e-6f));
    const Vec3 seen = at_depth(ray, camera, 6.0f);
    EXPECT_NEAR(seen.x, sharp.x, 1e-5f);
    EXPECT_NEAR(seen.y, sharp.y, 1e-5f);
    EXPECT_NEAR(seen.z, sharp.z, 1e-5f);
  }
}

// A ray from the rim of the lens meets the plane at depth d off the focused point by
// R·|d − f|/f: the radius of the thin lens's circle of confusion, projected back to depth d.
TEST(Camera, OffThePlaneInFocusRaysSpreadByTheCircleOfConfusion) {
  const float radius = 0.4f, focus = 5.0f;
  const RenderCamera camera = lens_camera(radius, focus);
  const Ray centre = camera_ray(camera, 32.0f, 24.0f, {0.5f, 0.5f});
  const Ray rim = camera_ray(camera, 32.0f, 24.0f, {1.0f, 0.5f});  // (1, 0) on the unit disk
  for (const float depth : {2.0f, 8.0f, 20.0f}) {
    const float spread = length(at_depth(rim, camera, depth) - at_depth(centre, camera, depth));
    EXPECT_NEAR(spread, radius * std::fabs(depth - focus) / focus, 1e-4f) << depth;
  }
}

TEST(Camera, TheConcentricMapFillsTheDiskEvenly) {
  EXPECT_EQ(concentric_disk({0.5f, 0.5f}).x, 0.0f);
  constexpr int n = 64;
  double mean_r2 = 0.0;
  float largest = 0.0f;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Sample2D d = concentric_disk({(i + 0.5f) / n, (j + 0.5f) / n});
      const float r2 = d.x * d.x + d.y * d.y;
      mean_r2 += r2 / (n * n);
      largest = std::max(largest, r2);
    }
  EXPECT_LE(largest, 1.0f + 1e-6f);
  EXPECT_NEAR(mean_r2, 0.5, 1e-3);  // E[r²] = 1/2 for points uniform on the unit disk
}

// Two spheres, one on the plane in focus and one far behind it: with a lens, pixels across the
// near sphere's edge stay as they are through a pinhole while the far sphere's edge spreads.
TEST(Camera, ThePlaneInFocusStaysSharpAndTheRestBlurs) {
  RenderScene scene = test::empty_scene(96, 64);
  scene.render.spp = 64;
  scene.render.max_depth = 0;
  scene.top.geometries.emplace_back(SphereSet{{{{-1.2f, 0.0f, 0.0f}, 0.8f, 0}, {{6.0f, 0.0f, -30.0f}, 5.0f, 0}}});
  const auto render = [&](float aperture) {
    CameraDesc desc;
    desc.position = {0.0f, 0.0f, 10.0f};
    desc.look_at = {0.0f, 0.0f, 0.0f};
    desc.width = 96;
    desc.height = 64;
    desc.aperture = aperture;
    scene.camera = make_render_camera(desc);
    const auto backend = make_backend(BackendKind::kNative, scene, BackendOptions{});
    return render_image(scene, *backend, RenderOptions{}).image;
  };
  const Image pinhole = render(0.0f), lens = render(0.3f);
  // Mean absolute difference (green) over columns around each sphere, on the middle row band.
  const auto difference = [&](int x0, int x1) {
    double sum = 0.0;
    int count = 0;
    for (int y = 24; y < 40; ++y)
      for (int x = x0; x < x1; ++x, ++count) {
        const std::size_t i = (std::size_t(y) * 96 + std::size_t(x)) * 3 + 1;
        sum += std::fabs(pinhole.data[i] - lens.data[i]);
      }
    return sum / count;
  };
  const double near = difference(14, 44), far = difference(54, 96);
  EXPECT_LT(near, 0.01) << "the sphere on the plane in focus changed";
  EXPECT_GT(far, 5.0 * near + 0.01) << "the sphere far behind the plane in focus did not blur";
}

}  // namespace camera_test
}  // namespace rtpro
