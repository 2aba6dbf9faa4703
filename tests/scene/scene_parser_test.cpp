#include "rtpro/scene/scene_parser.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro {
namespace scene_parser_test {

// Two lines; test documents add their own lines from line 3.
const std::string kHeader =
    "rtpro: 1\n"
    "camera: {position: [0, 1, -5], look_at: [0, 0, 0]}\n";

struct Position {
  int line;
  int column;
};

// The 1-based position of `token` on `line` of `text`, so tests say what an error points at
// rather than counting columns.
Position at(const std::string& text, int line, const std::string& token) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::string line_text = text.substr(start, text.find('\n', start) - start);
  const std::size_t column = line_text.find(token);
  EXPECT_NE(column, std::string::npos) << "'" << token << "' is not on line " << line;
  return {line, static_cast<int>(column) + 1};
}

InputError parse_error(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene_text(text, "test.yaml", overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("(none)");
}

void check_error(const std::string& text, Position expected, const std::vector<std::string>& fragments) {
  const InputError error = parse_error(text);
  EXPECT_EQ(error.where().file, "test.yaml");
  EXPECT_EQ(error.where().line, expected.line) << error.what();
  EXPECT_EQ(error.where().column, expected.column) << error.what();
  for (const std::string& fragment : fragments)
    EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
}

#define EXPECT_SCENE_ERROR(text, position, ...) \
  do {                                          \
    SCOPED_TRACE("expected error");             \
    check_error(text, position, __VA_ARGS__);   \
  } while (false)

std::string with_world(const std::string& world_lines) { return kHeader + "world:\n" + world_lines; }

TEST(SceneParser, FullSceneRoundTrips) {
  test::write_file("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string text = kHeader.substr(0, kHeader.find('\n') + 1) +
                           "camera:\n"
                           "  position: [1, 2, 3]\n"
                           "  look_at: [0, 0.5, 0]\n"
                           "  up: [0, 0, 1]\n"
                           "  fov: 30\n"
                           "  resolution: [320, 240]\n"
                           "render: {spp: 4, max_depth: 3, seed: 42, ambient: 0.1, background: [0.1, 0.2, 0.3]}\n"
                           "materials:\n"
                           "  red: {color: [0.9, 0.1, 0.1], specular: 0.25, shininess: 20, reflectivity: 0.3}\n"
                           "  mirror: {reflectivity: 1}\n"
                           "lights:\n"
                           "  - {type: point, position: [0, 10, 0], color: [1, 0.5, 0.25], intensity: 2}\n"
                           "  - {type: directional, direction: [0, -2, 0]}\n"
                           "objects:\n"
                           "  ball:\n"
                           "    - {type: sphere, center: [1, 0, 0], radius: 0.5, material: mirror}\n"
                           "    - {type: mesh, file: meshes/tri.obj}\n"
                           "  pair:\n"
                           "    - {type: instance, object: ball, transform: {translate: [0, 2, 0]}}\n"
                           "world:\n"
                           "  - {type: sphere, center: [0, -100, 0], radius: 100, material: red}\n"
                           "  - {type: mesh, file: meshes/tri.obj, material: red}\n"
                           "  - {type: instance, object: pair}\n";
  const auto file = test::write_file("scene.yaml", text);
  const SceneDescription scene = parse_scene_file(file);

  EXPECT_EQ(scene.file, file);
  EXPECT_EQ(scene.camera.position, Vec3(1, 2, 3));
  EXPECT_EQ(scene.camera.look_at, Vec3(0, 0.5f, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 0, 1));
  EXPECT_EQ(scene.camera.fov_degrees, 30.0f);
  EXPECT_EQ(scene.camera.width, 320);
  EXPECT_EQ(scene.camera.height, 240);

  EXPECT_EQ(scene.render.spp, 4);
  EXPECT_EQ(scene.render.max_depth, 3);
  EXPECT_EQ(scene.render.seed, 42u);
  EXPECT_EQ(scene.render.ambient, 0.1f);
  EXPECT_EQ(scene.render.background, Color(0.1f, 0.2f, 0.3f));

  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_EQ(scene.materials[0].color, Color(0.8f));
  EXPECT_EQ(scene.materials[1].name, "red");
  EXPECT_EQ(scene.materials[1].color, Color(0.9f, 0.1f, 0.1f));
  const PhongParams& red = std::get<PhongParams>(scene.materials[1].params);
  EXPECT_EQ(red.specular, 0.25f);
  EXPECT_EQ(red.shininess, 20.0f);
  EXPECT_EQ(red.reflectivity, 0.3f);
  EXPECT_EQ(scene.materials[2].name, "mirror");
  EXPECT_EQ(std::get<PhongParams>(scene.materials[2].params).reflectivity, 1.0f);
  EXPECT_EQ(std::get<PhongParams>(scene.materials[2].params).specular, 0.5f);

  ASSERT_EQ(scene.lights.size(), 2u);
  const auto& point = std::get<PointLightDesc>(scene.lights[0]);
  EXPECT_EQ(point.position, Vec3(0, 10, 0));
  EXPECT_EQ(point.color, Color(1, 0.5f, 0.25f));
  EXPECT_EQ(point.intensity, 2.0f);
  const auto& sun = std::get<DirectionalLightDesc>(scene.lights[1]);
  EXPECT_EQ(sun.direction, Vec3(0, -1, 0));
  EXPECT_EQ(sun.intensity, 1.0f);

  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].name, "ball");
  ASSERT_EQ(scene.objects[0].spheres.size(), 1u);
  EXPECT_EQ(scene.objects[0].spheres[0].center, Vec3(1, 0, 0));
  EXPECT_EQ(scene.objects[0].spheres[0].radius, 0.5f);
  EXPECT_EQ(scene.objects[0].spheres[0].material, 2u);
  ASSERT_EQ(scene.objects[0].meshes.size(), 1u);
  EXPECT_EQ(scene.objects[0].meshes[0].material, kNoMaterial);
  EXPECT_EQ(scene.objects[0].meshes[0].file, file.parent_path() / "meshes/tri.obj");
  EXPECT_EQ(scene.objects[0].meshes[0].where.line, 18);
  EXPECT_EQ(scene.objects[1].name, "pair");
  ASSERT_EQ(scene.objects[1].instances.size(), 1u);
  EXPECT_EQ(scene.objects[1].instances[0].object, 0u);
  EXPECT_EQ(scene.objects[1].instances[0].transform, Affine::translate({0, 2, 0}));

  EXPECT_EQ(scene.world.name, "world");
  ASSERT_EQ(scene.world.spheres.size(), 1u);
  EXPECT_EQ(scene.world.spheres[0].radius, 100.0f);
  EXPECT_EQ(scene.world.spheres[0].material, 1u);
  ASSERT_EQ(scene.world.meshes.size(), 1u);
  EXPECT_EQ(scene.world.meshes[0].material, 1u);
  ASSERT_EQ(scene.world.instances.size(), 1u);
  EXPECT_EQ(scene.world.instances[0].object, 1u);
  EXPECT_EQ(scene.world.instances[0].transform, Affine::identity());
  EXPECT_EQ(scene.world.instances[0].where.file, file.string());
  EXPECT_EQ(scene.world.instances[0].where.line, 24);
  EXPECT_EQ(scene.world.instances[0].where.column, 5);
}

