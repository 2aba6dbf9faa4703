// glTF animation, skins and morph targets: small hand-written files posed at chosen times, checked
// against values computed by hand from the glTF 2.0 specification's formulas.
#include "gltf_asset.h"
#include "gltf_load_error.h"
#include "gltf_loader.h"
#include "gltf_motion.h"
#include "gltf_pose.h"
#include "gltf_test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>

namespace rtpro {
namespace gltf_animation_test {

using test::GltfFile;
using test::kTriangle;

void expect_near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// One animation of one channel: `path` of node 0 keyed at `times` with `values` (type VEC3,
// VEC4 or SCALAR) by `interpolation`.
void animate(GltfFile& gltf, int node, const char* path, const std::vector<float>& times,
             const std::vector<float>& values, const char* type, const char* interpolation = "LINEAR") {
  const int input = gltf.floats(times, "SCALAR");
  const int output = gltf.floats(values, type);
  gltf.json["animations"].push_back(
      {{"samplers", {{{"input", input}, {"output", output}, {"interpolation", interpolation}}}},
       {"channels", {{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}}}});
}

// A file placing kTriangle at node 0, which `animate` may key.
GltfFile triangle_file() {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  gltf.scene({gltf.node({{"mesh", mesh}})});
  return gltf;
}

TEST(GltfAnimation, LinearRotationSlerpsAlongTheShorterArc) {
  const float s = std::sqrt(0.5f);
  // 0 to 90 degrees about +y; the second key written as its negation (the same rotation), which a
  // plain lerp would take the long way round.
  GltfFile gltf = triangle_file();
  animate(gltf, 0, "rotation", {0, 1}, {0, 0, 0, 1, 0, -s, 0, -s}, "VEC4");
  const GltfAsset asset = load_gltf_file(gltf.write("slerp"));
  const GltfPose pose = pose_gltf(asset, 0.25);
  ASSERT_EQ(pose.placements.size(), 1u);
  const double angle = 22.5 * std::acos(-1.0) / 180.0;  // a quarter of 90 degrees
  expect_near(pose.placements[0].transform.apply_point(Vec3(1, 0, 0)),
              Vec3(float(std::cos(angle)), 0.0f, float(-std::sin(angle))));
  // Past the last key the last value holds: 90 degrees, (1, 0, 0) -> (0, 0, -1).
  expect_near(pose_gltf(asset, 7.0).placements[0].transform.apply_point(Vec3(1, 0, 0)), Vec3(0, 0, -1));
}

TEST(GltfAnimation, LinearRotationSlerpsTheRotationsOfKeysOffUnitLength) {
  const float s = std::sqrt(0.5f);
  // The identity written at twice unit length, then 90 degrees about +y: halfway is 45 degrees.
  // Slerping the keys as written (weights from the angle of their raw dot product) gives 29.3.
  GltfFile gltf = triangle_file();
  animate(gltf, 0, "rotation", {0, 1}, {0, 0, 0, 2, 0, s, 0, s}, "VEC4");
  const GltfAsset asset = load_gltf_file(gltf.write("slerp_unnormalised"));
  const float c = std::sqrt(0.5f);
  expect_near(pose_gltf(asset, 0.5).placements[0].transform.apply_point(Vec3(1, 0, 0)), Vec3(c, 0, -c));
}

TEST(GltfAnimation, CubicSplineScalesTangentsByTheKeyInterval) {
  // x from 0 (out-tangent 1) at t = 0 to 1 (in-tangent 0) at t = 2. At t = 1 (s = 1/2) the
  // Hermite basis is h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8: x = 1/8 · 2 · 1 + 1/2 · 1 = 0.75.
  GltfFile gltf = triangle_file();
  animate(gltf, 0, "translation", {0, 2},
          {0, 0, 0, /* value */ 0, 0, 0, /* out */ 1, 0, 0, /* in */ 0, 0, 0, /* value */ 1, 0, 0, /* out */ 0, 0, 0},
          "VEC3", "CUBICSPLINE");
  const GltfAsset asset = load_gltf_file(gltf.write("cubic"));
  expect_near(pose_gltf(asset, 1.0).placements[0].transform.apply_point(Vec3(0, 0, 0)), Vec3(0.75f, 0, 0));
  // s = 1/4: h00 = 27/32, h10 = 9/64, h01 = 5/32: x = 9/64 · 2 + 5/32 = 0.4375.
  expect_near(pose_gltf(asset, 0.5).placements[0].transform.apply_point(Vec3(0, 0, 0)), Vec3(0.4375f, 0, 0));
}

TEST(GltfAnimation, StepHoldsEachKeyUntilTheNext) {
  GltfFile gltf = triangle_file();
  animate(gltf, 0, "scale", {1, 2}, {1, 1, 1, 3, 3, 3}, "VEC3", "STEP");
  const GltfAsset asset = load_gltf_file(gltf.write("step"));
  const auto x_scale = [&](double t) { return pose_gltf(asset, t).placements[0].transform.m[0][0]; };
  EXPECT_EQ(x_scale(0.0), 1.0f);  // before the first key
  EXPECT_EQ(x_scale(1.99), 1.0f);
  EXPECT_EQ(x_scale(2.0), 3.0f);
  EXPECT_EQ(x_scale(100.0), 3.0f);
}

TEST(GltfAnimation, SkinnedVertexFollowsItsWeightedJoints) {
  // Joint 0 at the origin, joint 1 at (2, 0, 0) with the inverse bind matrix moving it back;
  // joint 1 rises to (2, 1, 0) at t = 1. Every vertex half on each: at t = 1, J0 = I and
  // J1 = T(0, 1, 0), so each vertex rises by 0.5. The mesh node's own translation is ignored.
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  auto& attributes = gltf.json["meshes"][mesh]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = gltf.ushorts({0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, "VEC4");
  attributes["WEIGHTS_0"] = gltf.floats({0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4");
  const int bind = gltf.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1,  // identity
                                1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -2, 0, 0, 1},
                               "MAT4");
  const int joint0 = gltf.node({{"children", {1}}});
  gltf.node({{"translation", {2, 0, 0}}});
  const int skinned = gltf.node({{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}});
  gltf.json["skins"] = {{{"joints", {0, 1}}, {"inverseBindMatrices", bind}}};
  gltf.scene({joint0, skinned});
  animate(gltf, 1, "translation", {0, 1}, {2, 0, 0, 2, 1, 0}, "VEC3");
  const GltfAsset asset = load_gltf_file(gltf.write("skin"));
  // At rest the joints sit where they were bound: the mesh as written.
  ASSERT_EQ(asset.placements.size(), 1u);
  expect_near(asset.mesh_of(asset, asset.placements[0]).vertex(0), Vec3(1, 0, 0));
  const GltfPose pose = pose_gltf(asset, 1.0);
  ASSERT_EQ(pose.placements.size(), 1u);
  EXPECT_EQ(pose.placements[0].transform, Affine::identity());
  const TriangleMesh& posed = asset.mesh_of(pose, pose.placements[0]);
  expect_near(posed.vertex(0), Vec3(1, 0.5f, 0));
  expect_near(posed.vertex(2), Vec3(0, 0.5f, 1));
  // Halfway (t = 0.5) joint 1 is at (2, 0.5, 0): each vertex rises by 0.25.
  expect_near(asset.mesh_of(pose_gltf(asset, 0.5), pose.placements[0]).vertex(1), Vec3(0, 1.25f, 0));
}

TEST(GltfAnimation, EightInfluencesFromTwoSetsOfJointsAndWeights) {
  // Joints 0..7 at the origin, joint k rising to (0, k + 1, 0) at t = 1; every vertex an eighth on
  // each (JOINTS_0 names joints 0..3, JOINTS_1 joints 4..7): at t = 1 it rises by 4.5, the mean of
  // 1..8 (by 2.5 if the second set were dropped and the first renormalised).
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  auto& attributes = gltf.json["meshes"][mesh]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = gltf.ushorts({0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}, "VEC4");
  attributes["JOINTS_1"] = gltf.ushorts({4, 5, 6, 7, 4, 5, 6, 7, 4, 5, 6, 7}, "VEC4");
  attributes["WEIGHTS_0"] = gltf.floats(std::vector<float>(12, 0.125f), "VEC4");
  attributes["WEIGHTS_1"] = gltf.floats(std::vector<float>(12, 0.125f), "VEC4");
  std::vector<int> nodes;
  for (int k = 0; k < 8; ++k) nodes.push_back(gltf.node(nlohmann::json::object()));
  nodes.push_back(gltf.node({{"mesh", mesh}, {"skin", 0}}));
  gltf.json["skins"] = {{{"joints", {0, 1, 2, 3, 4, 5, 6, 7}}}};
  gltf.scene(nodes);
  for (int k = 0; k < 8; ++k) animate(gltf, k, "translation", {0, 1}, {0, 0, 0, 0, float(k + 1), 0}, "VEC3");
  const GltfAsset asset = load_gltf_file(gltf.write("eight_influences"));
  const GltfPose pose = pose_gltf(asset, 1.0);
  ASSERT_EQ(pose.placements.size(), 1u);
  expect_near(asset.mesh_of(pose, pose.placements[0]).vertex(0), Vec3(1, 4.5f, 0));
  expect_near(asset.mesh_of(pose, pose.placements[0]).vertex(2), Vec3(0, 4.5f, 1));

  // A second set alone, half a set, or a third set: errors naming the attributes.
  for (const auto& [remove, add, expected] :
       {std::tuple{"JOINTS_0", "", "JOINTS_1 or WEIGHTS_1 without JOINTS_0"},
        std::tuple{"WEIGHTS_1", "", "one of JOINTS_1 and WEIGHTS_1 without the other"},
        std::tuple{"", "JOINTS_2", "third set of joints or weights"}}) {
    GltfFile broken = gltf;
    auto& a = broken.json["meshes"][mesh]["primitives"][0]["attributes"];
    if (*remove) {
      a.erase(remove);
      if (std::string(remove) == "JOINTS_0") a.erase("WEIGHTS_0");
    }
    if (*add) a[add] = a["JOINTS_1"];
    const std::string message = test::gltf_error_of(broken.write("bad_influences"));
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_NE(message.find("meshes[0].primitives[0].attributes"), std::string::npos) << message;
  }
}

TEST(GltfAnimation, MorphTargetsBlendByMeshNodeAndAnimatedWeights) {
  // One target moving vertex 0 by (0, 0, 2).
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  gltf.json["meshes"][mesh]["primitives"][0]["targets"] = {
      {{"POSITION", gltf.floats({0, 0, 2, 0, 0, 0, 0, 0, 0}, "VEC3")}}};
  gltf.json["meshes"][mesh]["weights"] = {0.5};
  const int animated = gltf.node({{"mesh", mesh}});
  const int own_weights = gltf.node({{"mesh", mesh}, {"weights", {0.25}}});
  gltf.scene({animated, own_weights});
  animate(gltf, animated, "weights", {0, 1}, {0, 1}, "SCALAR");
  const GltfAsset asset = load_gltf_file(gltf.write("morph"));
  // Without animation: the mesh's weight 0.5 (z = 1), the node's own 0.25 (z = 0.5).
  ASSERT_EQ(asset.placements.size(), 2u);
  expect_near(asset.mesh_of(asset, asset.placements[0]).vertex(0), Vec3(1, 0, 1));
  expect_near(asset.mesh_of(asset, asset.placements[1]).vertex(0), Vec3(1, 0, 0.5f));
  // At t = 0.75 the animated weight is 0.75: z = 1.5; the other node keeps its own.
  const GltfPose pose = pose_gltf(asset, 0.75);
  expect_near(asset.mesh_of(pose, pose.placements[0]).vertex(0), Vec3(1, 0, 1.5f));
  expect_near(asset.mesh_of(pose, pose.placements[1]).vertex(0), Vec3(1, 0, 0.5f));
  expect_near(asset.mesh_of(pose, pose.placements[0]).vertex(1), Vec3(0, 1, 0));
}

TEST(GltfAnimation, EachNodeFollowsTheFirstAnimationThatKeysIt) {
  GltfFile gltf = triangle_file();
  animate(gltf, 0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "VEC3");
  animate(gltf, 0, "translation", {0, 1}, {0, 0, 0, 0, 5, 0}, "VEC3");
  // The second animation's sampler reads its own accessors.
  gltf.json["animations"][1]["samplers"][0]["input"] = 3;
  gltf.json["animations"][1]["samplers"][0]["output"] = 4;
  const GltfAsset asset = load_gltf_file(gltf.write("two"));
  expect_near(pose_gltf(asset, 1.0).placements[0].transform.apply_point(Vec3(0, 0, 0)), Vec3(1, 0, 0));
}

TEST(GltfAnimation, BadAnimationsAndSkinsAreErrorsNamingTheirJsonPath) {
  {
    GltfFile gltf = triangle_file();
    animate(gltf, 0, "translation", {0, 1, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3");
    const std::string message = test::gltf_error_of(gltf.write("not_increasing"));
    EXPECT_NE(message.find("animations[0].samplers[0].input"), std::string::npos) << message;
    EXPECT_NE(message.find("increase strictly"), std::string::npos) << message;
  }
  {
    GltfFile gltf = triangle_file();
    animate(gltf, 0, "translation", {0, std::nanf("")}, {0, 0, 0, 1, 0, 0}, "VEC3");
    const std::string message = test::gltf_error_of(gltf.write("nan_key"));
    EXPECT_NE(message.find("animations[0].samplers[0]"), std::string::npos) << message;
    EXPECT_NE(message.find("not a finite number"), std::string::npos) << message;
  }
  {
    GltfFile gltf = triangle_file();
    animate(gltf, 0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3");
    const std::string message = test::gltf_error_of(gltf.write("count"));
    EXPECT_NE(message.find("animations[0].samplers[0].output"), std::string::npos) << message;
  }
  {
    GltfFile gltf = triangle_file();
    animate(gltf, 0, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "VEC3");
    gltf.json["animations"][0]["channels"][0]["target"]["node"] = 9;
    EXPECT_NE(test::gltf_error_of(gltf.write("no_node")).find("animations[0].channels[0].target.node"),
              std::string::npos);
  }
  {
    GltfFile gltf = triangle_file();
    animate(gltf, 0, "weights", {0, 1}, {0, 1}, "SCALAR");
    EXPECT_NE(test::gltf_error_of(gltf.write("no_targets")).find("morph targets"), std::string::npos);
  }
  {
    GltfFile gltf;
    const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
    auto& attributes = gltf.json["meshes"][mesh]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = gltf.ushorts({0, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0, 0}, "VEC4");
    attributes["WEIGHTS_0"] = gltf.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    const int joint = gltf.node(nlohmann::json::object());
    gltf.json["skins"] = {{{"joints", {joint}}}};
    gltf.scene({joint, gltf.node({{"mesh", mesh}, {"skin", 0}})});
    const std::string message = test::gltf_error_of(gltf.write("joint_past_skin"));
    EXPECT_NE(message.find("meshes[0].primitives[0].attributes.JOINTS_0"), std::string::npos) << message;
    EXPECT_NE(message.find("skins[0], which has 1 joints"), std::string::npos) << message;
  }
}

TEST(GltfAnimation, AnOpenShutterGivesMovingNodesAndDeformingMeshesTimeSteps) {
  // Node 0 turns 90° about +y over 1 s; node 1 (morphed) has its weight keyed 0 to 1 over 1 s;
  // node 2 keeps still.
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  const int morphed = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  gltf.json["meshes"][morphed]["primitives"][0]["targets"] = {
      {{"POSITION", gltf.floats({0, 0, 2, 0, 0, 0, 0, 0, 0}, "VEC3")}}};
  const float s = std::sqrt(0.5f);
  gltf.scene({gltf.node({{"mesh", mesh}}), gltf.node({{"mesh", morphed}}), gltf.node({{"mesh", mesh}})});
  animate(gltf, 0, "rotation", {0, 1}, {0, 0, 0, 1, 0, s, 0, s}, "VEC4");
  const int input = gltf.floats({0, 1}, "SCALAR");
  gltf.json["animations"][0]["samplers"].push_back({{"input", input}, {"output", gltf.floats({0, 1}, "SCALAR")}});
  gltf.json["animations"][0]["channels"].push_back({{"sampler", 1}, {"target", {{"node", 1}, {"path", "weights"}}}});
  const GltfAsset asset = load_gltf_file(gltf.write("shutter"));
  // Frame 12 at 24 fps is 0.5 s; the shutter spans frames 6 to 18 (0.25 s to 0.75 s).
  const Shutter shutter{-6.0f, 6.0f};
  const GltfPose pose = pose_gltf_frame(asset, 12.0, 24.0, shutter);
  ASSERT_EQ(pose.placements.size(), 3u);
  const std::vector<Affine>& turning = pose.placements[0].transform_steps;
  // A 45° turn in the shutter: more than two steps keep it on its arc; the ends are its poses at
  // the shutter's ends.
  ASSERT_GT(turning.size(), 2u);
  EXPECT_EQ(turning.front(), pose_gltf(asset, 0.25).placements[0].transform);
  EXPECT_EQ(turning.back(), pose_gltf(asset, 0.75).placements[0].transform);
  EXPECT_TRUE(pose.placements[1].transform_steps.empty());
  EXPECT_TRUE(pose.placements[2].transform_steps.empty());
  const TriangleMesh& deforming = asset.mesh_of(pose, pose.placements[1]);
  // The weight changes linearly, so the vertices move on straight lines: two steps hold the motion.
  ASSERT_EQ(deforming.vertex_steps.size(), 2u);
  EXPECT_NEAR(deforming.vertex_steps.front()[0].z, 0.5f, 1e-6f);  // weight 0.25
  EXPECT_NEAR(deforming.vertex_steps.back()[0].z, 1.5f, 1e-6f);   // weight 0.75
  EXPECT_NEAR(deforming.vertex(0).z, 1.0f, 1e-6f);                // the frame's own pose
  // A closed shutter: no steps at all.
  const GltfPose still = pose_gltf_frame(asset, 12.0, 24.0, Shutter{});
  EXPECT_TRUE(still.placements[0].transform_steps.empty());
  EXPECT_TRUE(asset.mesh_of(still, still.placements[1]).vertex_steps.empty());
}

TEST(GltfAnimation, DeformingMeshesTakeAsManyVertexStepsAsKeepThemOnTheirPaths) {
  const Shutter shutter{-6.0f, 6.0f};  // frame 12 at 24 fps: 0.25 s to 0.75 s
  {
    // The weight goes 0.5, 1, 0.5 over the shutter: both ends alike, the middle apart. Three steps
    // are exact (the weight is linear on each half); two would leave the mesh still.
    GltfFile gltf = triangle_file();
    gltf.json["meshes"][0]["primitives"][0]["targets"] = {
        {{"POSITION", gltf.floats({0, 0, 2, 0, 0, 0, 0, 0, 0}, "VEC3")}}};
    animate(gltf, 0, "weights", {0, 0.5f, 1}, {0, 1, 0}, "SCALAR");
    const GltfAsset asset = load_gltf_file(gltf.write("peaked_weight"));
    const GltfPose pose = pose_gltf_frame(asset, 12.0, 24.0, shutter);
    const TriangleMesh& mesh = asset.mesh_of(pose, pose.placements[0]);
    ASSERT_EQ(mesh.vertex_steps.size(), 3u);
    EXPECT_NEAR(mesh.vertex_steps[0][0].z, 1.0f, 1e-6f);
    EXPECT_NEAR(mesh.vertex_steps[1][0].z, 2.0f, 1e-6f);
    EXPECT_NEAR(mesh.vertex_steps[2][0].z, 1.0f, 1e-6f);
  }
  {
    // A joint turning 90° about +y in the shutter: its vertices follow arcs, which take the most
    // steps; each step is the pose at its time.
    GltfFile gltf;
    const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
    auto& attributes = gltf.json["meshes"][mesh]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = gltf.ushorts({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "VEC4");
    attributes["WEIGHTS_0"] = gltf.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    const int joint = gltf.node(nlohmann::json::object());
    gltf.json["skins"] = {{{"joints", {joint}}}};
    gltf.scene({joint, gltf.node({{"mesh", mesh}, {"skin", 0}})});
    const float s = std::sqrt(0.5f);
    animate(gltf, joint, "rotation", {0.25f, 0.75f}, {0, 0, 0, 1, 0, s, 0, s}, "VEC4");
    const GltfAsset asset = load_gltf_file(gltf.write("turning_joint"));
    const GltfPose pose = pose_gltf_frame(asset, 12.0, 24.0, shutter);
    const TriangleMesh& skinned = asset.mesh_of(pose, pose.placements[0]);
    ASSERT_EQ(skinned.vertex_steps.size(), std::size_t(kMaxDeformationSteps));
    for (int step = 0; step < kMaxDeformationSteps; ++step) {
      const double time = 0.25 + 0.5 * step / (kMaxDeformationSteps - 1);
      const GltfPose at = pose_gltf(asset, time);
      for (std::uint32_t v = 0; v < 3; ++v)
        expect_near(skinned.vertex_steps[std::size_t(step)][v].position(),
                    asset.mesh_of(at, at.placements[0]).vertex(v));
    }
  }
}

// Khronos' samples from Debian's assimp-testmodels, posed against values worked out from their
// JSON and buffers by the specification's formulas (in Python, outside rtpro).
const std::filesystem::path kSamples = "/usr/share/assimp/models/glTF2";

TEST(GltfAnimationSamples, SimpleSkinBendsAsItsJointsTurn) {
  const auto file = kSamples / "simple_skin/simple_skin.gltf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const GltfAsset asset = load_gltf_file(file);
  // At t = 1 s joint 2 has turned 90° about z (its key (0, 0, 0.707, 0.707)). Both inverse bind
  // matrices are T(-0.5, -1, 0) and joint 1 sits at (0, 1, 0): vertex 8, (0, 2, 0) wholly on
  // joint 2, goes to (0, 1, 0) + R(-0.5, 1, 0) = (-1, 0.5, 0); vertex 4, (0, 1, 0) half on each,
  // to the mean of (-0.5, 1, 0) and (0, 0.5, 0).
  const GltfPose pose = pose_gltf(asset, 1.0);
  ASSERT_EQ(pose.placements.size(), 1u);
  const TriangleMesh& mesh = asset.mesh_of(pose, pose.placements[0]);
  expect_near(mesh.vertex(8), Vec3(-1.0f, 0.5f, 0.0f), 1e-5f);
  expect_near(mesh.vertex(4), Vec3(-0.25f, 0.75f, 0.0f), 1e-5f);
  // Without animation both joints are as bound: every vertex moved by T(-0.5, 0, 0).
  expect_near(asset.mesh_of(asset, asset.placements[0]).vertex(8), Vec3(-0.5f, 2.0f, 0.0f), 1e-6f);
}

TEST(GltfAnimationSamples, AnimatedMorphCubeFollowsItsWeights) {
  const auto file = kSamples / "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const GltfAsset asset = load_gltf_file(file);
  // At t = 1 s the weights are (0.68359367, 0): the cube's lowest y (in the mesh) rises from
  // -0.01 to 0.0029421515.
  EXPECT_NEAR(asset.mesh_of(asset, asset.placements[0]).bounds().lower.y, -0.01f, 1e-7f);
  const GltfPose pose = pose_gltf(asset, 1.0);
  ASSERT_EQ(pose.placements.size(), 1u);
  const BBox bounds = asset.mesh_of(pose, pose.placements[0]).bounds();
  EXPECT_NEAR(bounds.lower.y, 0.0029421515f, 1e-7f);
  EXPECT_NEAR(bounds.upper.y, 0.01f, 1e-7f);
}

}  // namespace gltf_animation_test
}  // namespace rtpro
