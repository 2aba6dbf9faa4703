// What a glTF file read as the whole scene is refused for after it loads (gltf_scene.h,
// geometry_origin.h): the scene rtpro writes for it is YAML text the user never sees, so every
// error names the glTF file and the JSON path of the element at fault, never a line of that text.
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "gltf_test_files.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace rtpro {
namespace gltf_scene_errors_test {

using test::GltfFile;

// One triangle drawn by nodes[0].
GltfFile triangle_model() {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.scene({gltf.node({{"mesh", mesh}})});
  return gltf;
}

// Adds cameras[0] with this vertical field of view (radians), on a new node with `node`'s
// properties that the scene lists as a root; returns the node's index.
int add_camera(GltfFile& gltf, double yfov, nlohmann::json node) {
  gltf.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", yfov}, {"znear", 0.1}}}}};
  node["camera"] = 0;
  const int index = gltf.node(std::move(node));
  gltf.json["scenes"][0]["nodes"].push_back(index);
  return index;
}

// Adds extensions.KHR_lights_punctual.lights[0] on nodes[N], the child of a root scaled by 2, so a
// translation of 1e16 places it at 2e16; returns N.
int add_doubled_light(GltfFile& gltf, nlohmann::json light, nlohmann::json node) {
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::array({std::move(light)});
  node["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  const int lamp = gltf.node(std::move(node));
  gltf.json["scenes"][0]["nodes"].push_back(gltf.node({{"children", {lamp}}, {"scale", {2, 2, 2}}}));
  return lamp;
}

// Whether `text` names a line of a glTF file ("cam.gltf:3:27").
bool names_a_line(const std::string& text) { return std::regex_search(text, std::regex(R"(\.gltf:[0-9])")); }

// The message of the InputError reading `file` as a scene throws, which must be located at the
// file itself (no line); a test failure when it is read.
std::string scene_error(const std::filesystem::path& file, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene_file(file, overrides);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string()) << e.what();
    EXPECT_EQ(e.where().line, 0) << e.what();
    EXPECT_FALSE(names_a_line(e.what())) << e.what();
    return e.message();
  }
  ADD_FAILURE() << file << " was read";
  return {};
}

// The same for building the render scene of `file` once read.
std::string build_error(const std::filesystem::path& file) {
  const SceneDescription description = parse_scene_file(file);
  try {
    build_render_scene(description);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string()) << e.what();
    EXPECT_EQ(e.where().line, 0) << e.what();
    EXPECT_FALSE(names_a_line(e.what())) << e.what();
    return e.message();
  }
  ADD_FAILURE() << file << " was built";
  return {};
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// The scene format's positions stay within ±1e16: a camera node at 1e16 under a parent scaled by
// 2 is at 2e16.
TEST(GltfSceneErrors, ACameraBeyondTheSceneFormatsRangeNamesItsNode) {
  GltfFile gltf = triangle_model();
  gltf.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  const int camera = gltf.node({{"camera", 0}, {"translation", {0, 0, 1e16}}});
  gltf.json["scenes"][0]["nodes"].push_back(gltf.node({{"children", {camera}}, {"scale", {2, 2, 2}}}));
  const std::string message = scene_error(gltf.write("far_camera"));
  EXPECT_TRUE(starts_with(message, "nodes[1] (cameras[0]): camera.position: 2")) << message;
  EXPECT_NE(message.find("is out of range (numbers must be finite and within ±1e16 for positions)"), std::string::npos)
      << message;
}

// At 2e9 a float cannot hold a step of 1 along the view direction: the point looked at is placed
// farther along it, and the camera keeps its direction.
TEST(GltfSceneErrors, ACameraFarFromTheOriginKeepsItsViewDirection) {
  GltfFile gltf = triangle_model();
  add_camera(gltf, 0.7, {{"translation", {0, 3, 2e9}}});
  const SceneDescription scene = parse_scene_file(gltf.write("far_view"));
  EXPECT_EQ(scene.camera.position.z, 2e9f);
  const Vec3 view = normalize(scene.camera.look_at - scene.camera.position);
  EXPECT_NEAR(view.x, 0.0f, 1e-6f);
  EXPECT_NEAR(view.y, 0.0f, 1e-6f);
  EXPECT_NEAR(view.z, -1.0f, 1e-6f);
}

