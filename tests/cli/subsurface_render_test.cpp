// Random-walk subsurface scattering through the rtpro binary, on both backends: the subsurface
// white furnace (an albedo-1 sphere in a uniform sky of radiance 1 vanishes, whatever its radius
// and however coloured), a thin slab lets more light through as its radius grows, and bad
// subsurface keys are refused at their file:line:column.
#include "rtpro/core/vec3.h"
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <regex>
#include <string>

namespace rtpro {
namespace subsurface_render_test {

Image render(const std::string& name, const std::string& text, const std::string& options) {
  const auto scene = test::write_file(name + ".yaml", text);
  const auto output = scene.parent_path() / (name + ".exr");
  test::run_rtpro(test::render_args(scene, output, "-q --no-journal " + options), 0);
  return read_image(output);
}

// The image's mean per channel.
Color channel_means(const Image& image) {
  Color sum(0.0f);
  const std::size_t pixels = image.data.size() / 3;
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += image.data[3 * i + c];
  return sum / static_cast<float>(pixels);
}

// Four spheres of subsurface albedo 1, one in each quadrant of the image, in a uniform sky: every
// walk leaves its sphere (the media absorb nothing), so the spheres vanish. The radii keep each
// sphere within a few mean free paths, where walks leave long before kMaxWalkSteps (which ends a
// walk, dark): the default specular layer over a plain walk, the same walk with a four times
// larger radius, an anisotropic walk, and coloured radii (the spectral MIS keeps each channel at 1).
TEST(SubsurfaceRender, WhiteFurnaceOnBothBackends) {
  for (const std::string backend : {"native", "embree"}) {
    const Image image = render("subsurface_furnace_" + backend, R"(rtpro: 1
camera: {position: [0, 0, -8], look_at: [0, 0, 0], fov: 20, resolution: [24, 24]}
render: {integrator: path, spp: 32, max_depth: 64, background: [1, 1, 1]}
materials:
  plain: {type: principled, color: [1, 1, 1], subsurface: 1, subsurface_scale: 1,
          subsurface_method: random_walk_fixed_radius, subsurface_radius: [6, 6, 6]}
  larger: {type: principled, color: [1, 1, 1], subsurface: 1, subsurface_scale: 4,
           subsurface_method: random_walk_fixed_radius, subsurface_radius: [6, 6, 6]}
  forward: {type: principled, color: [1, 1, 1], subsurface: 1, subsurface_scale: 1, specular_weight: 0,
            subsurface_method: random_walk_fixed_radius, subsurface_radius: [6, 6, 6], subsurface_anisotropy: 0.7}
  coloured: {type: principled, color: [1, 1, 1], subsurface: 1, subsurface_scale: 1, specular_weight: 0,
             subsurface_method: random_walk_fixed_radius, subsurface_radius: [12, 6, 3]}
world:
  - {type: sphere, center: [0.7, 0.7, 0], radius: 0.65, material: plain}
  - {type: sphere, center: [-0.7, 0.7, 0], radius: 0.65, material: larger}
  - {type: sphere, center: [0.7, -0.7, 0], radius: 0.65, material: forward}
  - {type: sphere, center: [-0.7, -0.7, 0], radius: 0.65, material: coloured}
)",
                               "--backend " + backend);
    // Per quadrant and channel (a fifth of each quadrant is sky, exactly 1).
    for (int quadrant = 0; quadrant < 4; ++quadrant) {
      Color sum(0.0f);
      for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
          const std::size_t pixel = std::size_t(12 * (quadrant / 2) + y) * 24 + std::size_t(12 * (quadrant % 2) + x);
          for (int c = 0; c < 3; ++c) sum[c] += image.data[3 * pixel + c];
        }
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c] / 144.0f, 1.0f, 0.02f) << backend << ", quadrant " << quadrant << ", channel " << c;
    }
  }
}

// Light through a slab 0.2 thick: a quad light behind it, the camera in front sees only what the
// walks carry through. Radii of a tenth and of twice the thickness.
float slab_transmission(const std::string& backend, const std::string& radius) {
  const auto slab = test::write_file("subsurface_slab.obj", R"(v -2 -2 -0.1
v 2 -2 -0.1
v 2 2 -0.1
v -2 2 -0.1
v -2 -2 0.1
v 2 -2 0.1
v 2 2 0.1
v -2 2 0.1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
)");
  const Image image = render("subsurface_slab_" + backend, R"(rtpro: 1
camera: {position: [0, 0, -3], look_at: [0, 0, 0], fov: 10, resolution: [8, 8]}
render: {integrator: path, spp: 16, max_depth: 16}
lights:
  - {type: quad, position: [0, 0, 0.5], edge1: [0, 2, 0], edge2: [2, 0, 0], color: [1, 1, 1], intensity: 1}
materials:
  wax: {type: principled, color: [0.8, 0.8, 0.8], specular_weight: 0, subsurface: 1, subsurface_scale: 1,
        subsurface_radius: )" + radius + R"(}
world:
  - {type: mesh, file: )" + slab.string() + R"(, material: wax}
)",
                             "--backend " + backend);
  const Color mean = channel_means(image);
  return (mean.x + mean.y + mean.z) / 3.0f;
}

TEST(SubsurfaceRender, ThinSlabTransmitsMoreWithALargerRadius) {
  for (const std::string backend : {"native", "embree"}) {
    const float narrow = slab_transmission(backend, "[0.02, 0.02, 0.02]");
    const float wide = slab_transmission(backend, "[0.4, 0.4, 0.4]");
    std::cout << "[slab] " << backend << ": radius 0.02 " << narrow << ", radius 0.4 " << wide << "\n";
    EXPECT_GT(wide, 0.01f) << backend;
    EXPECT_GT(wide, 2.0f * narrow) << backend;
  }
}

TEST(SubsurfaceRender, BadSubsurfaceKeysAreRefusedWhereWritten) {
  const auto refuse = [](const std::string& keys, const std::string& text) {
    const auto scene = test::write_file("bad_subsurface.yaml", R"(rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0]}
materials:
  skin: {type: principled, )" + keys + R"(}
)");
    const std::string answer = test::expect_rtpro_answer("info " + scene.string(), 2, text);
    EXPECT_TRUE(std::regex_search(answer, std::regex(scene.filename().string() + ":4:[0-9]+: "))) << answer;
  };
  refuse("subsurface: 1, subsurface_radius: [1, -0.2, 0.1]", "subsurface_radius");
  refuse("subsurface: 1, subsurface_radius: [1, .nan, 0.1]", "subsurface_radius");
  refuse("subsurface: 1, subsurface_radius: [1, 0, 0.1]", "above 0 in each channel");
  refuse("subsurface: 1, subsurface_scale: 0", "above 0");
  refuse("subsurface: 1, subsurface_scale: -1", "subsurface_scale");
  refuse("subsurface: 1, subsurface_anisotropy: 0.95", "from 0 to 0.9");
  refuse("subsurface: 1.5", "from 0 to 1");
  refuse("subsurface: 1, subsurface_method: burley", "random_walk or random_walk_fixed_radius");
}

}  // namespace subsurface_render_test
}  // namespace rtpro
