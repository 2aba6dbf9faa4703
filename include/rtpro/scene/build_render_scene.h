#pragma once
// Turns a scene description into the immutable render scene: loads meshes (each file once),
// merges their MTL materials, and flattens nested instances to the single level both backends
// support (Debian's Embree allows one instance level).
#include "rtpro/scene/description.h"
#include "rtpro/scene/mesh_loader.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rtpro {

struct SceneBuildReport {
  struct MeshFile {
    std::string file;
    MeshLoadStats stats;
    double load_seconds = 0.0;
  };
  std::vector<MeshFile> meshes;
  std::size_t flattened_instances = 0;
};

// Upper bound on instances after flattening; deeper or wider nesting is an input error.
inline constexpr std::size_t kMaxFlattenedInstances = 10'000'000;

// What building may use besides the description: the memory left in the budget for geometry made
// while building (subdivision surfaces; 0: the default budget), and how to read a displacement
// texture (the image layer, which the scene module does not link; unset: such a texture is an
// input error), and whether meshes keep their shading normals as 32-bit octahedral codes
// (TriangleMesh::pack_normals: 8 bytes a vertex less, each normal within 5e-5 radians), and
// whether top-level static meshes of more than `piece_triangles` triangles are reordered into
// compact pieces of that many (scene/mesh_pieces.h; 0: file order), which the Embree backend
// builds one BVH at a time.
struct SceneBuildOptions {
  bool compact_normals = false;
  std::uint32_t piece_triangles = 0;
  std::uint64_t geometry_budget = 0;
  // What the volumes' grids may take, read: what the estimate counted for them (from the files'
  // statistics) and what it left of the budget (0: the default budget).
  std::uint64_t volume_budget = 0;
  std::string budget_source = "the default budget";
  std::function<ScalarImage(const std::filesystem::path&, std::uint64_t max_bytes)> read_scalar_image = nullptr;
};

// Models the scene reader already loaded (MeshDesc::loaded, GltfDesc::loaded) are copied into
// the render scene: `description` keeps them and can be built again.
RenderScene build_render_scene(const SceneDescription& description, SceneBuildReport* report = nullptr,
                               const SceneBuildOptions& options = {});
// The same, but those models move into the render scene (each one that no other entry shares) and
// leave `description`: a mesh is never held twice, which for a mesh file of 100 million triangles
// is gigabytes. What the commands use.
RenderScene build_render_scene_taking_models(SceneDescription& description, SceneBuildReport* report = nullptr,
                                             const SceneBuildOptions& options = {});

// The render-time forms of the description's camera and lights (build_render_scene uses them;
// tests that assemble a RenderScene by hand do too).
RenderCamera make_render_camera(const CameraDesc& desc);
Light make_light(const LightDesc& desc);
// A world entry's light linking as flags over the scene's `light_count` lights.
LinkGroup make_link_group(const LightLinkingDesc& desc, std::size_t light_count);

}  // namespace rtpro
