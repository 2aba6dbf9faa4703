// Motion blur (scene/motion.h) against what it must integrate: an emissive quad crossing the frame
// at constant speed blurs into the box filter's trapezoid with the static image's energy, a bar
// turned 90° lights its arc and not the chord, both backends agree, and an open shutter on a
// static scene changes nothing.
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
namespace motion_blur_test {

constexpr BackendKind kBackends[] = {BackendKind::kNative, BackendKind::kEmbree};

// A camera at z = -10 looking along +z whose pixels are `pixel` scene units wide on the plane z = 0,
// an emissive material (index 1) and nothing else; the shutter spans the frame.
RenderScene camera_scene(int width, int height, float pixel, int spp, const std::string& shutter = "[0, 1]") {
  const double fov = 2.0 * std::atan(pixel * height / 2.0 / 10.0) * 180.0 / 3.14159265358979323846;
  const std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, -10], look_at: [0, 0, 0], fov: " + std::to_string(fov) + ", resolution: [" +
      std::to_string(width) + ", " + std::to_string(height) + "], shutter: " + shutter +
      "}\nrender: {integrator: path, spp: " + std::to_string(spp) +
      ", max_depth: 1}\nmaterials: {glow: {type: diffuse, color: [0, 0, 0], emission: [1, 1, 1]}}\n";
  return build_render_scene(parse_scene_text(text, "motion.yaml", {}));
}

// A rectangle [x0, x1] × [y0, y1] in the plane z = 0, emitting towards the camera.
TriangleMesh quad(float x0, float x1, float y0, float y1) {
  TriangleMesh mesh;
  mesh.vertices = {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};  // facing the camera (−z)
  mesh.material = 1;
  return mesh;
}

VertexArray shifted(const VertexArray& vertices, float dx) {
  VertexArray out = vertices;
  for (MeshVertex& v : out) v.x += dx;
  return out;
}

// The prototype `shape` placed by an instance moving through `steps`.
void add_moving_instance(RenderScene& scene, Geometry shape, std::vector<Affine> steps) {
  scene.prototypes.push_back(Group{{std::move(shape)}});
  Instance instance{static_cast<std::uint32_t>(scene.prototypes.size() - 1), steps.front(), *inverse(steps.front()),
                    std::move(steps)};
  scene.top.geometries.emplace_back(std::move(instance));
}

Image render(const RenderScene& scene, BackendKind kind, int threads = 1) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, threads);
  BackendOptions options;
  options.threads = threads;
  const auto backend = make_backend(kind, scene, options);
  return render_image(scene, *backend, {}).image;
}

double red_sum(const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) sum += image.at(x, y, 0);
  return sum;
}

// The quad: 8 pixels wide, crossing 32 pixels of a 64-pixel row during the shutter.
constexpr int kWidth = 64, kHeight = 4;
constexpr float kPixel = 0.1f, kQuadWidth = 0.8f, kTravel = 3.2f, kStart = -2.0f;

// The fraction of the shutter during which the quad covers world x = s (the image's x runs
// along −x: cross(forward, up) with forward +z).
double covered_time(double s) {
  const double from = std::max(0.0, (s - kStart - kQuadWidth) / kTravel);
  const double to = std::min(1.0, (s - kStart) / kTravel);
  return std::max(0.0, to - from);
}

// Pixel x's expected value: the covered time averaged over the pixel's footprint (box filter).
double expected_pixel(int x) { return test::box_filtered_coverage(x, kWidth, kPixel, covered_time); }

void expect_trapezoid(const Image& image, const char* what) {
  double worst = 0.0;
  for (int x = 0; x < kWidth; ++x) {
    double row_mean = 0.0;
    for (int y = 0; y < kHeight; ++y) row_mean += image.at(x, y, 0) / kHeight;
    worst = std::max(worst, std::fabs(row_mean - expected_pixel(x)));
  }
  // 1% of the quad's radiance (1): the profile's plateau is 0.25, its ramps 8 pixels long.
  EXPECT_LT(worst, 0.01) << what;
}