TEST(SceneParser, OmittedSectionsTakeTheirDefaults) {
  const SceneDescription scene = parse_scene_text(kHeader, "test.yaml");
  const CameraDesc camera_defaults;
  const RenderSettings render_defaults;
  EXPECT_EQ(scene.camera.up, camera_defaults.up);
  EXPECT_EQ(scene.camera.fov_degrees, camera_defaults.fov_degrees);
  EXPECT_EQ(scene.camera.width, camera_defaults.width);
  EXPECT_EQ(scene.render.spp, render_defaults.spp);
  EXPECT_EQ(scene.render.max_depth, render_defaults.max_depth);
  EXPECT_EQ(scene.render.ambient, render_defaults.ambient);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.objects.empty());
  EXPECT_TRUE(scene.world.spheres.empty());
}

TEST(SceneParser, EmptySectionsAndAnEmptyWorldAreAllowed) {
  const SceneDescription scene = parse_scene_text(kHeader + "materials:\nlights: []\nworld: []\n", "test.yaml");
  EXPECT_TRUE(scene.world.spheres.empty());
  EXPECT_TRUE(scene.world.instances.empty());
}

TEST(SceneParser, DefaultMaterialCanBeRedefinedAndStaysAtIndexZero) {
  const SceneDescription scene =
      parse_scene_text(kHeader +
                           "materials:\n  blue: {color: [0, 0, 1]}\n  default: {color: [0.5, 0.5, 0.5]}\n"
                           "world:\n  - {type: sphere}\n",
                       "test.yaml");
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_EQ(scene.materials[0].color, Color(0.5f));
  EXPECT_EQ(scene.materials[1].name, "blue");
  ASSERT_EQ(scene.world.spheres.size(), 1u);
  EXPECT_EQ(scene.world.spheres[0].material, 0u);
  EXPECT_EQ(scene.world.spheres[0].radius, 1.0f);
}

