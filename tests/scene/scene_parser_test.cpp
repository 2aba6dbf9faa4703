// What the YAML scene parser reads: every section, defaults, transforms, aliases and mesh files.
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::test {
namespace scene_parser_test {

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

}  // namespace scene_parser_test
}  // namespace rtpro::test
