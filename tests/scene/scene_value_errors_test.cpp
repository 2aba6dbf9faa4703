// Scene values the parser refuses for their range: radii, cameras, lenses, checkers, render
// settings and transforms.
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::test {
namespace scene_value_errors_test {

TEST(SceneParser, RejectsNonPositiveRadius) {
  for (const std::string radius : {"0", "-1"}) {
    const std::string text = with_world("  - {type: sphere, radius: " + radius + "}\n");
    EXPECT_SCENE_ERROR(text, at(text, 4, radius + "}"), {"sphere.radius must be > 0"});
  }
}

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

TEST(SceneParser, RejectsMaxDepthOutsideZeroTo1024) {
  for (const std::string depth : {"-1", "1025"}) {
    const std::string text = kHeader + "render: {max_depth: " + depth + "}\n";
    EXPECT_SCENE_ERROR(text, at(text, 3, depth), {"render.max_depth", "from 0 to 1024"});
  }
  EXPECT_EQ(parse_scene_text(kHeader + "render: {max_depth: 0}\n", "t.yaml").render.max_depth, 0);
  EXPECT_EQ(parse_scene_text(kHeader + "render: {max_depth: 1024}\n", "t.yaml").render.max_depth, 1024);
}

TEST(SceneParser, ReadsThePathControlsAndRejectsBadOnes) {
  const RenderSettings unset = parse_scene_text(kHeader + "render: {max_depth: 7}\n", "t.yaml").render;
  EXPECT_FALSE(unset.path.max_diffuse_depth || unset.path.max_glossy_depth || unset.path.max_transmission_depth);
  EXPECT_EQ(lobe_depths(unset).diffuse, 7);
  EXPECT_EQ(unset.path.clamp_direct, 0.0f);
  EXPECT_EQ(unset.path.filter_glossy, 0.0f);
  const RenderSettings set =
      parse_scene_text(kHeader +
                           "render: {max_depth: 300, max_diffuse_depth: 4, max_glossy_depth: 1, "
                           "max_transmission_depth: 1024, clamp_direct: 2.5, clamp_indirect: 10, filter_glossy: 1}\n",
                       "t.yaml")
          .render;
  EXPECT_EQ(lobe_depths(set).diffuse, 4);
  EXPECT_EQ(lobe_depths(set).glossy, 1);
  EXPECT_EQ(lobe_depths(set).transmission, 1024);
  EXPECT_EQ(set.path.clamp_direct, 2.5f);
  EXPECT_EQ(set.path.clamp_indirect, 10.0f);
  EXPECT_EQ(set.path.filter_glossy, 1.0f);
  for (const std::string key : {"max_diffuse_depth", "max_glossy_depth", "max_transmission_depth"})
    for (const std::string depth : {"0", "1025"}) {
      const std::string text = kHeader + "render: {" + key + ": " + depth + "}\n";
      EXPECT_SCENE_ERROR(text, at(text, 3, depth + "}"), {"render." + key, "from 1 to 1024"});
    }
  for (const std::string key : {"clamp_direct", "clamp_indirect", "filter_glossy"})
    for (const std::string value : {"-1", ".inf", ".nan", "bright"}) {
      const std::string text = kHeader + "render: {" + key + ": " + value + "}\n";
      EXPECT_SCENE_ERROR(text, at(text, 3, value), {"render." + key});
    }
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

}  // namespace scene_value_errors_test
}  // namespace rtpro::test
