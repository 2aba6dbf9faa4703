#include "rtpro/scene/render_cost.h"

#include "gltf_asset.h"
#include "gltf_loader.h"

#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/scene/grid_medium.h"
#include "rtpro/core/overloaded.h"
#include "rtpro/core/printable_text.h"

#include <algorithm>
#include <fstream>
#include <string_view>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace rtpro {

namespace {

// glTF files count by their placements (placements_in), not as the object's own shapes; every
// other list of shapes is the object's own.
bool has_own_shapes(const ObjectDesc& object) {
  bool any = false;
  visit_shape_lists(object, Overloaded{[](const std::vector<GltfDesc>&) {},
                                       [&](const auto& shapes) { any = any || !shapes.empty(); }});
  return any;
}

std::uint64_t placements_in(const std::vector<GltfDesc>& gltfs, const GltfPlacementCount& gltf_placements) {
  std::uint64_t count = 0;
  for (const GltfDesc& gltf : gltfs) count = saturating_add(count, gltf_placements(gltf));
  return count;
}

// Instances one placement of `object` becomes, memoised per object. An object that draws nothing
// still counts as one: flattening visits it, and ten levels of ten instances of an empty object
// are 10^10 visits that would otherwise pass the limit as 0 and hang the flattening.
std::uint64_t instances_of(const SceneDescription& scene, std::uint32_t object,
                           const GltfPlacementCount& gltf_placements, std::vector<std::optional<std::uint64_t>>& memo) {
  if (memo[object]) return *memo[object];
  const ObjectDesc& desc = scene.objects[object];
  std::uint64_t count = saturating_add(has_own_shapes(desc) ? 1 : 0, placements_in(desc.gltfs, gltf_placements));
  for (const InstanceDesc& nested : desc.instances)
    count = saturating_add(count, instances_of(scene, nested.object, gltf_placements, memo));
  count = std::max<std::uint64_t>(count, 1);
  memo[object] = count;
  return count;
}

// A binary PLY says so in its second line ("format binary_little_endian 1.0").
bool is_binary_ply(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char start[64] = {};
  in.read(start, sizeof start);
  const std::string_view head(start, static_cast<std::size_t>(in.gcount()));
  return head.starts_with("ply") && head.find("format binary") != std::string_view::npos;
}

void add_file_bytes(const std::filesystem::path& file, std::set<std::filesystem::path>& seen, std::uint64_t& bytes) {
  if (!seen.insert(file).second) return;
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return;
  const std::uint64_t per_byte = is_binary_ply(file) ? kMeshBytesPerBinaryFileByte : kMeshBytesPerFileByte;
  bytes = saturating_add(bytes, saturating_multiply(size, per_byte));
}

// A glTF file's buffers may live in .bin files beside it: a loaded asset counts its meshes' own
// bytes instead of the file's size.
void add_gltf_bytes(const std::vector<GltfDesc>& gltfs, std::set<std::filesystem::path>& seen, std::uint64_t& bytes) {
  for (const GltfDesc& gltf : gltfs) {
    if (!gltf.loaded) {
      add_file_bytes(gltf.file, seen, bytes);
      continue;
    }
    if (!seen.insert(gltf.file).second) continue;
    for (const TriangleMesh& mesh : gltf.loaded->meshes)
      bytes = saturating_add(bytes, saturating_multiply(mesh.memory_bytes(), 2));  // and its BVH
  }
}

// Mesh memory of every mesh and glTF file an object draws, each file counted once; a shape
// described in the scene file itself adds what its kind estimates (scene/sphere_geometry.h).
void add_shape_bytes(const ObjectDesc& object, std::set<std::filesystem::path>& seen, std::uint64_t& bytes) {
  visit_shape_lists(object, Overloaded{[&](const std::vector<MeshDesc>& meshes) {
                                         for (const MeshDesc& mesh : meshes) add_file_bytes(mesh.file, seen, bytes);
                                       },
                                       [&](const std::vector<GltfDesc>& gltfs) { add_gltf_bytes(gltfs, seen, bytes); },
                                       [&](const auto& shapes) {
                                         for (const auto& shape : shapes)
                                           bytes = saturating_add(bytes, estimated_bytes(shape));
                                       }});
}

}  // namespace

std::uint64_t described_gltf_placements(const GltfDesc& gltf) {
  return gltf.loaded ? gltf.loaded->placements.size() : count_gltf_mesh_nodes(gltf.file);
}

