#include "test_fixtures.h"

#include "rtpro/image/image_io.h"
#include "rtpro/scene/mesh_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <string>

namespace rtpro::test {

std::string bumpy_grid_obj(int n, double spacing, double amplitude, double fx, double fy) {
  std::string obj;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      obj += "v " + std::to_string(x * spacing) + " " + std::to_string(y * spacing) + " " +
             std::to_string(amplitude * std::sin(fx * x) * std::cos(fy * y)) + "\n";
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 1, d = c + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
    }
  return obj;
}

std::string white_furnace_scene(const std::string& material, int size, int spp) {
  const std::string resolution = std::to_string(size);
  return R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 20, resolution: [)" +
         resolution + ", " + resolution + R"(]}
render: {integrator: path, spp: )" +
         std::to_string(spp) + R"(, max_depth: 64, background: [1, 1, 1]}
materials:
  glass: )" +
         material +
         R"(
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}
)";
}

Image uniform_image(int width, int height, float value) {
  Image image(width, height);
  std::fill(image.data.begin(), image.data.end(), value);
  return image;
}

Image gradient_image(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.1f * x + 0.01f * y + 0.3f * c;
  return image;
}

double image_sum(const Image& image) {
  double sum = 0.0;
  for (const float value : image.data) sum += value;
  return sum;
}

InputError mesh_load_error(const std::filesystem::path& file) {
  try {
    load_mesh_file(file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << file;
  return InputError("none");
}

void expect_same_pixels(const std::filesystem::path& reference, const std::filesystem::path& test) {
  const Image a = read_image(reference), b = read_image(test);
  ASSERT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0)
      << test << " differs from " << reference;
}

void expect_same_channels(const Image& expected, const Image& actual) {
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  ASSERT_EQ(actual.channel_count(), expected.channel_count());
  for (int c = 0; c < expected.channel_count(); ++c) {
    const auto found = std::find(actual.channels.begin(), actual.channels.end(), expected.channels[c]);
    ASSERT_NE(found, actual.channels.end()) << expected.channels[c];
    const int actual_c = static_cast<int>(found - actual.channels.begin());
    for (int y = 0; y < expected.height; ++y)
      for (int x = 0; x < expected.width; ++x)
        ASSERT_EQ(std::bit_cast<std::uint32_t>(actual.at(x, y, actual_c)),
                  std::bit_cast<std::uint32_t>(expected.at(x, y, c)))
            << expected.channels[c] << " at " << x << "," << y;
  }
}

}  // namespace rtpro::test
