// glTF files as whole scenes and inside YAML scenes (gltf_scene.h, build_render_scene.cpp).
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"
#include "gltf_asset.h"
#include "gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

namespace rtpro {
namespace gltf_scene_test {

using test::GltfFile;

// A unit cube's corners drawn as two triangles spanning it, placed at (10, 0, 0).
GltfFile offset_model() {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 1, 1, 1, 0, 0, 0, 1, 1, 1, 0, 1, 1}, "VEC3"));
  gltf.scene({gltf.node({{"mesh", mesh}, {"translation", {10, 0, 0}}})});
  return gltf;
}

TEST(GltfScene, WithoutCameraTheDefaultOneFramesTheBoundsAndADefaultLightShines) {
  const auto file = offset_model().write("model");
  const SceneDescription scene = parse_scene_file(file);
  const CameraDesc& camera = scene.camera;
  EXPECT_EQ(camera.look_at, Vec3(10.5f, 0.5f, 0.5f));
  const Vec3 forward = normalize(camera.look_at - camera.position);
  EXPECT_LT(forward.z, 0.0f);  // looking at the model's front (+z) side
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(10.0f + float(corner & 1), float(corner >> 1 & 1), float(corner >> 2 & 1));
    const float angle = std::acos(dot(normalize(p - camera.position), forward)) * 180.0f / 3.14159265f;
    EXPECT_LT(angle, camera.fov_degrees / 2) << corner;
  }
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<DirectionalLightDesc>(scene.lights[0]));
  ASSERT_EQ(scene.world.gltfs.size(), 1u);
  EXPECT_TRUE(scene.world.gltfs[0].loaded) << "read once, not again by build_render_scene";
  const RenderScene render = build_render_scene(scene);
  EXPECT_EQ(render.prototypes.size(), 1u);
  EXPECT_EQ(render.bounds().lower, Vec3(10, 0, 0));
}

TEST(GltfScene, AMeshDrawnOnlyMorphedHasNoPrototypeOfItsOwn) {
  // Node 0 draws mesh 0 morphed (weight 0.5); node 1 draws mesh 1 as it is.
  GltfFile gltf = offset_model();
  gltf.json["meshes"][0]["primitives"][0]["targets"] = {
      {{"POSITION", gltf.floats({0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC3")}}};
  gltf.json["meshes"][0]["weights"] = {0.5};
  const int plain = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.json["scenes"][0]["nodes"].push_back(gltf.node({{"mesh", plain}}));
  const RenderScene render = build_render_scene(parse_scene_file(gltf.write("morphed")));
  // The morphed copy and mesh 1: mesh 0 as the file stores it is drawn nowhere.
  ASSERT_EQ(render.prototypes.size(), 2u);
  std::size_t triangles = 0;
  for (const Group& prototype : render.prototypes)
    triangles += std::get<TriangleMesh>(prototype.geometries[0]).triangles.size();
  EXPECT_EQ(triangles, 3u);
}

TEST(GltfScene, TheFirstCameraAndThePunctualLightsAreUsed) {
  GltfFile gltf = offset_model();
  gltf.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}};
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 400}, {"color", {1, 0.5, 0.5}}},
      {{"type", "directional"}, {"intensity", 2}},
      {{"type", "spot"}, {"intensity", 100}, {"spot", nlohmann::json::object()}}};
  const int camera = gltf.node({{"camera", 0}, {"translation", {10.5, 0.5, 5}}});
  const int point =
      gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {10.5, 10.5, 0.5}}});
  const int sun = gltf.node(
      {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"rotation", {-0.7071068, 0, 0, 0.7071068}}});
  const int spot =
      gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}, {"translation", {10.5, 0.5, 10.5}}});
  gltf.json["scenes"][0]["nodes"] = {0, camera, point, sun, spot};
  const SceneDescription scene = parse_scene_file(gltf.write("lit"), {"render.spp=4"});
  EXPECT_EQ(scene.camera.position, Vec3(10.5f, 0.5f, 5.0f));
  EXPECT_EQ(scene.camera.look_at, Vec3(10.5f, 0.5f, 4.0f));
  EXPECT_NEAR(scene.camera.fov_degrees, 0.5f * 180.0f / 3.14159265f, 1e-4f);
  EXPECT_EQ(scene.camera.width, 2 * scene.camera.height);
  EXPECT_EQ(scene.render.spp, 4);  // --set works on glTF scenes too
  ASSERT_EQ(scene.lights.size(), 3u);
  // Photometric units as radiometric ones (683 lm/W, as Blender's importer reads them): candela
  // become W/sr, lux W/m²; the file's colours as they are. The file is path traced in the dark.
  EXPECT_EQ(scene.render.integrator, Integrator::kPath);
  EXPECT_EQ(scene.render.background, Color(0.0f));
  const auto& p = std::get<PointLightDesc>(scene.lights[0]);
  const auto& d = std::get<DirectionalLightDesc>(scene.lights[1]);
  const auto& s = std::get<SpotLightDesc>(scene.lights[2]);
  EXPECT_NEAR(p.intensity, 400.0f / 683.0f, 1e-6f);
  EXPECT_EQ(p.color, Color(1.0f, 0.5f, 0.5f));
  EXPECT_NEAR(d.intensity, 2.0f / 683.0f, 1e-6f);
  EXPECT_NEAR(d.direction.y, -1.0f, 1e-5f);  // the node's -z turned to point down
  EXPECT_NEAR(s.intensity, 100.0f / 683.0f, 1e-6f);
  EXPECT_EQ(s.position, Vec3(10.5f, 0.5f, 10.5f));
  EXPECT_EQ(s.direction, Vec3(0.0f, 0.0f, -1.0f));  // an unrotated node's -z
  EXPECT_EQ(s.inner_angle, 0.0f);                   // glTF's defaults: 0 and π/4
  EXPECT_NEAR(s.outer_angle, 45.0f, 1e-5f);
}

