// Scene documents the parser refuses for their form: YAML syntax, keys, types, names, cycles and
// nesting.
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::test {
namespace scene_syntax_errors_test {

TEST(SceneParser, ReportsYamlSyntaxErrorsWithPosition) {
  const InputError error = parse_error(kHeader + "world: [1, 2\nrender: {}\n");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_GT(error.where().column, 0);
  EXPECT_NE(error.message().find("YAML syntax error"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find("test.yaml:4:"), std::string::npos) << error.what();
}

// libyaml calls a tab in the indentation "a character that cannot start any token": the message
// names the tab and points at it, also after spaces and in a block mapping's first key.
TEST(SceneParser, ATabInTheIndentationIsNamed) {
  const std::string listed = kHeader + "lights:\n\t- {type: point, position: [4, 6, 5]}\n";
  EXPECT_SCENE_ERROR(listed, at(listed, 4, "\t"), {"tab characters are not allowed in YAML indentation"});
  const std::string mapped = kHeader + "render:\n  spp: 4\n  \tseed: 1\n";
  EXPECT_SCENE_ERROR(mapped, at(mapped, 5, "\t"), {"tab characters are not allowed in YAML indentation"});
  const std::string first = kHeader + "render:\n\tspp: 4\n";
  EXPECT_SCENE_ERROR(first, at(first, 4, "\t"), {"tab characters are not allowed in YAML indentation"});
}

TEST(SceneParser, UnknownKeySuggestsTheClosestKey) {
  const std::string text = with_world("  - {type: sphere, radus: 1}\n");
  EXPECT_SCENE_ERROR(text, at(text, 4, "radus"), {"unknown key 'radus' in sphere; did you mean 'radius'?"});
  const std::string top = kHeader + "lihgts: []\n";
  EXPECT_SCENE_ERROR(top, at(top, 3, "lihgts"), {"unknown key 'lihgts'", "did you mean 'lights'?"});
}

TEST(SceneParser, UnknownKeyWithoutNearMatchListsTheValidKeys) {
  const std::string text = kHeader + "render: {quality: high}\n";
  EXPECT_SCENE_ERROR(text, at(text, 3, "quality"), {"unknown key 'quality' in render", "spp, max_depth, seed"});
}

TEST(SceneParser, DetectsDuplicateKeys) {
  const std::string block = kHeader + "render:\n  spp: 4\n  seed: 1\n  spp: 16\n";
  EXPECT_SCENE_ERROR(block, at(block, 6, "spp"), {"duplicate key 'spp'", "line 4"});
  const std::string flow = with_world("  - {type: sphere, radius: 1, radius: 2}\n");
  EXPECT_SCENE_ERROR(flow, at(flow, 4, "radius: 2"), {"duplicate key 'radius'"});
  const std::string top = kHeader + "camera: {position: [0, 0, 1], look_at: [0, 0, 0]}\n";
  EXPECT_SCENE_ERROR(top, at(top, 3, "camera"), {"duplicate key 'camera'", "line 2"});
}

TEST(SceneParser, RejectsWrongTypes) {
  const std::string text = with_world("  - {type: sphere, radius: big}\n");
  EXPECT_SCENE_ERROR(text, at(text, 4, "big"), {"sphere.radius", "expected a number", "'big'"});
  const std::string quoted = with_world("  - {type: sphere, radius: \"2\"}\n");
  EXPECT_SCENE_ERROR(quoted, at(quoted, 4, "\"2\""), {"sphere.radius", "expected a number"});
  const std::string listed = with_world("  - {type: sphere, radius: [1]}\n");
  EXPECT_SCENE_ERROR(listed, at(listed, 4, "[1]"), {"sphere.radius", "expected a number", "a list of 1 item"});
  const std::string integer = kHeader + "render: {spp: 4.0}\n";
  EXPECT_SCENE_ERROR(integer, at(integer, 3, "4.0"), {"render.spp", "expected an integer"});
  const std::string empty = kHeader + "render:\n  ambient:\n";
  EXPECT_SCENE_ERROR(empty, at(empty, 4, "ambient"), {"render.ambient", "an empty value"});
}

TEST(SceneParser, RejectsVectorsOfTheWrongLength) {
  const std::string text = with_world("  - {type: sphere, center: [1, 2]}\n");
  EXPECT_SCENE_ERROR(text, at(text, 4, "[1, 2]"), {"sphere.center", "3 numbers", "a list of 2 items"});
  const std::string resolution = kHeader + "render: {}\ncamera2: 1\n";
  EXPECT_SCENE_ERROR(resolution, at(resolution, 4, "camera2"), {"unknown key 'camera2'", "did you mean 'camera'?"});
}

TEST(SceneParser, RejectsNonFiniteNumbers) {
  for (const std::string number : {".nan", ".inf", "-.inf", "1e999", "-1e999"}) {
    const std::string text = with_world("  - {type: sphere, center: [0, " + number + ", 0]}\n");
    EXPECT_SCENE_ERROR(text, at(text, 4, number), {"sphere.center", number});
  }
  const std::string fov = kHeader + "render: {ambient: .NaN}\n";
  EXPECT_SCENE_ERROR(fov, at(fov, 3, ".NaN"), {"render.ambient", "finite"});
}

TEST(SceneParser, RejectsHugeNumbers) {
  const std::string text = with_world("  - {type: sphere, center: [1e20, 0, 0]}\n");
  EXPECT_SCENE_ERROR(text, at(text, 4, "1e20"), {"sphere.center", "out of range"});
}

// Positions and translations reach ±1e16, as far as mesh vertices; lengths and factors stay within
// ±1e9.
TEST(SceneParser, PositionsReachFartherThanOtherNumbers) {
  const std::string far = camera_scene("{position: [2e9, 0, 5], look_at: [2e9, 0, 0]}") + "world:\n" +
                          "  - {type: sphere, center: [2e9, 0, 0]}\n" +
                          "  - {type: instance, object: o, transform: {translate: [0, 2e15, 0]}}\n" +
                          "objects: {o: [{type: sphere}]}\n";
  const SceneDescription scene = parse_scene_text(far, "far.yaml");
  EXPECT_EQ(scene.camera.position.x, 2e9f);
  const std::string beyond = with_world("  - {type: sphere, center: [0, 2e16, 0]}\n");
  EXPECT_SCENE_ERROR(beyond, at(beyond, 4, "2e16"), {"sphere.center: 2e16 is out of range", "±1e16 for positions"});
  const std::string translated = with_world("  - {type: instance, object: o, transform: {translate: [2e16, 0, 0]}}\n") +
                                 "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(translated, at(translated, 4, "2e16"), {"instance.transform.translate", "±1e16 for positions"});
  const std::string radius = with_world("  - {type: sphere, radius: 2e9}\n");
  EXPECT_SCENE_ERROR(radius, at(radius, 4, "2e9"), {"sphere.radius: 2e9 is out of range", "within ±1e9)"});
  const std::string scaled =
      with_world(
          "  - {type: instance, object: o, transform: [{scale: 1e5}, {translate: [1e9, 0, 0]}, {scale: 1e5}]}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(scaled, at(scaled, 4, "[{scale"),
                     {"instance.transform", "beyond ±1e9 (±1e16 for its translation"});
}

TEST(SceneParser, UnknownMaterialSuggestsTheClosestName) {
  const std::string text = kHeader + "materials: {crimson: {}}\nworld:\n  - {type: sphere, material: crimsom}\n";
  EXPECT_SCENE_ERROR(text, at(text, 5, "crimsom"), {"unknown material 'crimsom'", "did you mean 'crimson'?"});
}

TEST(SceneParser, UnknownObjectInAnInstance) {
  const std::string text = kHeader + "objects: {tree: []}\nworld:\n  - {type: instance, object: tre}\n";
  EXPECT_SCENE_ERROR(text, at(text, 5, "tre}"), {"instance.object", "unknown object 'tre'", "did you mean 'tree'?"});
  const std::string none = with_world("  - {type: instance, object: tree}\n");
  EXPECT_SCENE_ERROR(none, at(none, 4, "tree"), {"unknown object 'tree'", "no objects are defined"});
}

TEST(SceneParser, UnknownEntryAndLightTypesSuggestTheClosest) {
  const std::string entry = with_world("  - {type: sphre}\n");
  EXPECT_SCENE_ERROR(entry, at(entry, 4, "sphre"), {"unknown entry type 'sphre'", "did you mean 'sphere'?"});
  const std::string light = kHeader + "lights:\n  - {type: lamp, position: [0, 1, 0]}\n";
  EXPECT_SCENE_ERROR(light, at(light, 4, "lamp"), {"unknown light type 'lamp'", "point, spot, directional"});
  const std::string untyped = with_world("  - {radius: 1}\n");
  EXPECT_SCENE_ERROR(untyped, at(untyped, 4, "{"),
                     {"missing the required key 'type'", "sphere, mesh, curves, instance"});
}

TEST(SceneParser, DetectsInstanceCyclesWithTheChain) {
  const std::string self = kHeader + "objects:\n  a:\n    - {type: instance, object: a}\n";
  EXPECT_SCENE_ERROR(self, at(self, 5, "a}"), {"instance cycle: a -> a"});
  const std::string indirect = kHeader +
                               "objects:\n"
                               "  a: [{type: instance, object: b}]\n"
                               "  b: [{type: sphere}, {type: instance, object: c}]\n"
                               "  c: [{type: instance, object: a}]\n"
                               "world: [{type: instance, object: a}]\n";
  EXPECT_SCENE_ERROR(indirect, at(indirect, 6, "a}"), {"instance cycle: a -> b -> c -> a"});
}

TEST(SceneParser, RejectsInstanceNestingDeeperThan16) {
  auto chain = [](int levels) {
    std::string text = kHeader + "objects:\n  o0: [{type: sphere}]\n";
    for (int i = 1; i < levels; ++i)
      text += "  o" + std::to_string(i) + ": [{type: instance, object: o" + std::to_string(i - 1) + "}]\n";
    return text + "world: [{type: instance, object: o" + std::to_string(levels - 1) + "}]\n";
  };
  EXPECT_NO_THROW(parse_scene_text(chain(16), "test.yaml"));  // world -> o15 -> ... -> o0: 16 levels
  const std::string deep = chain(17);
  const InputError error = parse_error(deep);
  EXPECT_EQ(error.where().line, 21);  // the world's instance: the 17th level starts there
  EXPECT_NE(error.message().find("deeper than 16 levels: world -> o16 -> o15"), std::string::npos) << error.what();
  EXPECT_NE(error.message().find("o1 -> o0"), std::string::npos) << error.what();
}

TEST(SceneParser, RequiresVersionAndCamera) {
  const std::string no_version = "camera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n";
  EXPECT_SCENE_ERROR(no_version, at(no_version, 1, "camera"), {"missing the required key 'rtpro'"});
  const std::string v2 = "rtpro: 2\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0]}\n";
  EXPECT_SCENE_ERROR(v2, at(v2, 1, "2"), {"unsupported scene format version 2", "version 1"});
  const std::string no_camera = "rtpro: 1\nworld: []\n";
  EXPECT_SCENE_ERROR(no_camera, at(no_camera, 1, "rtpro"), {"missing the required key 'camera'"});
  const std::string no_look_at = "rtpro: 1\ncamera: {position: [0, 0, -5]}\n";
  EXPECT_SCENE_ERROR(no_look_at, at(no_look_at, 2, "{"), {"camera is missing the required key 'look_at'"});
}

TEST(SceneParser, RejectsDocumentsThatAreNotOneMapping) {
  const std::string empty;
  const InputError error = parse_error(empty);
  EXPECT_NE(error.message().find("the scene is empty"), std::string::npos) << error.what();
  const std::string list = "- 1\n- 2\n";
  EXPECT_SCENE_ERROR(list, at(list, 1, "-"), {"expected the scene to be a mapping", "a list of 2 items"});
  const std::string two = kHeader + "---\n" + kHeader;
  EXPECT_SCENE_ERROR(two, at(two, 3, "---"), {"more than one YAML document"});
  const std::string tagged = kHeader + "render: {spp: !!int 4}\n";
  EXPECT_SCENE_ERROR(tagged, at(tagged, 3, "!!int"), {"YAML tags"});
  const std::string self_alias = kHeader + "world: &w [*w]\n";
  EXPECT_SCENE_ERROR(self_alias, at(self_alias, 3, "*w"), {"alias refers to a node that contains it"});
}

TEST(SceneParser, RejectsDeepNestingWithoutCrashing) {
  const std::string brackets = kHeader + "world: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  const InputError flow = parse_error(brackets);
  EXPECT_EQ(flow.where().line, 3);
  EXPECT_EQ(flow.where().column, 8 + 63);  // the 64th '[' is level 65, the top mapping being level 1
  EXPECT_NE(flow.message().find("nesting deeper than 64"), std::string::npos) << flow.what();

  std::string indented = "rtpro: 1\n";
  for (int depth = 0; depth < 5000; ++depth) indented += std::string(depth, ' ') + "k:\n";
  const InputError block = parse_error(indented);
  EXPECT_EQ(block.where().line, 66);  // level n (the top mapping is 1) starts on line n + 1
  EXPECT_NE(block.message().find("nesting deeper than 64"), std::string::npos) << block.what();
}

}  // namespace scene_syntax_errors_test
}  // namespace rtpro::test
