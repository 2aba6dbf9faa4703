#pragma once
// glTF morph targets: per-vertex POSITION and NORMAL offsets that a mesh's weights (the mesh's
// `weights`, a node's, or an animation's) blend into the base shape: p = p0 + Σ w_i Δp_i, and
// likewise the normal, renormalised. Every primitive of a mesh has the same number of targets
// (the specification's rule, checked); a target without POSITION or NORMAL offsets nothing there.
#include "rtpro/core/vec3.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace rtpro::gltf {

class AccessorReader;

struct MorphTarget {
  std::vector<Vec3> positions;  // per vertex; empty: the target moves no vertex
  std::vector<Vec3> normals;    // per vertex; empty: the target turns no normal
};

// The number of targets of meshes[mesh], the same for all its primitives (an error otherwise);
// the mesh's `weights`, when given, must have as many.
std::size_t morph_target_count(const tinygltf::Model& model, int mesh, const AccessorReader& reader);

// The targets of one primitive of `vertex_count` vertices; `path` names it.
std::vector<MorphTarget> read_morph_targets(const tinygltf::Primitive& primitive, std::size_t vertex_count,
                                            const AccessorReader& reader, const std::string& path);

// Adds Σ weights[i] · targets[i] to positions (and normals, when given, then renormalised).
void apply_morph(const std::vector<MorphTarget>& targets, std::span<const double> weights, std::span<Vec3> positions,
                 std::span<Vec3> normals);

}  // namespace rtpro::gltf