Affine instance_transform(const std::string& transform) {
  const SceneDescription scene = parse_scene_text(
      kHeader + "objects: {o: [{type: sphere}]}\nworld:\n  - {type: instance, object: o, transform: " + transform +
          "}\n",
      "test.yaml");
  return scene.world.instances.at(0).transform;
}

TEST(SceneParser, TransformMappingAppliesScaleThenRotateThenTranslate) {
  const Affine expected =
      compose(Affine::translate({1, 2, 3}), compose(Affine::rotate({0, 1, 0}, 90), Affine::scale({2, 2, 2})));
  EXPECT_EQ(instance_transform("{translate: [1, 2, 3], rotate: {axis: [0, 1, 0], angle: 90}, scale: 2}"), expected);
  EXPECT_EQ(instance_transform("{scale: 2, translate: [1, 2, 3], rotate: {axis: [0, 1, 0], angle: 90}}"), expected);
}

TEST(SceneParser, TransformListAppliesStepsInOrder) {
  const Affine expected = compose(Affine::scale({1, 2, 3}), Affine::translate({1, 0, 0}));
  EXPECT_EQ(instance_transform("[{translate: [1, 0, 0]}, {scale: [1, 2, 3]}]"), expected);
}

TEST(SceneParser, TransformEulerRotatesAboutXThenYThenZ) {
  const Affine expected =
      compose(Affine::rotate({0, 0, 1}, 30), compose(Affine::rotate({0, 1, 0}, 20), Affine::rotate({1, 0, 0}, 10)));
  EXPECT_EQ(instance_transform("{rotate: [10, 20, 30]}"), expected);
}

TEST(SceneParser, TransformMatrixIsRowMajor) {
  Affine expected = Affine::translate({5, 6, 7});
  expected.m[0][1] = 0.5f;
  EXPECT_EQ(instance_transform("{matrix: [1, 0.5, 0, 5,  0, 1, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1]}"), expected);
}

TEST(SceneParser, AliasesReuseAnchoredValues) {
  const SceneDescription scene =
      parse_scene_text(kHeader + "world:\n  - &ball {type: sphere, radius: 2}\n  - *ball\n", "test.yaml");
  ASSERT_EQ(scene.world.spheres.size(), 2u);
  EXPECT_EQ(scene.world.spheres[1].radius, 2.0f);
}