// A spot light on a child of a rotated, translated node: placed and aimed by both transforms (it
// shines down the node's -z), its cone's half-angles from radians to degrees, candela / 683 W/sr.
// aspectRatio 0.0011 made a 640x65536 image: ratios past 1:16 are clamped, with a warning.
TEST(GltfScene, AnAbsurdCameraAspectRatioIsClampedWithAWarning) {
  GltfFile gltf = offset_model();
  gltf.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 0.0011}, {"znear", 0.1}}}}};
  const int camera = gltf.node({{"camera", 0}, {"translation", {10.5, 0.5, 5}}});
  gltf.json["scenes"][0]["nodes"] = {0, camera};
  const auto file = gltf.write("tall");
  const SceneDescription scene = parse_scene_file(file);
  EXPECT_EQ(scene.camera.width, 640);
  EXPECT_EQ(scene.camera.height, 640 * 16);
  ASSERT_EQ(scene.world.gltfs.size(), 1u);
  ASSERT_TRUE(scene.world.gltfs[0].loaded);
  bool warned = false;
  for (const std::string& w : scene.world.gltfs[0].loaded->stats.warnings)
    warned |= w.find("cameras[0].perspective.aspectRatio 0.001100 is outside 1/16..16; 0.062500 is used") !=
              std::string::npos;
  EXPECT_TRUE(warned);
}

// The scene a glTF file makes is YAML text naming the file: `$b` in `a$b.gltf` was read as a
// variable ("undefined variable '$b'").
TEST(GltfScene, AFileNameWithADollarOrAQuoteIsReadAsItIs) {
  const auto file = offset_model().write("a$b \"q\"", /*embed=*/true);
  const SceneDescription scene = parse_scene_file(file);
  ASSERT_EQ(scene.world.gltfs.size(), 1u);
  EXPECT_EQ(scene.world.gltfs[0].file.filename(), file.filename());
}

TEST(GltfScene, ASpotLightKeepsItsConeAndShinesDownItsNodesMinusZ) {
  GltfFile gltf = offset_model();
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"},
       {"intensity", 1366},
       {"color", {0.5, 1, 1}},
       {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
      {{"type", "spot"},
       {"spot", {{"outerConeAngle", double(1.5707963705062866)}}}}};  // π/2 as a float, as Blender writes it
  const double s = std::sqrt(0.5);
  const int lamp = gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0, -2}}});
  // 90° about +y: -z turns to -x.
  const int arm = gltf.node({{"children", {lamp}}, {"translation", {1, 2, 3}}, {"rotation", {0, s, 0, s}}});
  const int wide = gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  gltf.json["scenes"][0]["nodes"] = {0, arm, wide};
  const SceneDescription scene = parse_scene_file(gltf.write("spot"));
  ASSERT_EQ(scene.lights.size(), 2u);
  const auto& spot = std::get<SpotLightDesc>(scene.lights[0]);
  EXPECT_NEAR(spot.position.x, -1.0f, 1e-5f);
  EXPECT_NEAR(spot.position.y, 2.0f, 1e-5f);
  EXPECT_NEAR(spot.position.z, 3.0f, 1e-5f);
  EXPECT_NEAR(spot.direction.x, -1.0f, 1e-6f);
  EXPECT_NEAR(spot.direction.y, 0.0f, 1e-6f);
  EXPECT_NEAR(spot.direction.z, 0.0f, 1e-6f);
  EXPECT_NEAR(spot.inner_angle, 0.2 * 180.0 / 3.14159265358979, 1e-4);
  EXPECT_NEAR(spot.outer_angle, 0.6 * 180.0 / 3.14159265358979, 1e-4);
  EXPECT_NEAR(spot.intensity, 2.0f, 1e-6f);
  EXPECT_EQ(spot.color, Color(0.5f, 1.0f, 1.0f));
  const auto& hemisphere = std::get<SpotLightDesc>(scene.lights[1]);
  EXPECT_EQ(hemisphere.outer_angle, 90.0f);  // held to the limit, not refused
  EXPECT_EQ(hemisphere.inner_angle, 0.0f);
  EXPECT_NEAR(hemisphere.intensity, 1.0f / 683.0f, 1e-9f);  // glTF's default intensity, 1 cd
  const RenderScene render = build_render_scene(scene);
  const auto& light = std::get<SpotLight>(render.lights[0]);
  EXPECT_NEAR(light.cos_inner, std::cos(0.2), 1e-6);
  EXPECT_NEAR(light.cos_outer, std::cos(0.6), 1e-6);
  EXPECT_NEAR(light.radiance.y, 2.0f, 1e-6f);
}