TEST(MotionBlur, QuadCrossingTheFrameBlursIntoTheTrapezoidWithTheStaticEnergy) {
  for (BackendKind kind : kBackends) {
    RenderScene still = camera_scene(kWidth, kHeight, kPixel, 256, "[0, 0]");
    still.top.geometries.emplace_back(quad(kStart + kTravel / 2, kStart + kTravel / 2 + kQuadWidth, -1, 1));
    const double still_energy = red_sum(render(still, kind));
    ASSERT_NEAR(still_energy, 8 * kHeight, 0.05);

    RenderScene by_instance = camera_scene(kWidth, kHeight, kPixel, 256);
    add_moving_instance(by_instance, quad(0, kQuadWidth, -1, 1),
                        {Affine::translate({kStart, 0, 0}), Affine::translate({kStart + kTravel, 0, 0})});
    const Image moved = render(by_instance, kind);
    EXPECT_NEAR(red_sum(moved), still_energy, 0.005 * still_energy) << backend_name(kind);
    expect_trapezoid(moved, "instance");

    RenderScene deformed = camera_scene(kWidth, kHeight, kPixel, 256);
    TriangleMesh mesh = quad(kStart, kStart + kQuadWidth, -1, 1);
    mesh.vertex_steps = {mesh.vertices, shifted(mesh.vertices, kTravel)};
    deformed.top.geometries.emplace_back(std::move(mesh));
    const Image bent = render(deformed, kind);
    EXPECT_NEAR(red_sum(bent), still_energy, 0.005 * still_energy) << backend_name(kind);
    expect_trapezoid(bent, "deforming mesh");
  }
}

// A trapezoid shutter exposes the quad's path as it exposes time: each point of the row is lit for
// the shutter's exposure while the quad covers it (the ramps weigh the ends of the path less),
// with the static image's energy.
TEST(MotionBlur, ShutterOpeningWeighsThePathAsItExposesTime) {
  static constexpr double kOpening = 0.25, kClosing = 0.75, kExposure = 0.5 * (1.0 + kClosing - kOpening);
  const auto exposed_until = [](double t) {
    t = std::clamp(t, 0.0, 1.0);
    double area = 0.5 * std::min(t, kOpening) * std::min(t, kOpening) / kOpening;
    if (t > kOpening) area += std::min(t, kClosing) - kOpening;
    if (t > kClosing) area += 0.5 * (1.0 - kClosing) - 0.5 * (1.0 - t) * (1.0 - t) / (1.0 - kClosing);
    return area / kExposure;
  };
  const auto exposed_while_covered = [&](double s) {
    const double from = std::max(0.0, (s - kStart - kQuadWidth) / kTravel);
    const double to = std::min(1.0, (s - kStart) / kTravel);
    return to > from ? exposed_until(to) - exposed_until(from) : 0.0;
  };
  for (BackendKind kind : kBackends) {
    RenderScene scene = camera_scene(kWidth, kHeight, kPixel, 256);
    scene.camera.shutter.opening = static_cast<float>(kOpening);
    scene.camera.shutter.closing = static_cast<float>(kClosing);
    add_moving_instance(scene, quad(0, kQuadWidth, -1, 1),
                        {Affine::translate({kStart, 0, 0}), Affine::translate({kStart + kTravel, 0, 0})});
    const Image image = render(scene, kind);
    EXPECT_NEAR(red_sum(image), 8 * kHeight, 0.005 * 8 * kHeight) << backend_name(kind);
    double worst = 0.0, worst_box = 0.0;
    for (int x = 0; x < kWidth; ++x) {
      double row_mean = 0.0;
      for (int y = 0; y < kHeight; ++y) row_mean += image.at(x, y, 0) / kHeight;
      worst =
          std::max(worst, std::fabs(row_mean - test::box_filtered_coverage(x, kWidth, kPixel, exposed_while_covered)));
      worst_box = std::max(worst_box, std::fabs(row_mean - expected_pixel(x)));
    }
    EXPECT_LT(worst, 0.01) << backend_name(kind);
    EXPECT_GT(worst_box, 0.03) << backend_name(kind) << ": the profile should differ from a box shutter's";
  }
}

// A bar from the centre to radius 1.5 turned by 90° about the view axis during the shutter.
Image spun_bar(BackendKind kind, const std::vector<Affine>& steps) {
  RenderScene scene = camera_scene(40, 40, 0.1f, 32);
  add_moving_instance(scene, quad(0.0f, 1.5f, -0.06f, 0.06f), steps);
  return render(scene, kind);
}

std::vector<Affine> turn_steps(int count) {
  std::vector<Affine> steps;
  for (int i = 0; i < count; ++i) steps.push_back(Affine::rotate({0, 0, 1}, 90.0f * i / (count - 1)));
  return steps;
}

float largest_difference(const Image& a, const Image& b) {
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.data.size(); ++i) worst = std::max(worst, std::fabs(a.data[i] - b.data[i]));
  return worst;
}

// Pixels that one image lights and the other leaves black.
int pixels_lit_differently(const Image& a, const Image& b) {
  int count = 0;
  for (std::size_t i = 0; i < a.data.size(); i += 3) count += (a.data[i] > 0.0f) != (b.data[i] > 0.0f);
  return count;
}