TEST(SceneParser, ReportsYamlSyntaxErrorsWithPosition) {
  const InputError error = parse_error(kHeader + "world: [1, 2\nrender: {}\n");
  EXPECT_EQ(error.where().line, 4);
  EXPECT_GT(error.where().column, 0);
  EXPECT_NE(error.message().find("YAML syntax error"), std::string::npos) << error.what();
  EXPECT_NE(std::string(error.what()).find("test.yaml:4:"), std::string::npos) << error.what();
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

TEST(SceneParser, RejectsNonPositiveRadius) {
  for (const std::string radius : {"0", "-1"}) {
    const std::string text = with_world("  - {type: sphere, radius: " + radius + "}\n");
    EXPECT_SCENE_ERROR(text, at(text, 4, radius + "}"), {"sphere.radius must be > 0"});
  }
}

std::string camera_scene(const std::string& camera) { return "rtpro: 1\ncamera: " + camera + "\n"; }

TEST(SceneParser, RejectsFovOutsideZeroTo180) {
  for (const std::string fov : {"0", "180", "200", "-5"}) {
    const std::string text = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], fov: " + fov + "}");
    EXPECT_SCENE_ERROR(text, at(text, 2, fov + "}"), {"camera.fov", "between 0 and 180"});
  }
}

TEST(SceneParser, ReadsAThinLensAndRejectsBadOnes) {
  const SceneDescription lens = parse_scene_text(
      camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], aperture: 0.25, focus_distance: 3}"), "l.yaml");
  EXPECT_EQ(lens.camera.aperture, 0.25f);
  EXPECT_EQ(lens.camera.focus_distance, 3.0f);
  EXPECT_EQ(parse_scene_text(camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0]}"), "p.yaml").camera.aperture,
            0.0f);
  for (const std::string aperture : {"-0.1", ".NaN", ".inf"}) {
    const std::string text = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], aperture: " + aperture + "}");
    EXPECT_SCENE_ERROR(text, at(text, 2, aperture + "}"), {"camera.aperture"});
  }
  for (const std::string focus : {"0", "-2", ".NaN", "1e39"}) {
    const std::string text = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], focus_distance: " + focus + "}");
    EXPECT_SCENE_ERROR(text, at(text, 2, focus + "}"), {"camera.focus_distance"});
  }
}

TEST(SceneParser, ReadsACheckerColourAndRejectsBadOnes) {
  const SceneDescription scene = parse_scene_text(
      kHeader + "materials:\n  floor: {color: {checker: {size: 0.5, colors: [[1, 1, 1], [0, 0, 0.5]], axes: xyz}}}\n",
      "c.yaml");
  ASSERT_TRUE(scene.materials[1].checker.has_value());
  EXPECT_EQ(scene.materials[1].checker->size, 0.5f);
  EXPECT_EQ(scene.materials[1].checker->odd, (Color{0, 0, 0.5f}));
  EXPECT_EQ(scene.materials[1].checker->axes, CheckerAxes::kXYZ);
  const SceneDescription defaults =
      parse_scene_text(kHeader + "materials:\n  floor: {color: {checker: {}}}\n", "d.yaml");
  EXPECT_EQ(defaults.materials[1].checker->axes, CheckerAxes::kXZ);
  const std::string size = kHeader + "materials:\n  floor: {color: {checker: {size: 0}}}\n";
  EXPECT_SCENE_ERROR(size, at(size, 4, "0}"), {"checker.size", "positive"});
  const std::string axes = kHeader + "materials:\n  floor: {color: {checker: {axes: xw}}}\n";
  EXPECT_SCENE_ERROR(axes, at(axes, 4, "xw"), {"checker.axes", "xz, xy, yz or xyz"});
  const std::string colors = kHeader + "materials:\n  floor: {color: {checker: {colors: [[1, 1, 1]]}}}\n";
  EXPECT_SCENE_ERROR(colors, at(colors, 4, "[[1"), {"checker.colors"});
  const std::string unknown = kHeader + "materials:\n  floor: {color: {stripes: {}}}\n";
  EXPECT_SCENE_ERROR(unknown, at(unknown, 4, "stripes"), {"stripes"});
}