// Outside glTF's 0 <= innerConeAngle <= outerConeAngle <= π/2 (beyond rounding) the file is
// refused at the light's JSON path.
TEST(GltfScene, ASpotLightsConeOutsideGltfsLimitsIsRefused) {
  const auto refusal = [](const nlohmann::json& spot) {
    GltfFile gltf = offset_model();
    gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
    gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "spot"}, {"spot", spot}}};
    gltf.json["scenes"][0]["nodes"] = {0, gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})};
    try {
      parse_scene_file(gltf.write("bad_spot"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << "accepted " << spot.dump();
    return std::string();
  };
  EXPECT_NE(refusal({{"outerConeAngle", 1.6}}).find("lights[0].spot.outerConeAngle"), std::string::npos);
  EXPECT_NE(refusal({{"outerConeAngle", 0.0}}).find("lights[0].spot.outerConeAngle"), std::string::npos);
  EXPECT_NE(refusal({{"innerConeAngle", 0.9}}).find("lights[0].spot.innerConeAngle"), std::string::npos);  // past π/4
  EXPECT_NE(refusal({{"innerConeAngle", -0.1}}).find("at most outerConeAngle"), std::string::npos);
}

TEST(GltfScene, AnEmissiveMaterialLightsTheSceneInsteadOfTheDefaultSunAndSky) {
  GltfFile gltf = offset_model();
  gltf.json["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  gltf.json["materials"] = {{{"emissiveFactor", {1.0, 0.5, 0.25}},
                             {"doubleSided", true},
                             {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}}}}},
                            {{"emissiveFactor", {0.0, 0.0, 0.0}}}};
  gltf.json["meshes"][0]["primitives"][0]["material"] = 0;
  const SceneDescription scene = parse_scene_file(gltf.write("glowing"));
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.render.background, Color(0.0f));
  EXPECT_EQ(scene.render.integrator, Integrator::kPath);
  const RenderScene render = build_render_scene(scene);
  ASSERT_GE(render.materials.size(), 3u);
  const Emission& lamp = render.materials[render.materials.size() - 2].emission;
  EXPECT_EQ(lamp.radiance, Color(8.0f, 4.0f, 2.0f));
  EXPECT_TRUE(lamp.two_sided);
  EXPECT_FALSE(render.materials.back().emission.emits());
}

// One mesh drawn by `nodes` nodes side by side.
GltfFile repeated_model(int nodes) {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  std::vector<int> roots;
  for (int i = 0; i < nodes; ++i) roots.push_back(gltf.node({{"mesh", mesh}, {"translation", {2.0 * i, 0, 0}}}));
  gltf.scene(roots);
  return gltf;
}

TEST(GltfScene, TheCostEstimateCountsTheNodesOfAGltfSceneAsInstances) {
  const SceneDescription description = parse_scene_file(repeated_model(7).write("seven"));
  EXPECT_EQ(estimate_render_cost(description).flattened_instances, 7u);
  EXPECT_GT(estimate_render_cost(description).mesh_bytes, 0u);
}

// 100 placements in the file × 1,000 per row × 200 rows: 2·10^7 instances from a few kilobytes,
// refused at the world instance that crosses the limit (the 101st, line 1108), before anything is
// flattened.
TEST(GltfScene, PlacementsInsideAGltfObjectCountTowardTheInstanceLimitBeforeFlattening) {
  repeated_model(100).write("hundred", true);
  std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, 30], look_at: [0, 0, 0]}\nobjects:\n  piece:\n"
      "    - {type: mesh, file: hundred.gltf}\n  row:\n";
  for (int i = 0; i < 1000; ++i) text += "    - {type: instance, object: piece}\n";
  text += "world:\n";
  for (int i = 0; i < 200; ++i) text += "  - {type: instance, object: row}\n";
  const SceneDescription description = parse_scene_file(test::write_file("rows.yaml", text));
  try {
    build_render_scene(description);
    FAIL() << "the instance limit was not applied";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("instances after flattening"), std::string::npos) << message;
    EXPECT_NE(message.find("rows.yaml:" + std::to_string(7 + 1000 + 101) + ":"), std::string::npos) << message;
  }
}