// A glTF node translated within ±1e16 is kept as the backends trace it (±1e16).
TEST(GltfSceneErrors, ANodeTranslatedBeyondABillionLoads) {
  GltfFile gltf = triangle_model();
  gltf.json["nodes"][0]["translation"] = {5e9, 0, 0};
  const std::filesystem::path file = gltf.write("far_node");
  const SceneDescription scene = parse_scene_file(file);
  EXPECT_NO_THROW(build_render_scene(scene));
  GltfFile refused = triangle_model();
  refused.json["nodes"][0]["translation"] = {2e16, 0, 0};
  try {
    parse_scene_file(refused.write("too_far_node"));
    ADD_FAILURE() << "a translation of 2e16 was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nodes[0].translation: needs 3 finite numbers (magnitude <= 1e16)"),
              std::string::npos)
        << e.what();
  }
}

// A sheared node matrix turns the camera's -z nearly onto its +y (sine 1e-4): the loader keeps
// it (not parallel), the scene format refuses an up that close to the view direction.
TEST(GltfSceneErrors, ACameraWhoseUpNearlyMeetsItsViewNamesItsNode) {
  GltfFile gltf = triangle_model();
  add_camera(gltf, 0.7, {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, -1, -1e-4, 0, 0, 0, 3, 1}}});
  const std::string message = scene_error(gltf.write("sheared_camera"));
  EXPECT_TRUE(starts_with(message, "nodes[1] (cameras[0]): camera.up is parallel to the view direction")) << message;
}

// yfov 3.1415925 is 179.999996 degrees, below 180 as the loader checks it, and 180 as a float.
TEST(GltfSceneErrors, AFieldOfViewThatRoundsTo180DegreesNamesTheCamerasNode) {
  GltfFile gltf = triangle_model();
  add_camera(gltf, 3.1415925, {{"translation", {0, 0, 3}}});
  const std::string message = scene_error(gltf.write("wide_camera"));
  EXPECT_TRUE(starts_with(message, "nodes[1] (cameras[0]): camera.fov must be between 0 and 180 degrees")) << message;
}

// yfov 1e-47 is above 0 as the loader checks it, and 0 degrees as a float.
TEST(GltfSceneErrors, AFieldOfViewThatRoundsToZeroNamesTheCamerasNode) {
  GltfFile gltf = triangle_model();
  add_camera(gltf, 1e-47, {{"translation", {0, 0, 3}}});
  const std::string message = scene_error(gltf.write("narrow_camera"));
  EXPECT_TRUE(starts_with(message, "nodes[1] (cameras[0]): camera.fov must be between 0 and 180 degrees")) << message;
}

// A mesh 1e9 wide at z = 1e16 is within what the backends trace, but the camera framing it from
// +z is beyond the scene format's ±1e16: there is no glTF camera to name, so the error says which camera it is.
TEST(GltfSceneErrors, TheCameraFramingFarMeshesSaysItIsRtprosOwn) {
  GltfFile gltf = triangle_model();
  gltf.json["nodes"][0]["translation"] = {0, 0, 1e7};
  gltf.json["scenes"][0]["nodes"] = {gltf.node({{"children", {0}}, {"scale", {1e9, 1e9, 1e9}}})};
  const std::string message = scene_error(gltf.write("far_meshes"));
  EXPECT_TRUE(starts_with(message,
                          "the camera rtpro places to frame the meshes (the file has no usable camera): "
                          "camera.position: "))
      << message;
}

