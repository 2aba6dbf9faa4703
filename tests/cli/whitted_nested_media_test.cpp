// Whitted's one tracked medium where two media overlap, as the liquid of scenes/media.yaml's glass
// reaches into the glass's wall: a ray entering a clear glass, then the liquid, then leaving the
// glass's back is still in the liquid, which absorbs up to its own far surface.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace whitted_nested_media_test {

TEST(WhittedNestedMedia, LeavingAnOuterGlassByItsBackKeepsTheLiquidAbsorbing) {
  // Along the x axis: the clear sphere spans [-1, 1], the liquid (σa = 1) [0.5, 2.5]. Both are
  // interfaces (glass of index 1 under whitted: no bending, no reflection), so the axis ray
  // crosses 2 units of liquid: exp(−2), where dropping the liquid at x = 1 would give exp(−0.5).
  for (const std::string backend : {"native", "embree"}) {
    const auto scene = test::write_file("whitted_nested_" + backend + ".yaml", R"(rtpro: 1
camera: {position: [-6, 0, 0], look_at: [0, 0, 0], fov: 0.2, resolution: [3, 3]}
render: {integrator: whitted, spp: 1, max_depth: 8, background: [1, 1, 1]}
materials:
  clear: {type: interface}
  liquid: {type: interface, interior: {sigma_a: [1, 1, 1]}}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: clear}
  - {type: sphere, center: [1.5, 0, 0], radius: 1, material: liquid}
)");
    const auto output = scene.parent_path() / ("whitted_nested_" + backend + ".exr");
    test::run_rtpro(test::render_args(scene, output, "-q --no-journal --backend " + backend), 0);
    const Image image = read_image(output);
    for (const float v : image.data) EXPECT_NEAR(v, std::exp(-2.0f), 1e-3f) << backend;
  }
}

}  // namespace whitted_nested_media_test
}  // namespace rtpro
