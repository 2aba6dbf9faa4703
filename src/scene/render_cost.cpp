#include "rtpro/scene/render_cost.h"

#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <optional>
#include <set>
#include <vector>

namespace rtpro {

namespace {

bool has_own_shapes(const ObjectDesc& object) { return !object.spheres.empty() || !object.meshes.empty(); }

// Instances one placement of `object` becomes, memoised per object.
std::uint64_t instances_of(const SceneDescription& scene, std::uint32_t object,
                           std::vector<std::optional<std::uint64_t>>& memo) {
  if (memo[object]) return *memo[object];
  const ObjectDesc& desc = scene.objects[object];
  std::uint64_t count = has_own_shapes(desc) ? 1 : 0;
  for (const InstanceDesc& nested : desc.instances)
    count = saturating_add(count, instances_of(scene, nested.object, memo));
  memo[object] = count;
  return count;
}

void add_mesh_file_bytes(const std::vector<MeshDesc>& meshes, std::set<std::filesystem::path>& seen,
                         std::uint64_t& bytes) {
  for (const MeshDesc& mesh : meshes) {
    if (!seen.insert(mesh.file).second) continue;
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(mesh.file, error);
    if (!error) bytes = saturating_add(bytes, saturating_multiply(size, kMeshBytesPerFileByte));
  }
}

}  // namespace

std::vector<std::uint64_t> flattened_instances_per_object(const SceneDescription& scene) {
  std::vector<std::optional<std::uint64_t>> memo(scene.objects.size());
  std::vector<std::uint64_t> counts(scene.objects.size());
  for (std::uint32_t object = 0; object < scene.objects.size(); ++object) counts[object] = instances_of(scene, object, memo);
  return counts;
}

std::uint64_t count_flattened_instances(const SceneDescription& scene) {
  const std::vector<std::uint64_t> per_object = flattened_instances_per_object(scene);
  std::uint64_t count = 0;
  for (const InstanceDesc& instance : scene.world.instances) count = saturating_add(count, per_object[instance.object]);
  return count;
}

RenderCost estimate_render_cost(const SceneDescription& scene, int extra_channels) {
  RenderCost cost;
  cost.flattened_instances = count_flattened_instances(scene);
  cost.pixels = saturating_multiply(static_cast<std::uint64_t>(scene.camera.width),
                                    static_cast<std::uint64_t>(scene.camera.height));
  cost.channels = 3 + extra_channels;
  cost.samples = saturating_multiply(cost.pixels, static_cast<std::uint64_t>(scene.render.spp));
  // The film holds 32-bit floats per channel; writing it may take one more copy of that size.
  cost.image_bytes = saturating_multiply(saturating_multiply(cost.pixels, static_cast<std::uint64_t>(cost.channels)),
                                         2 * sizeof(float));
  cost.instance_bytes = saturating_multiply(cost.flattened_instances, kBytesPerInstance);
  std::set<std::filesystem::path> seen;
  add_mesh_file_bytes(scene.world.meshes, seen, cost.mesh_bytes);
  for (const ObjectDesc& object : scene.objects) add_mesh_file_bytes(object.meshes, seen, cost.mesh_bytes);
  cost.total_bytes = saturating_add(saturating_add(cost.image_bytes, cost.instance_bytes), cost.mesh_bytes);
  return cost;
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
  throw InputError(SourceLocation{scene_file.string()},
                   "the render would need an estimated " + format_bytes(cost.total_bytes) + " (" + parts +
                       "), more than the memory budget of " + format_bytes(budget_bytes) + " (" + budget_source +
                       "); lower the resolution or the instancing, or raise the budget with --max-memory MiB");
}

}  // namespace rtpro
