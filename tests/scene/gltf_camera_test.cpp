// glTF cameras as the scene's camera: an orthographic one keeps its projection (ymag the half
// height, xmag / ymag the aspect), and one under an animated parent takes its frame at the
// shutter's time steps (camera motion blur), none while the shutter is closed.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "gltf_test_files.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace gltf_camera_test {

using test::GltfFile;

// A triangle at the origin and a camera 5 in front of it (looking down −z) under node 1, whose x
// is keyed from 0 at 0 s to 1 at 2/24 s (frame 2 at 24 fps).
GltfFile camera_file(const nlohmann::json& camera) {
  GltfFile gltf;
  gltf.node({{"mesh", gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"))}});
  gltf.json["cameras"] = nlohmann::json::array({camera});
  gltf.node({{"children", {2}}});
  gltf.node({{"camera", 0}, {"translation", {0, 0, 5}}});
  gltf.scene({0, 1});
  const int times = gltf.floats({0.0f, 2.0f / 24.0f}, "SCALAR");
  const int values = gltf.floats({0, 0, 0, 1, 0, 0}, "VEC3");
  const nlohmann::json sampler = {{"input", times}, {"output", values}};
  const nlohmann::json channel = {{"sampler", 0}, {"target", {{"node", 1}, {"path", "translation"}}}};
  gltf.json["animations"] = nlohmann::json::array();
  gltf.json["animations"].push_back({{"samplers", {sampler}}, {"channels", {channel}}});
  return gltf;
}

const nlohmann::json kPerspective = {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}};

TEST(GltfCamera, AnOrthographicCameraKeepsItsProjection) {
  const nlohmann::json orthographic = {{"type", "orthographic"},
                                       {"orthographic", {{"xmag", 3.0}, {"ymag", 1.5}, {"znear", 0.1}, {"zfar", 100}}}};
  const SceneDescription scene = parse_scene_file(camera_file(orthographic).write("ortho"));
  EXPECT_EQ(scene.camera.projection, CameraProjection::kOrthographic);
  EXPECT_EQ(scene.camera.ortho_height, 3.0f);  // twice ymag
  EXPECT_EQ(scene.camera.width, 2 * scene.camera.height);
  // Frame 1 (the default) is 1/24 s: the parent halfway.
  EXPECT_EQ(scene.camera.position, Vec3(0.5f, 0.0f, 5.0f));
  const RenderCamera camera = make_render_camera(scene.camera);
  EXPECT_TRUE(camera.orthographic);
  EXPECT_EQ(camera.half_height, 1.5f);
}

TEST(GltfCamera, ACameraUnderAnAnimatedParentMovesDuringTheShutter) {
  const auto file = camera_file(kPerspective).write("dolly");
  EXPECT_TRUE(parse_scene_file(file).camera.frame_steps.empty());  // a closed shutter
  // Frame 1's shutter [-0.5, 0.5] spans 0.5/24 to 1.5/24 s: the parent's x from 0.25 to 0.75.
  const SceneDescription scene = parse_scene_file(file, {"camera.shutter=[-0.5, 0.5]"});
  ASSERT_EQ(scene.camera.frame_steps.size(), 2u);  // a straight line takes two
  const RenderCamera camera = make_render_camera(scene.camera);
  ASSERT_TRUE(camera.moving());
  for (const auto& [time, x] : {std::pair{0.0f, 0.25f}, std::pair{0.5f, 0.5f}, std::pair{1.0f, 0.75f}}) {
    const CameraPose pose = camera_pose_at(camera, time);
    EXPECT_NEAR(pose.position.x, x, 1e-6f) << time;
    EXPECT_EQ(pose.position.z, 5.0f);
    EXPECT_NEAR(pose.forward.z, -1.0f, 1e-6f);
    EXPECT_NEAR(pose.true_up.y, 1.0f, 1e-6f);
  }
}

}  // namespace gltf_camera_test
}  // namespace rtpro
