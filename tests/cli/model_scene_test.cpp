// A model file as the whole scene, as a newcomer first tries rtpro: an OBJ or a PLY renders as a
// glTF does (a camera framing it, a light), `info` and `crosscheck` read it too, an extension
// rtpro does not read is refused naming what it reads, and what rtpro chose for the file (the
// framing camera, the default light, emissive-only lighting) is said in one line each, while a
// scene that nothing lights gets a warning and a lit one none.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace model_scene_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::run_rtpro;

// A unit tetrahedron, four faces wound outwards.
const std::string kTetrahedronObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const std::string kTetrahedronPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// The tetrahedron as a glTF file with no camera, no lights and nothing emissive.
std::filesystem::path bare_gltf(const std::string& name) {
  test::GltfFile gltf;
  const int positions = gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3");
  gltf.mesh(positions, gltf.indices({0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  gltf.node({{"mesh", 0}});
  gltf.scene({0});
  return gltf.write(name);
}

TEST(ModelScene, AnObjAndAPlyRenderDirectlyFramedAndLit) {
  const auto dir = test::scratch_dir();
  for (const auto& [name, text] : {std::pair{"tetra.obj", kTetrahedronObj}, std::pair{"tetra.ply", kTetrahedronPly}}) {
    const auto model = test::write_file(name, text);
    const auto out = dir / (std::string(name) + ".exr");
    const std::string said = run_rtpro(render_args(model, out, "--size 24x18 --spp 1"), 0);
    EXPECT_NE(said.find(std::string(name) + " has no camera: rtpro frames its bounds, [0, 0, 0] .. [1, 1, 1]"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("rtpro adds a directional light"), std::string::npos) << said;
    const Image image = read_image(out);
    // Framed: the model covers the centre, and it is lit (brighter than the grey sky around it).
    EXPECT_GT(image.at(12, 9, 0), image.at(0, 0, 0)) << name;
    EXPECT_GT(test::image_sum(image), 0.0);
    if (model.extension() == ".ply") expect_rtpro_answer("info " + model.string(), 0, "4 triangles");
    else run_rtpro("crosscheck " + model.string() + " --rays 200", 0);
  }
}

TEST(ModelScene, AnExtensionRtproDoesNotReadIsRefusedNamingWhatItReads) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("model.stl", "solid x\nendsolid x\n");
  expect_rtpro_answer("info " + scene.string(), 2, "model.stl: rtpro does not read '.stl' files as scenes");
  expect_rtpro_answer(render_args(scene, dir / "x.png"), 2, ".yaml, .yml or .json");
  expect_rtpro_answer("crosscheck " + scene.string(), 2, ".gltf, .glb, .obj or .ply");
}

TEST(ModelScene, WhatLightsAModelIsSaidAndAnUnlitSceneWarned) {
  const auto dir = test::scratch_dir();
  const auto obj = test::write_file("bare.obj", kTetrahedronObj);
  const auto gltf = bare_gltf("bare");
  for (const auto& model : {obj, gltf}) {
    const std::string said = run_rtpro(render_args(model, dir / "m.exr", "--size 8x6 --spp 1"), 0);
    EXPECT_NE(said.find("has no lights and nothing emissive: rtpro adds a directional light"), std::string::npos)
        << said;
    EXPECT_EQ(said.find("warning"), std::string::npos) << said;
  }
  // Lit only by what it emits: said, and no light added.
  test::GltfFile glowing;
  glowing.json["materials"] = nlohmann::json::array();
  glowing.json["materials"].push_back({{"name", "glow"}, {"emissiveFactor", {1, 1, 1}}});
  glowing.mesh(glowing.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  glowing.json["meshes"][0]["primitives"][0]["material"] = 0;
  glowing.node({{"mesh", 0}});
  glowing.scene({0});
  const std::string lit = run_rtpro("info " + glowing.write("glow").string(), 0);
  EXPECT_NE(lit.find("glow.gltf has no lights: it is lit only by emissive surfaces"), std::string::npos) << lit;
  EXPECT_NE(lit.find("0 point, 0 spot, 0 directional, 0 area"), std::string::npos) << lit;
  // A scene file that nothing lights is warned about, once, under either integrator; the demo is not.
  const auto dark = test::write_file("dark.yaml",
                                     "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0], resolution: [8, 6]}\n"
                                     "render: {integrator: path, spp: 1}\nworld:\n"
                                     "  - {type: sphere, center: [0, 0, 0], radius: 1}\n");
  expect_rtpro_answer(render_args(dark, dir / "d.exr"), 0, "warning: nothing lights the scene");
  expect_rtpro_answer(render_args(dark, dir / "d.exr", "--integrator whitted"), 0,
                      "warning: the scene has no lights: under the whitted integrator");
  expect_rtpro_answer("info " + dark.string(), 0, "note         warning: nothing lights the scene");
  // Cycles' light-path controls given to a whitted render are said to do nothing there.
  expect_rtpro_answer(
      render_args(test::scenes_dir() / "demo.yaml", dir / "w.exr", "--size 8x6 --spp 1 --clamp-direct 3"), 0,
      "warning: render.clamp_direct is read by the path integrator only; the whitted integrator renders without it");
  const std::string demo =
      run_rtpro(render_args(test::scenes_dir() / "demo.yaml", dir / "demo.exr", "--size 8x6 --spp 1"), 0);
  EXPECT_EQ(demo.find("warning"), std::string::npos) << demo;
  EXPECT_EQ(demo.find("lights"), std::string::npos) << demo;
}

}  // namespace model_scene_test
}  // namespace rtpro
