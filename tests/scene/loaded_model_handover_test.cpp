// A model the scene reader already loaded (a mesh or glTF file read as the whole scene) moves into
// the render scene instead of being copied, so the path from file to BVH never holds a mesh twice
// (build_render_scene_taking_models); the const build copies and leaves the description whole.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "gltf_asset.h"
#include "gltf_test_files.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <variant>

namespace rtpro {
namespace {

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

const TriangleMesh& top_mesh(const RenderScene& scene) {
  for (const Geometry& geometry : scene.top.geometries)
    if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) return *mesh;
  throw std::logic_error("no mesh at the top level");
}

TEST(LoadedModelHandover, AMeshFileSceneMovesItsMeshIntoTheRenderScene) {
  SceneDescription description = parse_scene_file(test::write_file("tri.obj", kTriangle));
  ASSERT_EQ(description.world.meshes.size(), 1u);
  ASSERT_TRUE(description.world.meshes[0].loaded);
  const MeshVertex* stored = description.world.meshes[0].loaded->mesh.vertices.data();
  const TriangleIndices* indices = description.world.meshes[0].loaded->mesh.triangles.data();

  const RenderScene scene = build_render_scene_taking_models(description);
  EXPECT_EQ(top_mesh(scene).vertices.data(), stored);
  EXPECT_EQ(top_mesh(scene).triangles.data(), indices);
  EXPECT_FALSE(description.world.meshes[0].loaded);
}

TEST(LoadedModelHandover, TheConstBuildCopiesAndCanBuildAgain) {
  const SceneDescription description = parse_scene_file(test::write_file("tri.obj", kTriangle));
  const MeshVertex* stored = description.world.meshes[0].loaded->mesh.vertices.data();
  const RenderScene first = build_render_scene(description);
  const RenderScene second = build_render_scene(description);
  EXPECT_NE(top_mesh(first).vertices.data(), stored);
  ASSERT_TRUE(description.world.meshes[0].loaded);
  EXPECT_EQ(description.world.meshes[0].loaded->mesh.vertices.data(), stored);
  EXPECT_EQ(top_mesh(second).triangle_count(), 1u);
}

TEST(LoadedModelHandover, AGltfSceneMovesItsMeshesIntoThePrototypes) {
  test::GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"));
  gltf.scene({gltf.node({{"mesh", mesh}}), gltf.node({{"mesh", mesh}, {"translation", {2, 0, 0}}})});
  SceneDescription description = parse_scene_file(gltf.write("model"));
  ASSERT_EQ(description.world.gltfs.size(), 1u);
  ASSERT_TRUE(description.world.gltfs[0].loaded);
  const MeshVertex* stored = description.world.gltfs[0].loaded->meshes[0].vertices.data();

  const RenderScene scene = build_render_scene_taking_models(description);
  ASSERT_EQ(scene.prototypes.size(), 1u);
  EXPECT_EQ(std::get<TriangleMesh>(scene.prototypes[0].geometries[0]).vertices.data(), stored);
  EXPECT_EQ(scene.top.geometries.size(), 2u);  // both placements kept
  EXPECT_FALSE(description.world.gltfs[0].loaded);
}

}  // namespace
}  // namespace rtpro
