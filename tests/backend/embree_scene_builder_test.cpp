// Which Embree scenes trace robustly: every group that holds triangles or spheres (itself or
// through an instance), as the options ask; a group of curves alone without, whatever the options.
#include "embree_scene_builder.h"

#include "rtpro/backend/backend.h"
#include "rtpro/scene/render_scene.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtpro {
namespace {

CurveSet some_curves() {
  CurveSet curves;
  curves.points = {{{0, 0, 0}, 0.1f}, {{1, 0, 0}, 0.1f}};
  curves.segments = {0};
  curves.basis = CurveBasis::kLinear;
  return curves;
}

TriangleMesh a_triangle() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

Group group_of(std::vector<Geometry> geometries) {
  Group group;
  group.geometries = std::move(geometries);
  return group;
}

bool robust(RTCSceneFlags flags) { return (flags & RTC_SCENE_FLAG_ROBUST) != 0; }

TEST(EmbreeGroupFlags, CurvesAloneGoWithoutRobustTraversal) {
  const EmbreeBuildSettings settings = embree_build_settings(BackendOptions{});
  ASSERT_TRUE(robust(settings.flags));
  EXPECT_FALSE(robust(embree_group_flags(group_of({some_curves(), some_curves()}), {}, settings)));
}

TEST(EmbreeGroupFlags, TrianglesOrSpheresBesideCurvesKeepIt) {
  const EmbreeBuildSettings settings = embree_build_settings(BackendOptions{});
  EXPECT_TRUE(robust(embree_group_flags(group_of({some_curves(), a_triangle()}), {}, settings)));
  EXPECT_TRUE(robust(embree_group_flags(group_of({SphereSet{{{{0, 0, 0}, 1.0f, 0}}}, some_curves()}), {}, settings)));
  EXPECT_TRUE(robust(embree_group_flags(group_of({}), {}, settings)));
}

TEST(EmbreeGroupFlags, InstancesCountWhatTheirPrototypesHold) {
  const EmbreeBuildSettings settings = embree_build_settings(BackendOptions{});
  const std::vector<Group> prototypes = {group_of({some_curves()}), group_of({a_triangle()})};
  Instance of_curves{0, Affine::identity(), Affine::identity()};
  Instance of_triangles{1, Affine::identity(), Affine::identity()};
  EXPECT_FALSE(robust(embree_group_flags(group_of({of_curves, some_curves()}), prototypes, settings)));
  EXPECT_TRUE(robust(embree_group_flags(group_of({of_curves, of_triangles}), prototypes, settings)));
}

TEST(EmbreeGroupFlags, OtherFlagsAndTheOptionsStand) {
  BackendOptions options;
  options.embree_compact = true;
  const EmbreeBuildSettings compact = embree_build_settings(options);
  const RTCSceneFlags curves = embree_group_flags(group_of({some_curves()}), {}, compact);
  EXPECT_TRUE((curves & RTC_SCENE_FLAG_COMPACT) != 0);
  EXPECT_FALSE(robust(curves));
  options.embree_robust = false;
  const RTCSceneFlags triangles = embree_group_flags(group_of({a_triangle()}), {}, embree_build_settings(options));
  EXPECT_FALSE(robust(triangles));
  // Coherent occlusion streams set a context filter (embree_ray_batches.cpp): every scene allows it.
  for (const RTCSceneFlags flags : {curves, triangles})
    EXPECT_TRUE((flags & RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION) != 0);
}

}  // namespace
}  // namespace rtpro