TEST(MotionBlur, TurnedBarLightsItsArcNotTheChord) {
  const std::vector<Affine> sampled = sample_transform_motion(Shutter{0.0f, 1.0f}, 0.0, [](double t) {
    return Affine::rotate({0, 0, 1}, static_cast<float>(90.0 * t));
  });
  ASSERT_GT(sampled.size(), 2u);
  for (BackendKind kind : kBackends) {
    const Image reference = spun_bar(kind, turn_steps(65));  // 64 segments
    const Image image = spun_bar(kind, sampled);
    // Lit only within the swept quarter disc (one pixel's margin) ...
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        // Pixel centre on the plane z = 0 (image x along −x).
        const float wx = -(x + 0.5f - 20.0f) * 0.1f, wy = (20.0f - y - 0.5f) * 0.1f;
        const bool near_arc = std::hypot(wx, wy) < 1.5f + 0.15f && wx > -0.15f && wy > -0.15f;
        if (!near_arc) {
          EXPECT_EQ(image.at(x, y, 0), 0.0f) << "pixel " << x << "," << y;
        }
      }
    // ... as the 64-segment reference lights it, where the two-step chord (its middle pulled in to
    // cos 45° of the radius) visibly does not.
    EXPECT_LT(largest_difference(image, reference), 0.07f) << backend_name(kind);
    EXPECT_LE(pixels_lit_differently(image, reference), 2) << backend_name(kind);
    EXPECT_GE(pixels_lit_differently(spun_bar(kind, turn_steps(2)), reference), 20) << backend_name(kind);
  }
}

TEST(MotionBlur, MovingSpheresAreBitIdenticalAcrossBackendsAndThreads) {
  RenderScene scene = camera_scene(48, 32, 0.1f, 8);
  SphereSet set;
  set.spheres = {{{-1.0f, 0.5f, 0.0f}, 0.4f, 1}, {{0.5f, -0.6f, 0.5f}, 0.5f, 0}, {{0.0f, 0.0f, 3.0f}, 2.0f, 0}};
  set.step_count = 3;
  set.center_steps = {{-1.0f, 0.5f, 0.0f}, {0.0f, 0.7f, 0.0f},  {1.0f, 0.5f, 0.0f},  // sphere 0
                      {0.5f, -0.6f, 0.5f}, {0.5f, -0.6f, 0.5f}, {0.5f, -0.6f, 0.5f},
                      {0.0f, 0.0f, 3.0f},  {0.0f, 0.0f, 2.0f},  {0.0f, 0.0f, 3.0f}};
  scene.top.geometries.emplace_back(std::move(set));
  const Image reference = render(scene, BackendKind::kNative, 1);
  ASSERT_GT(red_sum(reference), 10.0);
  for (BackendKind kind : kBackends)
    for (int threads : {1, 2}) {
      const Image image = render(scene, kind, threads);
      EXPECT_EQ(std::memcmp(image.data.data(), reference.data.data(), image.data.size() * sizeof(float)), 0)
          << backend_name(kind) << " at " << threads << " threads";
    }
}

TEST(MotionBlur, DeformingTrianglesAgreeAcrossBackendsWithinTheTolerance) {
  RenderScene scene = camera_scene(48, 32, 0.1f, 8);
  TriangleMesh mesh = quad(-1.0f, 0.5f, -0.8f, 0.8f);
  VertexArray bent = mesh.vertices;
  bent[2].y += 0.6f;
  bent[2].z -= 1.0f;
  mesh.vertex_steps = {mesh.vertices, bent, shifted(bent, 0.8f)};
  scene.top.geometries.emplace_back(std::move(mesh));
  add_moving_instance(scene, quad(0.0f, 0.4f, 0.0f, 0.4f),
                      {Affine::translate({-0.5f, -1.2f, -0.5f}), Affine::translate({1.0f, -0.6f, -0.5f})});
  const Image native = render(scene, BackendKind::kNative);
  const Image embree = render(scene, BackendKind::kEmbree);
  ASSERT_GT(red_sum(native), 20.0);
  // docs/backends.md: mesh and instance scenes may differ in 0.1% of pixels by over 1e-3.
  int over = 0;
  for (std::size_t i = 0; i < native.data.size(); ++i) over += std::fabs(native.data[i] - embree.data[i]) > 1e-3f;
  EXPECT_LE(over, static_cast<int>(native.data.size() / 1000));
}

// camera_scene under the Whitted integrator: a white diffuse material (index 1), lit only by
// `lighting` (YAML: an ambient term and lights).
RenderScene whitted_scene(int width, int height, const std::string& lighting) {
  const double fov = 2.0 * std::atan(kPixel * height / 2.0 / 10.0) * 180.0 / 3.14159265358979323846;
  const std::string text = "rtpro: 1\ncamera: {position: [0, 0, -10], look_at: [0, 0, 0], fov: " + std::to_string(fov) +
                           ", resolution: [" + std::to_string(width) + ", " + std::to_string(height) +
                           "], shutter: [0, 1]}\nrender: {integrator: whitted, spp: 256, max_depth: 1, background: "
                           "[0, 0, 0], " +
                           lighting + "\nmaterials: {white: {type: diffuse, color: [1, 1, 1]}}\n";
  return build_render_scene(parse_scene_text(text, "whitted_motion.yaml", {}));
}

