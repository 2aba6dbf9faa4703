// Light linking in the scene file (yaml_light_linking.cpp): light names, world entries'
// light_linking and shadow_linking read into the description, grouped by build_render_scene (the
// world's spheres one by one, meshes, glTF placements and instances object by object), and each
// mistake refused where it was made.
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro {
namespace yaml_light_linking_test {

// The lights are on lines 4-6; the world starts on line 10.
const std::string kHead =
    "rtpro: 1\n"
    "camera: {position: [0, 1, -5], look_at: [0, 0, 0]}\n"
    "lights:\n"
    "  - {type: point, name: key, position: [0, 5, 0]}\n"
    "  - {type: spot, name: rim, position: [3, 3, 3], look_at: [0, 0, 0]}\n"
    "  - {type: directional, direction: [0, -1, 0]}\n"
    "objects:\n"
    "  pair: [{type: sphere, center: [1, 0, 0]}, {type: sphere, center: [-1, 0, 0]}]\n"
    "world:\n";

SceneDescription parse(const std::string& world) { return parse_scene_text(kHead + world, "link.yaml"); }

// The error `world` gets: on `line` at the first `token` of the line, saying each fragment.
void expect_error(const std::string& world, int line, const std::string& token,
                  const std::vector<std::string>& fragments) {
  SCOPED_TRACE(world);
  const std::string text = kHead + world;
  std::size_t start = 0;
  for (int l = 1; l < line; ++l) start = text.find('\n', start) + 1;
  const std::size_t column = text.find(token, start);
  ASSERT_NE(column, std::string::npos);
  try {
    parse_scene_text(text, "link.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, line) << error.what();
    EXPECT_EQ(error.where().column, static_cast<int>(column - start) + 1) << error.what();
    for (const std::string& fragment : fragments)
      EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
  }
}

TEST(YamlLightLinking, LightsKeepTheirNamesAndEntriesTheirLists) {
  const SceneDescription scene = parse(
      "  - {type: sphere, light_linking: {not_illuminated_by: [rim]}}\n"
      "  - {type: sphere}\n"
      "  - {type: instance, object: pair, light_linking: {illuminated_by: [key]}, shadow_linking: {shadows_from: "
      "[]}}\n");
  EXPECT_EQ(scene.light_names, (std::vector<std::string>{"key", "rim", ""}));
  ASSERT_EQ(scene.linkings.size(), 2u);
  EXPECT_EQ(scene.world.spheres[0].linking, 0u);
  EXPECT_EQ(scene.world.spheres[1].linking, kNoLinking);
  EXPECT_EQ(scene.world.instances[0].linking, 1u);
  ASSERT_TRUE(scene.linkings[0].illumination);
  EXPECT_FALSE(scene.linkings[0].illumination->include);
  EXPECT_EQ(scene.linkings[0].illumination->lights, (std::vector<std::uint32_t>{1}));
  EXPECT_FALSE(scene.linkings[0].shadows);
  EXPECT_TRUE(scene.linkings[1].illumination->include);
  EXPECT_EQ(scene.linkings[1].illumination->lights, (std::vector<std::uint32_t>{0}));
  ASSERT_TRUE(scene.linkings[1].shadows);
  EXPECT_TRUE(scene.linkings[1].shadows->include);
  EXPECT_TRUE(scene.linkings[1].shadows->lights.empty());
}

TEST(YamlLightLinking, TheRenderSceneGroupsObjectsThatAgree) {
  const auto cube = test::write_file("link_cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const RenderScene scene =
      build_render_scene(parse("  - {type: sphere, light_linking: {not_illuminated_by: [rim]}}\n"
                               "  - {type: sphere}\n"
                               "  - {type: sphere, light_linking: {illuminated_by: [key]}}\n"
                               "  - {type: mesh, file: " +
                               cube.string() +
                               ", shadow_linking: {no_shadows_from: [key]}}\n"
                               "  - {type: instance, object: pair, light_linking: {illuminated_by: [key]}}\n"
                               "  - {type: instance, object: pair}\n"));
  const LightLinks& links = scene.links;
  ASSERT_TRUE(links.linked());
  // Group 0: every light; not_illuminated_by [rim] keeps the unnamed sun, illuminated_by [key] does not.
  ASSERT_EQ(links.groups.size(), 4u);
  EXPECT_EQ(links.groups[0].illuminated_by, (std::vector<std::uint8_t>{1, 1, 1}));
  EXPECT_EQ(links.groups[1].illuminated_by, (std::vector<std::uint8_t>{1, 0, 1}));
  EXPECT_EQ(links.groups[2].illuminated_by, (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_EQ(links.groups[3].casts_shadow_from, (std::vector<std::uint8_t>{0, 1, 1}));
  // Geometry 0: the spheres, one by one; 1: the mesh; 2 and 3: the instances.
  ASSERT_EQ(scene.top.geometries.size(), 4u);
  EXPECT_EQ(links.group_of(0, 0), 1u);
  EXPECT_EQ(links.group_of(0, 1), 0u);
  EXPECT_EQ(links.group_of(0, 2), 2u);
  EXPECT_EQ(links.group_of(1, 0), 3u);
  EXPECT_EQ(links.group_of(2, 0), 2u);
  EXPECT_EQ(links.group_of(3, 0), 0u);
  EXPECT_TRUE(links.illuminates(1, 2));
  EXPECT_FALSE(links.illuminates(1, 1));
  EXPECT_TRUE(links.shadow_linked(0));
  EXPECT_FALSE(links.shadow_linked(1));
}

TEST(YamlLightLinking, ASceneWithoutLinkingHasNoGroups) {
  const RenderScene scene = build_render_scene(parse("  - {type: sphere}\n"));
  EXPECT_FALSE(scene.links.linked());
  EXPECT_EQ(scene.links.group_of(0, 0), 0u);
  EXPECT_TRUE(scene.links.illuminates(0, 1));
  EXPECT_TRUE(scene.links.casts_shadow(0, 1));
}

TEST(YamlLightLinking, MistakesAreRefusedWhereTheyAreMade) {
  expect_error("  - {type: sphere, light_linking: {not_illuminated_by: [rym]}}\n", 10, "rym",
               {"unknown light 'rym'", "did you mean 'rim'"});
  expect_error("  - {type: sphere, shadow_linking: {shadows_from: [key, key]}}\n", 10, "key]", {"listed twice"});
  expect_error("  - {type: sphere, light_linking: {illuminated_by: [key], not_illuminated_by: [rim]}}\n", 10, "[rim]",
               {"not both"});
  expect_error("  - {type: sphere, light_linking: {}}\n", 10, "{}", {"illuminated_by", "not_illuminated_by"});
  expect_error("  - {type: sphere, shadow_linking: {}}\n", 10, "{}", {"shadows_from", "no_shadows_from"});
  expect_error("  - {type: sphere, light_linking: {illuminated_by: key}}\n", 10, "key}", {"list of light names"});
  expect_error("  - {type: sphere, light_linking: {iluminated_by: [key]}}\n", 10, "iluminated_by",
               {"did you mean 'illuminated_by'"});
  expect_error("  - {type: sphere, light_links: {shadows_from: [key]}}\n", 10, "light_links", {"light_linking"});
}

TEST(YamlLightLinking, OnlyTheWorldsEntriesAreLinked) {
  try {
    parse_scene_text(
        "rtpro: 1\ncamera: {position: [0, 1, -5], look_at: [0, 0, 0]}\nlights: [{type: point, name: key, position: [0, "
        "5, 0]}]\n"
        "objects:\n  one: [{type: sphere, light_linking: {not_illuminated_by: [key]}}]\n",
        "link.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 5);
    EXPECT_NE(error.message().find("link the instance"), std::string::npos) << error.what();
  }
}

TEST(YamlLightLinking, LightNamesAreUnique) {
  try {
    parse_scene_text(
        "rtpro: 1\ncamera: {position: [0, 1, -5], look_at: [0, 0, 0]}\nlights:\n"
        "  - {type: point, name: key, position: [0, 5, 0]}\n  - {type: point, name: key, position: [0, 6, 0]}\n",
        "link.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 5);
    EXPECT_EQ(error.where().column, 25);
    EXPECT_NE(error.message().find("already named 'key'"), std::string::npos) << error.what();
  }
}

}  // namespace yaml_light_linking_test
}  // namespace rtpro
