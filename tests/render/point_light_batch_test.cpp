// A point light's samples made four points at a time must be sample_point_light's, bit for bit
// (the path integrator uses them in place of LightSet::sample when one point light lights the
// scene), and LightSet must offer them only when its sample() would pick that light everywhere.
#include "point_light_batch.h"

#include "light_set.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace rtpro {
namespace point_light_batch_test {

bool same(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same(const Vec3& a, const Vec3& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }

// Points around the light, far and near, one exactly at it and one at a huge distance.
std::vector<SurfacePoint> points_around(const Vec3& light, std::size_t count) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<SurfacePoint> points(count);
  for (std::size_t i = 0; i < count; ++i) {
    const float scale = i % 7 == 0 ? 1e-3f : (i % 11 == 0 ? 1e19f : 5.0f);
    points[i].position = light + Vec3{unit(rng), unit(rng), unit(rng)} * scale;
  }
  if (count > 2) points[2].position = light;
  return points;
}

TEST(PointLightBatch, EverySampleIsTheScalarOneBitForBit) {
  const PointLight light{{1.0f, 2.0f, 3.0f}, {5.0f, 4.0f, 3.0f}};
  for (std::size_t count : {0u, 1u, 3u, 4u, 5u, 9u, 1001u}) {
    const std::vector<SurfacePoint> points = points_around(light.position, count);
    std::vector<PathLightSample> out(count);
    std::vector<std::uint8_t> found(count, 7);
    sample_point_light_batch(light, points, out, found);
    for (std::size_t i = 0; i < count; ++i) {
      PathLightSample expected{};
      const bool lit = sample_point_light(light, points[i].position, expected);
      ASSERT_EQ(found[i], lit ? 1 : 0) << "point " << i << " of " << count;
      if (!lit) continue;
      ASSERT_TRUE(same(out[i].direction, expected.direction) && same(out[i].radiance, expected.radiance) &&
                  same(out[i].distance, expected.distance) && same(out[i].pdf, expected.pdf) &&
                  out[i].delta == expected.delta)
          << "point " << i << " of " << count;
    }
  }
}

RenderScene scene_with(const std::string& lights, const std::string& world = "") {
  return build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 1, -5], look_at: [0, 1, 0]}
materials:
  lamp: {type: diffuse, color: [0, 0, 0], emission: [2, 1, 1]}
lights:
)" + lights + R"(
world:
  - {type: sphere, center: [0, 0, 0], radius: 0.5}
)" + world,
                                             "lights.yaml"));
}

TEST(PointLightBatch, LightSetOffersItsLonePointLightAndItsSamplesAreSamplesOnes) {
  const std::string point = "  - {type: point, position: [0, 3, 0], intensity: 5}\n";
  const RenderScene scene = scene_with(point);
  const LightSet lights(scene);
  ASSERT_TRUE(lights.lone_point_light().has_value());
  EXPECT_EQ(lights.lone_point_light()->index, 0u);
  const std::vector<SurfacePoint> points = points_around({0.0f, 3.0f, 0.0f}, 203);
  std::vector<PathLightSample> out(points.size());
  std::vector<std::uint8_t> found(points.size());
  LightSet::sample_lone_point_light(*lights.lone_point_light(), points, out, found);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::optional<PathLightSample> expected = lights.sample(points[i].position, 0.5f, {0.5f, 0.5f});
    ASSERT_EQ(found[i] != 0, expected.has_value()) << i;
    if (!expected) continue;
    ASSERT_TRUE(same(out[i].direction, expected->direction) && same(out[i].radiance, expected->radiance) &&
                same(out[i].distance, expected->distance) && same(out[i].pdf, expected->pdf) &&
                out[i].delta == expected->delta && out[i].light == expected->light)
        << i;
  }

  // Not when sample() picks among lights, nor for a light of another kind, nor an emitter.
  EXPECT_FALSE(LightSet(scene_with(point + point)).lone_point_light());
  EXPECT_FALSE(
      LightSet(scene_with("  - {type: directional, direction: [0, -1, 0], intensity: 1}\n")).lone_point_light());
  EXPECT_FALSE(LightSet(scene_with("", "  - {type: sphere, center: [2, 2, 2], radius: 0.5, material: lamp}\n"))
                   .lone_point_light());
  EXPECT_FALSE(LightSet(scene_with(point, "  - {type: sphere, center: [2, 2, 2], radius: 0.5, material: lamp}\n"))
                   .lone_point_light());
  // Nor with light linking, where what sample() picks depends on the object.
  EXPECT_FALSE(LightSet(scene_with("  - {type: point, name: key, position: [0, 3, 0], intensity: 5}\n",
                                   "  - {type: sphere, center: [2, 0, 0], radius: 0.5, "
                                   "light_linking: {not_illuminated_by: [key]}}\n"))
                   .lone_point_light());
}

}  // namespace point_light_batch_test
}  // namespace rtpro
