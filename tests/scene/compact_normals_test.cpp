// SceneBuildOptions::compact_normals: every mesh's static shading normals leave the render scene
// as 32-bit octahedral codes that decode to within 5e-5 radians of the floats they replace, in
// the top level and in prototypes alike; normals that move during the shutter stay floats.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <variant>

namespace rtpro {
namespace compact_normals_test {

std::vector<const TriangleMesh*> meshes_of(const RenderScene& scene) {
  std::vector<const TriangleMesh*> out;
  const auto collect = [&](const Group& group) {
    for (const Geometry& geometry : group.geometries)
      if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) out.push_back(mesh);
  };
  collect(scene.top);
  for (const Group& prototype : scene.prototypes) collect(prototype);
  return out;
}

TEST(CompactNormals, EveryMeshsNormalsBecomeCodesWithinTheirBound) {
  test::write_file("bumpy.obj", test::bumpy_grid_obj(12, 1.0, 0.7, 1.3, 0.9));
  const auto scene_file = test::write_file("scene.yaml", R"(rtpro: 1
camera: {position: [6, 6, 20], look_at: [6, 6, 0], fov: 40, resolution: [8, 8]}
objects:
  bump: [{type: mesh, file: bumpy.obj, normals: smooth}]
world:
  - {type: mesh, file: bumpy.obj, normals: smooth}
  - {type: instance, object: bump, transform: {translate: [20, 0, 0]}}
  - {type: instance, object: bump, transform: {translate: [40, 0, 0]}}
)");
  const SceneDescription description = parse_scene_file(scene_file);
  const RenderScene floats = build_render_scene(description);
  SceneBuildOptions options;
  options.compact_normals = true;
  const RenderScene packed = build_render_scene(description, nullptr, options);

  const std::vector<const TriangleMesh*> before = meshes_of(floats), after = meshes_of(packed);
  ASSERT_EQ(before.size(), after.size());
  ASSERT_GE(before.size(), 2u);  // one at the top, one in the instances' prototype
  double worst = 0.0;
  for (std::size_t m = 0; m < before.size(); ++m) {
    ASSERT_FALSE(before[m]->normals.empty());
    EXPECT_TRUE(before[m]->packed_normals.empty());
    EXPECT_TRUE(after[m]->normals.empty());
    ASSERT_EQ(after[m]->packed_normals.size(), before[m]->normals.size());
    EXPECT_TRUE(after[m]->smooth());
    EXPECT_LT(after[m]->memory_bytes(), before[m]->memory_bytes());
    for (std::uint32_t v = 0; v < before[m]->normals.size(); ++v) {
      const Vec3 a = before[m]->normals[v], b = after[m]->normal(v);
      worst = std::max(worst, std::atan2(double(length(cross(a, b))), double(dot(a, b))));
      EXPECT_EQ(after[m]->normal_at(v, 0.5f), b);
    }
  }
  EXPECT_LT(worst, 5e-5);
  EXPECT_GT(worst, 0.0);  // the codes are not the floats: the comparison above compared something
}

TEST(CompactNormals, NormalsThatMoveStayFloatsAndFlatMeshesStayFlat) {
  TriangleMesh moving;
  moving.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  moving.triangles = {{0, 1, 2}};
  moving.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  moving.vertex_steps = {moving.vertices, moving.vertices};
  moving.normal_steps = {moving.normals, {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}}};
  moving.pack_normals();
  EXPECT_EQ(moving.normals.size(), 3u);
  EXPECT_TRUE(moving.packed_normals.empty());

  TriangleMesh flat;
  flat.vertices = moving.vertices;
  flat.triangles = moving.triangles;
  flat.pack_normals();
  EXPECT_FALSE(flat.smooth());
}

}  // namespace compact_normals_test
}  // namespace rtpro
