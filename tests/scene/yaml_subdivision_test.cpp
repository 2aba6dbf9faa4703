#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace yaml_subdivision_test {

constexpr const char* kCube =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

SceneDescription parse_entry(const std::string& entry) {
  const auto cube = test::write_file("cube.obj", kCube);
  const std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0]}\nworld:\n  - {type: mesh, "
      "file: cube.obj, " +
      entry + "}\n";
  return parse_scene_text(text, cube.parent_path() / "scene.yaml");
}

std::string error_of(const std::string& entry) {
  return test::error_message_of<InputError>([&] { build_render_scene(parse_entry(entry)); });
}

TEST(YamlSubdivision, ReadsEveryKey) {
  const SceneDescription scene = parse_entry(
      "subdivision: {scheme: loop, level: 3, edge_length: 2.5, creases: [[0, 1, 2.5]], corners: [[7, 10]]}");
  const SubdivisionDesc& s = *scene.world.meshes.at(0).subdivision;
  EXPECT_EQ(s.scheme, SubdivisionScheme::kLoop);
  EXPECT_EQ(s.level, 3);
  EXPECT_FLOAT_EQ(s.edge_length, 2.5f);
  ASSERT_EQ(s.creases.size(), 1u);
  EXPECT_EQ(s.creases[0].v1, 1u);
  EXPECT_FLOAT_EQ(s.creases[0].sharpness, 2.5f);
  ASSERT_EQ(s.corners.size(), 1u);
  EXPECT_EQ(s.corners[0].vertex, 7u);
  EXPECT_EQ(s.creases[0].where.line, 4);
}

TEST(YamlSubdivision, RefinesTheCageWhenBuilt) {
  const RenderScene scene = build_render_scene(parse_entry("subdivision: {level: 2}"));
  EXPECT_EQ(std::get<TriangleMesh>(scene.top.geometries.at(0)).triangles.size(), 6u * 16u * 2u);
}

std::size_t prototype_triangles(const RenderScene& scene) {
  std::size_t triangles = 0;
  for (const Group& group : scene.prototypes)
    for (const Geometry& geometry : group.geometries)
      if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) triangles += mesh->triangles.size();
  return triangles;
}

// glTF has no subdivision of its own: the entry refines every mesh the file draws.
TEST(YamlSubdivision, AGltfEntryRefinesEveryMeshOfTheFile) {
  const auto scene = [](const std::string& keys) {
    const std::string text =
        "rtpro: 1\ncamera: {position: [0, 1, 3.5], look_at: [0, 1, 0]}\nworld:\n"
        "  - {type: mesh, file: cornell_box.gltf" +
        keys + "}\n";
    return build_render_scene(parse_scene_text(text, test::scenes_dir() / "scene.yaml"));
  };
  EXPECT_EQ(prototype_triangles(scene(", subdivision: {scheme: loop, level: 1}")), 4 * prototype_triangles(scene("")));
}

TEST(YamlSubdivision, BadValuesAreErrorsAtTheirPlace) {
  EXPECT_NE(error_of("subdivision: {level: 13}").find("from 0 to 12"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {scheme: doo-sabin, level: 1}").find("catmull-clark"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {scheme: catmull-clark}").find("level"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {level: 1, creases: [[0, 1]]}").find("[v0, v1, sharpness]"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {level: 1, corners: [[0, 11]]}").find("sharpness"), std::string::npos);
  EXPECT_NE(error_of("displacement: {value: 1}").find("needs `subdivision:`"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {level: 1}, displacement: {value: 1, bound: 0.5}").find("beyond bound"),
            std::string::npos);
  EXPECT_NE(error_of("subdivision: {level: 1}, displacement: {scale: 1}").find("exactly one"), std::string::npos);
  EXPECT_NE(error_of("subdivision: {scheme: loop, level: 1}").find("face 1 has 4 corners"), std::string::npos);
  const std::string crease = error_of("subdivision: {level: 1, creases: [[0, 8, 1]]}");
  EXPECT_NE(crease.find("scene.yaml:4:"), std::string::npos) << crease;
  EXPECT_NE(crease.find("out of range"), std::string::npos) << crease;
}

}  // namespace yaml_subdivision_test
}  // namespace rtpro
