#include "gltf_skin.h"

#include "gltf_accessor.h"
#include "mesh_normals.h"

#include <tiny_gltf.h>

#include <cmath>
#include <optional>

namespace rtpro::gltf {

namespace {

// The specification's bound on the magnitude of inverse bind matrices' entries is none; the
// scene format's (yaml_reader.h) keeps transforms finite and composable.
constexpr float kMaxBindEntry = 1e9f;
constexpr float kMaxBindTranslation = 1e16f;

Affine bind_matrix(const float* c, const AccessorReader& reader, const std::string& path, std::size_t joint) {
  // Column-major: element (row r, column k) is c[4k + r].
  if (c[3] != 0.0f || c[7] != 0.0f || c[11] != 0.0f || c[15] != 1.0f)
    reader.fail(path, "matrix " + std::to_string(joint) + " is not affine: its last row must be 0 0 0 1");
  Affine a;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 4; ++k) {
      const float v = c[4 * k + r];
      if (!(std::fabs(v) <= (k == 3 ? kMaxBindTranslation : kMaxBindEntry)))
        reader.fail(path, "matrix " + std::to_string(joint) + " has an entry beyond 1e9 (1e16 for the translation)");
      a.m[std::size_t(r)][std::size_t(k)] = v;
    }
  return a;
}

}  // namespace

std::vector<Skin> read_skins(const tinygltf::Model& model, const AccessorReader& reader) {
  std::vector<Skin> skins;
  for (std::size_t s = 0; s < model.skins.size(); ++s) {
    const tinygltf::Skin& skin = model.skins[s];
    const std::string path = "skins[" + std::to_string(s) + "]";
    Skin out;
    if (skin.joints.empty()) reader.fail(path + ".joints", "a skin needs at least one joint");
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
      const int node = skin.joints[j];
      if (node < 0 || std::size_t(node) >= model.nodes.size())
        reader.fail(path + ".joints[" + std::to_string(j) + "]", "node " + std::to_string(node) + " does not exist");
      out.joints.push_back(std::uint32_t(node));
    }
    if (skin.skeleton >= 0 && std::size_t(skin.skeleton) >= model.nodes.size())
      reader.fail(path + ".skeleton", "node " + std::to_string(skin.skeleton) + " does not exist");
    out.inverse_bind.assign(out.joints.size(), Affine::identity());
    if (skin.inverseBindMatrices >= 0) {
      const std::string where = path + ".inverseBindMatrices";
      const std::vector<float> m = reader.values(skin.inverseBindMatrices, where, TINYGLTF_TYPE_MAT4, false);
      if (m.size() != 16 * out.joints.size())
        reader.fail(where,
                    std::to_string(m.size() / 16) + " matrices for " + std::to_string(out.joints.size()) + " joints");
      for (std::size_t j = 0; j < out.joints.size(); ++j)
        out.inverse_bind[j] = bind_matrix(&m[16 * j], reader, where, j);
    }
    skins.push_back(std::move(out));
  }
  return skins;
}

SkinWeights read_skin_weights(const tinygltf::Primitive& primitive, std::size_t vertex_count,
                              const AccessorReader& reader, const std::string& path) {
  SkinWeights out;
  const auto has = [&](const std::string& name) { return primitive.attributes.count(name) != 0; };
  if (has("JOINTS_2") || has("WEIGHTS_2"))
    reader.fail(path + ".attributes", "has a third set of joints or weights; at most " +
                                          std::to_string(kSkinInfluences) + " influences per vertex are read");
  for (std::size_t set = 0; set < kSkinInfluences / 4; ++set) {
    const std::string joints = "JOINTS_" + std::to_string(set), weights = "WEIGHTS_" + std::to_string(set);
    if (!has(joints) && !has(weights)) break;
    if (!has(joints) || !has(weights))
      reader.fail(path + ".attributes", "has one of " + joints + " and " + weights + " without the other");
    const std::string where = path + ".attributes." + joints;
    const auto indices = reader.joints(primitive.attributes.at(joints), where);
    const std::vector<float> w =
        reader.values(primitive.attributes.at(weights), path + ".attributes." + weights, TINYGLTF_TYPE_VEC4, true);
    if (indices.size() != vertex_count || w.size() != 4 * vertex_count)
      reader.fail(where,
                  joints + " and " + weights + " need one element per vertex (" + std::to_string(vertex_count) + ")");
    out.joints.resize(vertex_count);
    out.weights.resize(vertex_count);
    for (std::size_t v = 0; v < vertex_count; ++v)
      for (std::size_t k = 0; k < 4; ++k) {
        if (!(w[4 * v + k] >= 0.0f))
          reader.fail(path + ".attributes." + weights, "element " + std::to_string(v) + " has a negative weight");
        out.joints[v][4 * set + k] = indices[v][k];
        out.weights[v][4 * set + k] = w[4 * v + k];
      }
  }
  if (out.joints.empty() && (has("JOINTS_1") || has("WEIGHTS_1")))
    reader.fail(path + ".attributes", "has JOINTS_1 or WEIGHTS_1 without JOINTS_0 and WEIGHTS_0");
  return out;
}

std::vector<Affine> joint_matrices(const Skin& skin, const std::vector<Affine>& world) {
  std::vector<Affine> out;
  out.reserve(skin.joints.size());
  for (std::size_t j = 0; j < skin.joints.size(); ++j)
    out.push_back(compose(world[skin.joints[j]], skin.inverse_bind[j]));
  return out;
}

void apply_skin(const std::vector<Affine>& joints, const SkinWeights& skin, std::span<Vec3> positions,
                std::span<Vec3> normals) {
  // Normals turn with the inverse transpose; a singular joint (scale 0) turns them with its
  // linear part instead, which the renormalisation makes harmless.
  std::vector<std::optional<Affine>> inverses;
  if (!normals.empty())
    for (const Affine& j : joints) inverses.push_back(inverse(j));
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const auto& index = skin.joints[v];
    const auto& weight = skin.weights[v];
    float sum = 0.0f;
    for (const float w : weight) sum += w;
    if (!(sum > 0.0f)) continue;
    Vec3 p(0.0f), n(0.0f);
    for (std::size_t k = 0; k < kSkinInfluences; ++k) {
      if (weight[k] == 0.0f) continue;
      const float w = weight[k] / sum;
      const Affine& j = joints[index[k]];
      p += w * j.apply_point(positions[v]);
      if (!normals.empty())
        n += w * (inverses[index[k]] ? inverses[index[k]]->apply_normal_of_inverse(normals[v])
                                     : j.apply_vector(normals[v]));
    }
    positions[v] = p;
    if (!normals.empty()) normals[v] = unit_or(n, normals[v]);
  }
}

}  // namespace rtpro::gltf
