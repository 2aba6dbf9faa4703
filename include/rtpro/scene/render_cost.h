#pragma once
// What a render will cost, estimated from the scene description before anything large is
// allocated: instances multiplied out through nesting (without flattening them), image buffers
// from resolution × channels, mesh memory from the mesh files' sizes, and the environment's image
// from its header, volumes from their grids' metadata. `rtpro render` and
// `rtpro info` check it against the memory budget (--max-memory, else
// default_memory_budget()), so a kilobyte of YAML asking for gigabytes is refused in milliseconds.
#include "rtpro/scene/description.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rtpro {

struct RenderCost {
  std::uint64_t flattened_instances = 0;  // instances after flattening nested ones (saturating)
  std::uint64_t pixels = 0;
  int channels = 3;                                             // colour plus AOV channels
  std::uint64_t samples = 0;                                    // camera samples: pixels × spp
  std::uint64_t image_bytes = 0;                                // film plus one output copy
  std::uint64_t instance_bytes = 0;                             // rtpro's and Embree's per-instance records
  std::uint64_t mesh_bytes = 0;                                 // loaded meshes and their BVHs, from the file sizes
  std::filesystem::path environment_file;                       // the environment's image, if any
  std::uint64_t environment_width = 0, environment_height = 0;  // as its header declares them
  std::uint64_t environment_bytes = 0;  // that image read and made a light (see add_environment_cost)
  std::uint64_t volume_bytes = 0;       // the volume entries' grids, from the files' grid metadata
  std::uint64_t total_bytes = 0;        // the sum, saturating
};

// Rough bytes per flattened instance (two 3×4 transforms and the geometry record in rtpro, an
// instance geometry and BVH leaf in Embree) and per byte of mesh file: positions, normals and
// indices with the BVH build at its peak (the BVH and the builder's scratch arrays), relative to
// the file's size. A binary PLY spends about 19 bytes a triangle where text spends 35-40, for the
// same ~140 bytes at the peak (benchmarks/scale_benchmark.sh, the dragon: docs/performance.md,
// "Memory"). Deliberately on the high side.
inline constexpr std::uint64_t kBytesPerInstance = 1024;
inline constexpr std::uint64_t kMeshBytesPerFileByte = 4;
inline constexpr std::uint64_t kMeshBytesPerBinaryFileByte = 8;

// How many placements (nodes drawing a mesh) a glTF entry becomes.
using GltfPlacementCount = std::function<std::uint64_t(const GltfDesc&)>;

// The count known from the description alone: exact for a file the scene reader loaded (a glTF
// file as the whole scene); for an entry that build_render_scene loads later (which then counts
// again with the exact figure before flattening), the nodes of its JSON that draw a mesh.
std::uint64_t described_gltf_placements(const GltfDesc& gltf);

// Instances after flattening: the world's glTF placements and, for every world instance, its
// object's own spheres and meshes (one instance, if any) and glTF placements plus, recursively,
// the objects it instances. Computed once per object, so it takes microseconds even when the
// answer is 10^30 (it saturates at UINT64_MAX). The objects must form no cycle (the scene parser
// guarantees it).
std::uint64_t count_flattened_instances(const SceneDescription& scene,
                                        const GltfPlacementCount& gltf_placements = described_gltf_placements);
// The same per object: element i is what one placement of scene.objects[i] becomes.
std::vector<std::uint64_t> flattened_instances_per_object(
    const SceneDescription& scene, const GltfPlacementCount& gltf_placements = described_gltf_placements);

// `extra_channels`: AOV channels beyond R, G, B.
RenderCost estimate_render_cost(const SceneDescription& scene, int extra_channels = 0);

// Counts the environment's image `file`: its size as its header declares it, and `bytes`, what
// reading it and building the light from it hold at their peak. The image layer and the light know
// those, so the caller (the command that reads the scene) adds them to estimate_render_cost's.
void add_environment_cost(RenderCost& cost, const std::filesystem::path& file, std::uint64_t width,
                          std::uint64_t height, std::uint64_t bytes);

// Throws InputError at the scene file when the estimate exceeds `budget_bytes`, naming the
// largest parts and --max-memory. `budget_source` says where the budget came from, e.g.
// "--max-memory 512" or "the default: the smaller of 4 GiB and the available memory".
void check_render_cost(const RenderCost& cost, std::uint64_t budget_bytes, const std::string& budget_source,
                       const std::filesystem::path& scene_file);

}  // namespace rtpro
