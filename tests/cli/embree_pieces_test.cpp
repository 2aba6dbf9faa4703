// --embree-pieces: a large mesh built by the Embree backend one compact piece at a time renders
// the image of the mesh built whole, while the build holds less at once; a piece size too small
// to pay is refused.
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

namespace rtpro {
namespace embree_pieces_test {

std::filesystem::path grid_scene() {
  // A bumpy, smoothly shaded 90 × 90 grid: 16,200 triangles, four pieces of 4096.
  test::write_file("grid.obj", test::bumpy_grid_obj(90, 1.0 / 30.0, 0.15, 0.4, 0.3));
  return test::write_file("scene.yaml", R"(rtpro: 1
camera: {position: [1.5, -2.5, 3], look_at: [1.5, 1.5, 0], fov: 50, resolution: [48, 36]}
render: {integrator: path, spp: 4, max_depth: 3}
materials:
  clay: {type: diffuse, color: [0.7, 0.6, 0.5]}
lights:
  - {type: point, position: [1, -1, 4], color: [1, 1, 1], intensity: 30}
world:
  - {type: mesh, file: grid.obj, material: clay, normals: smooth}
  - {type: sphere, center: [1.5, 1.5, 0.6], radius: 0.4, material: clay}
)");
}

double build_peak_of(const std::filesystem::path& stats) {
  std::ifstream in(stats);
  return nlohmann::json::parse(in)["memory_bytes"]["acceleration_build_peak"].get<double>();
}

TEST(EmbreePiecesOption, TheImageIsTheWholeMeshsAndTheBuildHoldsLess) {
  const auto scene = grid_scene();
  const auto dir = scene.parent_path();
  test::run_rtpro(test::render_args(scene, dir / "whole.exr", "--stats-json " + (dir / "whole.json").string()), 0);
  test::run_rtpro(test::render_args(scene, dir / "pieces.exr",
                                    "--embree-pieces 4096 --stats-json " + (dir / "pieces.json").string()),
                  0);
  test::expect_same_pixels(dir / "whole.exr", dir / "pieces.exr");
  EXPECT_LT(build_peak_of(dir / "pieces.json"), build_peak_of(dir / "whole.json"));
}

TEST(EmbreePiecesOption, APieceSizeBelowTheFloorIsRefused) {
  const auto scene = grid_scene();
  test::expect_rtpro_answer(test::render_args(scene, scene.parent_path() / "x.exr", "--embree-pieces 100"), 2,
                            "--embree-pieces must be 0 (whole meshes) or at least 4096 triangles, got 100");
  EXPECT_FALSE(std::filesystem::exists(scene.parent_path() / "x.exr"));
}

}  // namespace embree_pieces_test
}  // namespace rtpro