TEST(GltfScene, AGltfObjectInAYamlSceneIsPlacedThroughEveryLevel) {
  offset_model().write("piece");
  const auto scene_file = test::write_file("scene.yaml", R"(rtpro: 1
camera: {position: [0, 0, 30], look_at: [0, 0, 0]}
materials:
  red: {color: [1, 0, 0]}
objects:
  piece:
    - {type: mesh, file: piece.gltf, normals: flat}
world:
  - {type: instance, object: piece, transform: {translate: [0, 5, 0]}}
  - {type: instance, object: piece, transform: {scale: 2}}
  - {type: mesh, file: piece.gltf, material: red}
)");
  const SceneDescription description = parse_scene_file(scene_file);
  ASSERT_EQ(description.objects[0].gltfs.size(), 1u);
  EXPECT_EQ(description.objects[0].gltfs[0].normals, NormalsMode::kFlat);
  const RenderScene scene = build_render_scene(description);
  // Two loads (the override material makes a different prototype), three placements.
  EXPECT_EQ(scene.prototypes.size(), 2u);
  std::vector<Vec3> origins;
  for (const Geometry& g : scene.top.geometries)
    if (const auto* instance = std::get_if<Instance>(&g))
      origins.push_back(instance->object_to_world.apply_point(Vec3(0, 0, 0)));
  ASSERT_EQ(origins.size(), 3u);
  EXPECT_EQ(origins[0], Vec3(10, 0, 0));  // the world's own glTF, placed first
  EXPECT_EQ(origins[1], Vec3(10, 5, 0));  // node translation, then the instance's
  EXPECT_EQ(origins[2], Vec3(20, 0, 0));  // node translation, then scaled by 2
  const auto& red =
      std::get<TriangleMesh>(scene.prototypes[std::get<Instance>(scene.top.geometries[0]).prototype].geometries[0]);
  EXPECT_EQ(scene.material_names[red.material], "red");
}

TEST(GltfScene, NormalsKeyIsCheckedLikeEveryOtherKey) {
  offset_model().write("piece");
  try {
    parse_scene_text(
        "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nworld:\n  - {type: mesh, file: piece.gltf, "
        "normals: smoth}\n",
        test::write_file("bad.yaml", ""));
    ADD_FAILURE() << "accepted normals: smoth";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(e.message().find("did you mean 'smooth'"), std::string::npos) << e.message();
  }
}

TEST(GltfScene, RendersFromTheCommandLineWithBothBackends) {
  const auto file = offset_model().write("cli");
  for (const char* backend : {"native", "embree"}) {
    std::string output;
    const int code = test::run_command(test::rtpro_executable().string() + " render " + file.string() + " -o " +
                                           (file.parent_path() / (std::string(backend) + ".exr")).string() +
                                           " --size 32x24 --spp 1 -q --backend " + backend,
                                       &output);
    EXPECT_EQ(code, 0) << output;
    EXPECT_TRUE(std::filesystem::is_regular_file(file.parent_path() / (std::string(backend) + ".exr")));
  }
  std::string output;
  EXPECT_EQ(test::run_command(test::rtpro_executable().string() + " render " +
                                  (file.parent_path() / "absent.glb").string() + " -o x.exr",
                              &output),
            2)
      << output;
}

TEST(GltfScene, InfoShowsLoaderWarningsAndNoInfiniteBoundsForAnEmptyMesh) {
  const auto mesh = test::write_file("empty.obj", "o nothing\nl 1 1\n");
  const auto scene = test::write_file("empty.yaml",
                                      "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\n"
                                      "world:\n  - {type: mesh, file: empty.obj}\n");
  std::string output;
  EXPECT_EQ(test::run_command(test::rtpro_executable().string() + " info " + scene.string(), &output), 0) << output;
  EXPECT_NE(output.find("warning    " + mesh.string() + ": no faces"), std::string::npos) << output;
  EXPECT_NE(output.find("ignored 'l' statements"), std::string::npos) << output;
  EXPECT_NE(output.find("bounds       none"), std::string::npos) << output;
  EXPECT_EQ(output.find("inf"), std::string::npos) << output;
  EXPECT_EQ(test::run_command(test::rtpro_executable().string() + " info --json " + scene.string(), &output), 0);
  EXPECT_NE(output.find("\"bounds\": null"), std::string::npos) << output;
}

}  // namespace gltf_scene_test
}  // namespace rtpro