TEST(SceneParser, RejectsBadResolutions) {
  const std::string zero = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], resolution: [0, 480]}");
  EXPECT_SCENE_ERROR(zero, at(zero, 2, "0, 480"), {"camera.resolution", "from 1 to 65536"});
  const std::string wide = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], resolution: [640, 70000]}");
  EXPECT_SCENE_ERROR(wide, at(wide, 2, "70000"), {"camera.resolution", "from 1 to 65536", "70000"});
  const std::string huge = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], resolution: [20000, 20000]}");
  EXPECT_SCENE_ERROR(huge, at(huge, 2, "[20000"), {"camera.resolution", "400000000 pixels", "2^28"});
  const std::string shape = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], resolution: 640}");
  EXPECT_SCENE_ERROR(shape, at(shape, 2, "640"), {"camera.resolution", "[width, height]"});
}

TEST(SceneParser, AcceptsAnySppFromOneTo65536) {
  EXPECT_EQ(parse_scene_text(kHeader + "render: {spp: 10}\n", "s.yaml").render.spp, 10);
  const std::string zero = kHeader + "render: {spp: 0}\n";
  EXPECT_SCENE_ERROR(zero, at(zero, 3, "0}"), {"render.spp", "from 1 to 65536"});
  const std::string many = kHeader + "render: {spp: 262144}\n";
  EXPECT_SCENE_ERROR(many, at(many, 3, "262144"), {"render.spp", "from 1 to 65536"});
  for (int spp : {1, 4, 64, 65536})
    EXPECT_EQ(parse_scene_text(kHeader + "render: {spp: " + std::to_string(spp) + "}\n", "t.yaml").render.spp, spp);
}

TEST(SceneParser, RejectsMaxDepthOutsideZeroTo64) {
  for (const std::string depth : {"-1", "65"}) {
    const std::string text = kHeader + "render: {max_depth: " + depth + "}\n";
    EXPECT_SCENE_ERROR(text, at(text, 3, depth), {"render.max_depth", "from 0 to 64"});
  }
  EXPECT_EQ(parse_scene_text(kHeader + "render: {max_depth: 0}\n", "t.yaml").render.max_depth, 0);
}

TEST(SceneParser, RejectsNegativeAmbientColourAndIntensity) {
  const std::string ambient = kHeader + "render: {ambient: -0.1}\n";
  EXPECT_SCENE_ERROR(ambient, at(ambient, 3, "-0.1"), {"render.ambient must be >= 0"});
  const std::string colour = kHeader + "materials: {red: {color: [1, -0.5, 0]}}\n";
  EXPECT_SCENE_ERROR(colour, at(colour, 3, "-0.5"), {"material 'red'.color", ">= 0"});
  const std::string intensity = kHeader + "lights: [{type: point, position: [0, 1, 0], intensity: -2}]\n";
  EXPECT_SCENE_ERROR(intensity, at(intensity, 3, "-2"), {"point light.intensity must be >= 0"});
  const std::string background = kHeader + "render: {background: [0, 0, -1]}\n";
  EXPECT_SCENE_ERROR(background, at(background, 3, "-1"), {"render.background"});
}