TEST(GltfSceneErrors, APointLightBeyondTheSceneFormatsRangeNamesItsNodeAndLight) {
  GltfFile gltf = triangle_model();
  const int lamp = add_doubled_light(gltf, {{"type", "point"}, {"intensity", 10}}, {{"translation", {0, 0, 1e16}}});
  const std::string message = scene_error(gltf.write("far_point"));
  EXPECT_TRUE(starts_with(message, "nodes[" + std::to_string(lamp) +
                                       "] (extensions.KHR_lights_punctual.lights[0]): "
                                       "point light.position: 2"))
      << message;
  EXPECT_NE(message.find("is out of range (numbers must be finite and within ±1e16 for positions)"), std::string::npos)
      << message;
  GltfFile near = triangle_model();
  add_doubled_light(near, {{"type", "point"}, {"intensity", 10}}, {{"translation", {0, 0, 1e9}}});
  const SceneDescription lit = parse_scene_file(near.write("point_at_2e9"));
  ASSERT_EQ(lit.lights.size(), 1u);
  EXPECT_EQ(std::get<PointLightDesc>(lit.lights[0]).position.z, 2e9f);
}

TEST(GltfSceneErrors, ASpotLightBeyondTheSceneFormatsRangeNamesItsNodeAndLight) {
  GltfFile gltf = triangle_model();
  const int lamp =
      add_doubled_light(gltf, {{"type", "spot"}, {"spot", nlohmann::json::object()}}, {{"translation", {1e16, 0, 0}}});
  const std::string message = scene_error(gltf.write("far_spot"));
  EXPECT_TRUE(starts_with(message, "nodes[" + std::to_string(lamp) +
                                       "] (extensions.KHR_lights_punctual.lights[0]): "
                                       "spot light.position: 2"))
      << message;
  EXPECT_NE(message.find("±1e16 for positions"), std::string::npos) << message;
}

// A light intensity below 0 or above 1e9 was read as 0: a black image with exit 0. It is refused
// at its JSON path, in the light's unit.
TEST(GltfSceneErrors, ALightIntensityOutOfRangeIsRefusedAtItsPath) {
  for (const auto& [name, light, said] :
       {std::tuple{"negative", nlohmann::json{{"type", "point"}, {"intensity", -5}}, "is -5; it"},
        std::tuple{"huge", nlohmann::json{{"type", "directional"}, {"intensity", 2e9}}, "is 2e+09; it"}}) {
    GltfFile gltf = triangle_model();
    add_doubled_light(gltf, light, {{"translation", {0, 0, 1}}});
    const std::string message = scene_error(gltf.write(name));
    EXPECT_NE(message.find("extensions.KHR_lights_punctual.lights[0].intensity: " + std::string(said) +
                           " must be a finite number from 0 to 1e9"),
              std::string::npos)
        << message;
  }
  GltfFile gltf = triangle_model();
  add_doubled_light(gltf, {{"type", "spot"}, {"intensity", 1e9}, {"spot", nlohmann::json::object()}},
                    {{"translation", {0, 0, 1}}});
  EXPECT_NO_THROW(parse_scene_file(gltf.write("brightest")));
}

// A colour channel below 0 was clamped to 0 without a word, changing the light's hue; a colour
// that is not three finite numbers became white. Both are refused at the colour's path.
TEST(GltfSceneErrors, ALightColourOutOfRangeIsRefusedAtItsPath) {
  for (const auto& [name, color] :
       {std::pair{"negative", nlohmann::json{1.0, -0.5, 1.0}}, std::pair{"two_channels", nlohmann::json{1.0, 0.5}}}) {
    GltfFile gltf = triangle_model();
    add_doubled_light(gltf, {{"type", "point"}, {"intensity", 5}, {"color", color}}, {{"translation", {0, 0, 1}}});
    const std::string message = scene_error(gltf.write(name));
    EXPECT_NE(
        message.find("extensions.KHR_lights_punctual.lights[0].color: must be three finite numbers from 0 to 1e9"),
        std::string::npos)
        << message;
  }
  GltfFile gltf = triangle_model();
  add_doubled_light(gltf, {{"type", "point"}, {"intensity", 5}, {"color", {0.0, 0.25, 1.0}}},
                    {{"translation", {0, 0, 1}}});
  const SceneDescription lit = parse_scene_file(gltf.write("blue"));
  ASSERT_EQ(lit.lights.size(), 1u);
  EXPECT_EQ(std::get<PointLightDesc>(lit.lights[0]).color.y, 0.25f);
}