TEST(MotionBlur, WhittedCameraRaysBlurIntoTheTrapezoid) {
  for (BackendKind kind : kBackends) {
    RenderScene scene = whitted_scene(kWidth, kHeight, "ambient: 1}");
    add_moving_instance(scene, quad(0, kQuadWidth, -1, 1),
                        {Affine::translate({kStart, 0, 0}), Affine::translate({kStart + kTravel, 0, 0})});
    expect_trapezoid(render(scene, kind), backend_name(kind).data());
  }
}

// A floor lit by a point light at the camera's pinhole and a black occluder crossing in front of it:
// a camera ray that reaches the floor has its shadow ray retrace it at the same time, so the floor
// darkens only by the occluder's own blurred coverage (a shadow ray at another time would darken
// it where the occluder was then).
TEST(MotionBlur, WhittedShadowRaysKeepTheirCameraRaysTime) {
  constexpr float kDepth = -0.5f, kScale = (10.0f + kDepth) / 10.0f;  // the occluder's plane
  for (BackendKind kind : kBackends) {
    RenderScene floor = whitted_scene(kWidth, kHeight, "ambient: 0}\nlights: [{type: point, position: [0, 0, -10]}]");
    floor.materials[0].whitted = {Color(0.0f), 0.0f, 1.0f, 0.0f, {}};  // the default material: the occluder, black
    floor.top.geometries.emplace_back(quad(-4, 4, -1, 1));
    RenderScene scene = floor;
    TriangleMesh occluder = quad(0, kQuadWidth * kScale, -1, 1);
    occluder.material = 0;
    add_moving_instance(
        scene, std::move(occluder),
        {Affine::translate({kStart * kScale, 0, kDepth}), Affine::translate({(kStart + kTravel) * kScale, 0, kDepth})});
    const Image lit = render(floor, kind), blurred = render(scene, kind);
    Image shadow = blurred;
    for (std::size_t i = 0; i < shadow.data.size(); ++i) shadow.data[i] = 1.0f - blurred.data[i] / lit.data[i];
    expect_trapezoid(shadow, backend_name(kind).data());
  }
}

// A subsurface sphere (radius 0.6, flights of about 0.05) under a white sky, on the path of the
// quad above when `moving`, else at rest in the middle of it: moving through a uniform sky it
// returns the light it returns at rest, as long as its walks meet it where its camera rays did.
RenderScene subsurface_sphere(bool moving) {
  const std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, -10], look_at: [0, 0, 0], fov: 16, resolution: [24, 8], "
      "shutter: [0, 1]}\nrender: {integrator: path, spp: 64, max_depth: 4, background: [1, 1, 1]}\n"
      "materials: {jade: {type: principled, color: [0.3, 0.3, 0.3], roughness: 1, specular_weight: 0, "
      "subsurface: 1, subsurface_radius: [1, 1, 1], subsurface_scale: 0.05}}\n";
  RenderScene scene = build_render_scene(parse_scene_text(text, "subsurface_motion.yaml", {}));
  const float centre = kStart + kTravel / 2;
  add_moving_instance(
      scene, SphereSet{{{{0.0f, 0.0f, 0.0f}, 0.6f, 1}}},
      moving ? std::vector<Affine>{Affine::translate({kStart, 0, 0}), Affine::translate({kStart + kTravel, 0, 0})}
             : std::vector<Affine>{Affine::translate({centre, 0, 0}), Affine::translate({centre, 0, 0})});
  return scene;
}

TEST(MotionBlur, SubsurfaceWalksTraceAtTheirPathsTime) {
  for (BackendKind kind : kBackends) {
    // What the sphere takes from the white sky behind it.
    const double still = 24 * 8 - red_sum(render(subsurface_sphere(false), kind));
    const double blurred = 24 * 8 - red_sum(render(subsurface_sphere(true), kind));
    EXPECT_NEAR(blurred, still, 0.03 * still) << backend_name(kind);
  }
}

TEST(MotionBlur, OpenShutterOnAStaticSceneChangesNoPixel) {
  for (BackendKind kind : kBackends) {
    RenderScene closed = camera_scene(32, 16, 0.1f, 4, "[0, 0]");
    closed.top.geometries.emplace_back(quad(-1.0f, 0.5f, -0.3f, 0.6f));
    RenderScene open = closed;
    open.camera.shutter = {-0.5f, 0.5f};
    const Image a = render(closed, kind), b = render(open, kind);
    ASSERT_GT(red_sum(a), 10.0);
    EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0) << backend_name(kind);
  }
}

}  // namespace motion_blur_test
}  // namespace rtpro