TEST(SceneParser, RejectsReflectivityAboveOne) {
  const std::string text = kHeader + "materials: {glass: {reflectivity: 1.5}}\n";
  EXPECT_SCENE_ERROR(text, at(text, 3, "1.5"), {"reflectivity must be from 0 to 1"});
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
  EXPECT_SCENE_ERROR(untyped, at(untyped, 4, "{"), {"missing the required key 'type'", "sphere, mesh, instance"});
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

TEST(SceneParser, RejectsBadTransforms) {
  const std::string singular =
      with_world(
          "  - {type: instance, object: o, transform: {matrix: [1, 0, 0, 0, 0, 1, 0, 0, 2, 2, 0, 0, 0, 0, 0, 1]}}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(singular, at(singular, 4, "{matrix"), {"instance.transform", "singular"});
  const std::string row =
      with_world(
          "  - {type: instance, object: o, transform: {matrix: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 2, 1]}}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(row, at(row, 4, "2, 1]"), {"instance.transform.matrix", "last row must be 0 0 0 1"});
  const std::string short_matrix = with_world("  - {type: instance, object: o, transform: {matrix: [1, 0, 0]}}\n") +
                                   "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(short_matrix, at(short_matrix, 4, "[1, 0, 0]"), {"instance.transform.matrix", "16 numbers"});
  const std::string mixed =
      with_world("  - {type: instance, object: o, transform: {translate: [1, 0, 0], matrix: []}}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(mixed, at(mixed, 4, "[]"), {"'matrix' cannot be combined"});
  const std::string zero_scale = with_world("  - {type: instance, object: o, transform: {scale: [1, 0, 1]}}\n") +
                                 "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(zero_scale, at(zero_scale, 4, "[1, 0, 1]"), {"instance.transform.scale", "non-zero"});
  const std::string zero_axis =
      with_world("  - {type: instance, object: o, transform: {rotate: {axis: [0, 0, 0], angle: 5}}}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(zero_axis, at(zero_axis, 4, "[0, 0, 0]"), {"instance.transform.rotate.axis", "must not be zero"});
  const std::string bad_step =
      with_world("  - {type: instance, object: o, transform: [{translate: [1, 0, 0], scale: 2}]}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(bad_step, at(bad_step, 4, "{translate"), {"instance.transform", "one key"});
  const std::string overflow =
      with_world("  - {type: instance, object: o, transform: [{scale: 1e9}, {scale: 1e9}]}\n") +
      "objects: {o: [{type: sphere}]}\n";
  EXPECT_SCENE_ERROR(overflow, at(overflow, 4, "[{scale"), {"instance.transform", "beyond"});
}

TEST(SceneParser, RejectsDegenerateCameras) {
  const std::string same = camera_scene("{position: [1, 2, 3], look_at: [1, 2, 3]}");
  EXPECT_SCENE_ERROR(same, at(same, 2, "[1, 2, 3]}"), {"camera.look_at must differ from camera.position"});
  const std::string zero_up = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 0, 0]}");
  EXPECT_SCENE_ERROR(zero_up, at(zero_up, 2, "[0, 0, 0]}"), {"camera.up", "zero-length"});
  const std::string parallel = camera_scene("{position: [0, 0, -5], look_at: [0, 0, 0], up: [0, 0, 2]}");
  EXPECT_SCENE_ERROR(parallel, at(parallel, 2, "[0, 0, 2]"), {"camera.up", "parallel to the view direction"});
  const std::string looking_down = camera_scene("{position: [0, 5, 0], look_at: [0, 0, 0]}");
  EXPECT_SCENE_ERROR(looking_down, at(looking_down, 2, "[0, 0, 0]"), {"camera.up (default [0, 1, 0])", "parallel"});
}

TEST(SceneParser, RejectsZeroLengthLightDirection) {
  const std::string text = kHeader + "lights: [{type: directional, direction: [0, 0, 0]}]\n";
  EXPECT_SCENE_ERROR(text, at(text, 3, "[0, 0, 0]"), {"directional light.direction", "zero-length"});
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

TEST(SceneParser, MissingMeshFileIsReportedAtTheFileValue) {
  const std::string text = with_world("  - {type: mesh, file: meshes/absent.obj}\n");
  const auto file = test::write_file("scene.yaml", text);
  try {
    parse_scene_file(file);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, file.string());
    EXPECT_EQ(error.where().line, 4);
    EXPECT_EQ(error.where().column, at(text, 4, "meshes/absent").column);
    EXPECT_NE(error.message().find("mesh.file: mesh file 'meshes/absent.obj' not found"), std::string::npos)
        << error.what();
    EXPECT_NE(error.message().find((file.parent_path() / "meshes/absent.obj").string()), std::string::npos)
        << error.what();
  }
}

TEST(SceneParser, MeshPathsResolveAgainstTheSceneFolder) {
  const auto mesh = test::write_file("scenes/meshes/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto file = test::write_file("scenes/scene.yaml", with_world("  - {type: mesh, file: meshes/m.obj}\n"));
  const SceneDescription scene = parse_scene_file(file);
  ASSERT_EQ(scene.world.meshes.size(), 1u);
  EXPECT_TRUE(std::filesystem::equivalent(scene.world.meshes[0].file, mesh));

  const std::string wrong_format = with_world("  - {type: mesh, file: model.stl}\n");
  EXPECT_SCENE_ERROR(wrong_format, at(wrong_format, 4, "model.stl"), {"mesh.file", ".obj or .ply"});
}

TEST(SceneParser, MissingOrUnreadableSceneFileNamesTheFile) {
  const auto missing = test::scratch_dir() / "nowhere.yaml";
  try {
    parse_scene_file(missing);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, missing.string());
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos);
    EXPECT_NE(error.message().find("does not exist"), std::string::npos) << error.what();
  }
  try {
    parse_scene_file(test::scratch_dir());
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("is a directory"), std::string::npos) << error.what();
  }
}

TEST(SceneParserOverrides, SetValuesBeforeValidation) {
  const std::string text = kHeader + "render: {spp: 4}\nlights: [{type: point, position: [0, 1, 0]}]\n";
  const SceneDescription scene = parse_scene_text(
      text, "test.yaml",
      {"render.spp=64", "camera.resolution=[320, 240]", "camera.fov=30", "render.seed=7", "lights.0.intensity=2"});
  EXPECT_EQ(scene.render.spp, 64);
  EXPECT_EQ(scene.render.seed, 7u);
  EXPECT_EQ(scene.camera.width, 320);
  EXPECT_EQ(scene.camera.height, 240);
  EXPECT_EQ(scene.camera.fov_degrees, 30.0f);
  EXPECT_EQ(std::get<PointLightDesc>(scene.lights.at(0)).intensity, 2.0f);
}

TEST(SceneParserOverrides, CreateMissingSections) {
  const SceneDescription scene =
      parse_scene_text(kHeader, "test.yaml", {"render.max_depth=2", "materials.red.color=[1,0,0]"});
  EXPECT_EQ(scene.render.max_depth, 2);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[1].color, Color(1, 0, 0));
}

TEST(SceneParserOverrides, ChangeOnlyTheAliasTheyName) {
  const std::string text = kHeader + "materials:\n  a: &m {color: [0, 0, 1]}\n  b: *m\n";
  const SceneDescription scene = parse_scene_text(text, "test.yaml", {"materials.b.color=[1, 1, 1]"});
  EXPECT_EQ(scene.materials.at(1).color, Color(0, 0, 1));
  EXPECT_EQ(scene.materials.at(2).color, Color(1, 1, 1));
}

void check_override_error(const std::string& override_text, const std::vector<std::string>& fragments) {
  const InputError error = parse_error(kHeader + "render: {spp: 4}\n", {override_text});
  EXPECT_EQ(error.where().file, "--set " + override_text);
  EXPECT_EQ(error.where().line, 0);
  EXPECT_EQ(std::string(error.what()).rfind("--set " + override_text + ": ", 0), 0u) << error.what();
  for (const std::string& fragment : fragments)
    EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
}

TEST(SceneParserOverrides, ErrorsNameTheOverride) {
  check_override_error("render.spp=abc", {"render.spp: expected an integer, got 'abc'"});
  check_override_error("render.spp=0", {"render.spp", "from 1 to 65536"});
  check_override_error("camera.resolution=[320]", {"camera.resolution", "a list of 1 item"});
  check_override_error("camera.fov=.inf", {"camera.fov", "finite"});
  check_override_error("render.sp=64", {"unknown key 'sp' in render; did you mean 'spp'?"});
  check_override_error("rendr.spp=64", {"unknown key 'rendr'", "did you mean 'render'?"});
  check_override_error("render.spp", {"expected key=value"});
  check_override_error("render..spp=4", {"empty key name"});
  check_override_error("render.spp.x=4", {"'spp' is a single value"});
  check_override_error("lights.0.intensity=1", {"lights: expected a list of lights, got a mapping"});
  check_override_error("camera.resolution=[1, 2", {"YAML syntax error"});
}

}  // namespace scene_parser_test
}  // namespace rtpro