// An override's errors stay at the override, as in a scene file.
TEST(GltfSceneErrors, AnOverridesErrorNamesTheOverride) {
  GltfFile gltf = triangle_model();
  add_camera(gltf, 0.7, {{"translation", {0, 0, 3}}});
  try {
    parse_scene_file(gltf.write("overridden"), {"camera.fov=200"});
    FAIL() << "camera.fov=200 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, override_source("camera.fov=200")) << e.what();
  }
}

// A mesh node at 1e9 under a parent scaled by 1e8 places its triangle at 1e17, beyond what the
// backends trace (±1e16); the camera is the file's, within range.
GltfFile far_instance_model() {
  GltfFile gltf = triangle_model();
  gltf.json["nodes"][0]["translation"] = {1e9, 0, 0};
  gltf.json["scenes"][0]["nodes"] = {gltf.node({{"children", {0}}, {"scale", {1e8, 1e8, 1e8}}})};
  add_camera(gltf, 0.7, {{"translation", {0, 0, 3}}});
  return gltf;
}

TEST(GltfSceneErrors, AnInstanceBeyondTheTraceableRangeNamesItsNode) {
  const std::string message = build_error(far_instance_model().write("far_instance"));
  EXPECT_TRUE(starts_with(message, "nodes[0]: this instance places geometry as far as 1e+17 from the origin"))
      << message;
}

// Scaled by 1e-9 twice: rays entering the object would reach 1e18 in its space.
TEST(GltfSceneErrors, AnInstanceShrunkBeyondTheTraceableRangeNamesItsNode) {
  GltfFile gltf = triangle_model();
  gltf.json["nodes"][0]["scale"] = {1e-9, 1e-9, 1e-9};
  gltf.json["scenes"][0]["nodes"] = {gltf.node({{"children", {0}}, {"scale", {1e-9, 1e-9, 1e-9}}})};
  const std::string message = build_error(gltf.write("shrunk_instance"));
  EXPECT_TRUE(
      starts_with(message, "nodes[0]: this instance's transform (combined with its parents) shrinks its object"))
      << message;
}

// Placed by a YAML scene, the error is at the scene's entry and names the glTF file and node.
TEST(GltfSceneErrors, AnInstancePlacedByAYamlSceneNamesTheEntryTheFileAndTheNode) {
  const auto gltf = far_instance_model().write("far_piece");
  const auto scene = test::write_file("far_piece.yaml",
                                      "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\n"
                                      "world:\n  - {type: mesh, file: far_piece.gltf}\n");
  try {
    build_render_scene(parse_scene_file(scene));
    FAIL() << "built";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, scene.string());
    EXPECT_EQ(e.where().line, 4);
    EXPECT_TRUE(starts_with(e.message(), gltf.string() + ": nodes[0]: this instance places geometry")) << e.message();
  }
}

// YAML holds UTF-8 only: a Latin-1 file name made the scene's text a syntax error
// ("invalid trailing UTF-8 octet"). The file is placed all the same.
TEST(GltfSceneErrors, AFileNameThatIsNotUtf8IsReadAsTheScene) {
  const auto file = triangle_model().write("caf\xe9", /*embed=*/true);
  const SceneDescription description = parse_scene_file(file);
  ASSERT_EQ(description.world.gltfs.size(), 1u);
  EXPECT_EQ(description.world.gltfs[0].file.filename(), file.filename());
  EXPECT_TRUE(description.world.gltfs[0].loaded);
  EXPECT_EQ(build_render_scene(description).top.geometries.size(), 1u);
}

}  // namespace gltf_scene_errors_test
}  // namespace rtpro