std::vector<std::uint64_t> flattened_instances_per_object(const SceneDescription& scene,
                                                          const GltfPlacementCount& gltf_placements) {
  std::vector<std::optional<std::uint64_t>> memo(scene.objects.size());
  std::vector<std::uint64_t> counts(scene.objects.size());
  for (std::uint32_t object = 0; object < scene.objects.size(); ++object)
    counts[object] = instances_of(scene, object, gltf_placements, memo);
  return counts;
}

std::uint64_t count_flattened_instances(const SceneDescription& scene, const GltfPlacementCount& gltf_placements) {
  const std::vector<std::uint64_t> per_object = flattened_instances_per_object(scene, gltf_placements);
  std::uint64_t count = placements_in(scene.world.gltfs, gltf_placements);
  for (const InstanceDesc& instance : scene.world.instances) count = saturating_add(count, per_object[instance.object]);
  return count;
}

RenderCost estimate_render_cost(const SceneDescription& scene, int extra_channels) {
  RenderCost cost;
  // Each glTF file's JSON read once, however many entries place it.
  std::map<std::filesystem::path, std::uint64_t> gltf_nodes;
  cost.flattened_instances = count_flattened_instances(scene, [&](const GltfDesc& gltf) {
    if (gltf.loaded) return std::uint64_t(gltf.loaded->placements.size());
    const auto [it, added] = gltf_nodes.try_emplace(gltf.file, 0);
    if (added) it->second = count_gltf_mesh_nodes(gltf.file);
    return it->second;
  });
  cost.pixels = saturating_multiply(static_cast<std::uint64_t>(scene.camera.width),
                                    static_cast<std::uint64_t>(scene.camera.height));
  cost.channels = 3 + extra_channels;
  cost.samples = saturating_multiply(cost.pixels, static_cast<std::uint64_t>(scene.render.spp));
  // The film holds 32-bit floats per channel; writing it may take one more copy of that size.
  cost.image_bytes = saturating_multiply(saturating_multiply(cost.pixels, static_cast<std::uint64_t>(cost.channels)),
                                         2 * sizeof(float));
  cost.instance_bytes = saturating_multiply(cost.flattened_instances, kBytesPerInstance);
  std::set<std::filesystem::path> seen;
  add_shape_bytes(scene.world, seen, cost.mesh_bytes);
  for (const ObjectDesc& object : scene.objects) add_shape_bytes(object, seen, cost.mesh_bytes);
  for (const VolumeDesc& volume : scene.volumes)
    cost.volume_bytes = saturating_add(cost.volume_bytes, estimate_grid_medium_bytes(volume));
  cost.total_bytes = saturating_add(saturating_add(cost.image_bytes, cost.instance_bytes), cost.mesh_bytes);
  cost.total_bytes = saturating_add(cost.total_bytes, cost.volume_bytes);
  return cost;
}

void add_environment_cost(RenderCost& cost, const std::filesystem::path& file, std::uint64_t width,
                          std::uint64_t height, std::uint64_t bytes) {
  cost.environment_file = file;
  cost.environment_width = width;
  cost.environment_height = height;
  cost.environment_bytes = bytes;
  cost.total_bytes = saturating_add(cost.total_bytes, bytes);
}

void check_render_cost(const RenderCost& cost, std::uint64_t budget_bytes, const std::string& budget_source,
                       const std::filesystem::path& scene_file) {
  if (cost.total_bytes <= budget_bytes) return;
  std::string parts = "image buffers " + format_bytes(cost.image_bytes) + " (" + std::to_string(cost.pixels) +
                      " pixels x " + std::to_string(cost.channels) + " channels)";
  if (cost.instance_bytes > 0)
    parts += ", instances " + format_bytes(cost.instance_bytes) + " (" + std::to_string(cost.flattened_instances) +
             " after flattening nested instances)";
  if (cost.mesh_bytes > 0) parts += ", meshes " + format_bytes(cost.mesh_bytes);
  if (cost.volume_bytes > 0) parts += ", volumes " + format_bytes(cost.volume_bytes);
  if (cost.environment_bytes > 0)
    parts += ", environment map " + format_bytes(cost.environment_bytes) + " (" +
             printable_text(cost.environment_file.string()) + ", " + std::to_string(cost.environment_width) + "x" +
             std::to_string(cost.environment_height) + " pixels)";
  throw InputError(
      SourceLocation{scene_file.string()},
      "the render would need an estimated " + format_bytes(cost.total_bytes) + " (" + parts +
          "), more than the memory budget of " + format_bytes(budget_bytes) + " (" + budget_source +
          "); lower the resolution, the instancing, the environment map's or the volumes' size, or raise the budget "
          "with --max-memory MiB");
}

}  // namespace rtpro
