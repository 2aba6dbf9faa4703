#include "gltf_morph.h"

#include "gltf_accessor.h"
#include "mesh_normals.h"

#include <tiny_gltf.h>

namespace rtpro::gltf {

std::size_t morph_target_count(const tinygltf::Model& model, int mesh, const AccessorReader& reader) {
  const tinygltf::Mesh& m = model.meshes[std::size_t(mesh)];
  const std::string path = "meshes[" + std::to_string(mesh) + "]";
  const std::size_t count = m.primitives.empty() ? 0 : m.primitives.front().targets.size();
  for (std::size_t p = 1; p < m.primitives.size(); ++p)
    if (m.primitives[p].targets.size() != count)
      reader.fail(path + ".primitives[" + std::to_string(p) + "].targets",
                  std::to_string(m.primitives[p].targets.size()) + " morph targets, but primitives[0] has " +
                      std::to_string(count) + "; every primitive of a mesh has the same number");
  if (!m.weights.empty() && m.weights.size() != count)
    reader.fail(path + ".weights",
                std::to_string(m.weights.size()) + " weights for " + std::to_string(count) + " morph targets");
  return count;
}

std::vector<MorphTarget> read_morph_targets(const tinygltf::Primitive& primitive, std::size_t vertex_count,
                                            const AccessorReader& reader, const std::string& path) {
  std::vector<MorphTarget> targets;
  for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
    const std::string target_path = path + ".targets[" + std::to_string(t) + "]";
    const auto sized = [&](std::vector<Vec3> values, const std::string& where) {
      if (values.size() != vertex_count)
        reader.fail(where,
                    std::to_string(values.size()) + " elements, but POSITION has " + std::to_string(vertex_count));
      return values;
    };
    MorphTarget target;
    const auto& attributes = primitive.targets[t];
    if (const auto p = attributes.find("POSITION"); p != attributes.end())
      target.positions = sized(reader.positions(p->second, target_path + ".POSITION"), target_path + ".POSITION");
    if (const auto n = attributes.find("NORMAL"); n != attributes.end())
      target.normals = sized(reader.normals(n->second, target_path + ".NORMAL"), target_path + ".NORMAL");
    targets.push_back(std::move(target));
  }
  return targets;
}

void apply_morph(const std::vector<MorphTarget>& targets, std::span<const double> weights, std::span<Vec3> positions,
                 std::span<Vec3> normals) {
  for (std::size_t t = 0; t < targets.size() && t < weights.size(); ++t) {
    const auto w = float(weights[t]);
    if (w == 0.0f) continue;
    if (!targets[t].positions.empty())
      for (std::size_t v = 0; v < positions.size(); ++v) positions[v] += w * targets[t].positions[v];
    if (!targets[t].normals.empty())
      for (std::size_t v = 0; v < normals.size(); ++v) normals[v] += w * targets[t].normals[v];
  }
  for (Vec3& n : normals) n = unit_or(n, Vec3(0, 0, 1));
}

}  // namespace rtpro::gltf
