#include "gltf_mesh.h"

#include "rtpro/core/error.h"
#include "rtpro/core/large_buffer.h"
#include "mesh_limits.h"
#include "mesh_normals.h"

#include <algorithm>

namespace rtpro::gltf {

namespace {

const char* mode_name(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    default: return "unknown";
  }
}

// The triangles of a primitive as vertex indices, in the primitive's winding.
std::vector<TriangleIndices> triangles_of(int mode, const std::vector<std::uint32_t>& corners) {
  std::vector<TriangleIndices> triangles;
  const std::size_t n = corners.size();
  reserve_large(triangles, mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : n);
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < n; i += 3) triangles.push_back({corners[i], corners[i + 1], corners[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    // Every other triangle of a strip is flipped back to the strip's winding.
    for (std::size_t i = 0; i + 2 < n; ++i)
      triangles.push_back(i % 2 == 0 ? TriangleIndices{corners[i], corners[i + 1], corners[i + 2]}
                                     : TriangleIndices{corners[i + 1], corners[i], corners[i + 2]});
  } else {  // TRIANGLE_FAN
    for (std::size_t i = 1; i + 1 < n; ++i) triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  return triangles;
}

// A primitive's data before it joins the mesh.
struct Primitive {
  std::vector<Vec3> positions, normals;
  std::vector<TexCoord> uvs;
  std::vector<Color> colors;
  std::vector<TriangleIndices> triangles;
  std::uint32_t material;
  std::vector<MorphTarget> targets;
  SkinWeights skin;
};

class MeshBuilder {
 public:
  MeshBuilder(const tinygltf::Model& model, int mesh, const AccessorReader& reader, const MeshLoadOptions& options,
              const std::vector<UvMapping>& uv_mappings, MeshLoadStats& stats, MeshDeformation& deformation)
      : model_(model), mesh_index_(mesh), reader_(reader), options_(options), uv_mappings_(uv_mappings), stats_(stats),
        deformation_(deformation) {}

  TriangleMesh build() {
    const tinygltf::Mesh& mesh = model_.meshes[std::size_t(mesh_index_)];
    const std::string path = "meshes[" + std::to_string(mesh_index_) + "]";
    target_count_ = morph_target_count(model_, mesh_index_, reader_);
    deformation_.default_weights.assign(target_count_, 0.0);
    for (std::size_t t = 0; t < mesh.weights.size(); ++t) deformation_.default_weights[t] = mesh.weights[t];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
      read_primitive(mesh.primitives[p], path + ".primitives[" + std::to_string(p) + "]");
    out_.name = mesh.name.empty() ? path : mesh.name;
    finish();
    return std::move(out_);
  }

 private:
  void read_primitive(const tinygltf::Primitive& prim, const std::string& path) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      stats_.warnings.push_back(file() + ": " + path + ".mode: " + std::to_string(mode) + " (" + mode_name(mode) +
                                ") skipped: rtpro renders triangles (modes 4, 5 and 6)");
      return;
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      stats_.warnings.push_back(file() + ": " + path + " has no POSITION; skipped");
      return;
    }
    if (prim.material >= 0 && std::size_t(prim.material) >= model_.materials.size())
      reader_.fail(path + ".material", "material " + std::to_string(prim.material) + " does not exist");
    Primitive p;
    p.material = prim.material < 0 ? kNoMaterial : std::uint32_t(prim.material);
    p.positions = reader_.positions(position->second, path + ".attributes.POSITION");
    const auto vertex_count = std::uint32_t(p.positions.size());
    std::vector<std::uint32_t> corners;
    if (prim.indices >= 0) {
      corners = reader_.indices(prim.indices, vertex_count, path + ".indices");
    } else {
      corners.resize(vertex_count);
      for (std::uint32_t i = 0; i < vertex_count; ++i) corners[i] = i;
    }
    check_corner_count(mode, corners.size(), prim.indices >= 0 ? path + ".indices" : path + ".attributes.POSITION");
    p.triangles = triangles_of(mode, corners);
    corners = {};
    const auto degenerate = [](const TriangleIndices& t) { return t.v0 == t.v1 || t.v1 == t.v2 || t.v0 == t.v2; };
    const auto kept_end = std::remove_if(p.triangles.begin(), p.triangles.end(), degenerate);
    stats_.dropped_degenerate += std::size_t(p.triangles.end() - kept_end);
    p.triangles.erase(kept_end, p.triangles.end());
    stats_.faces += p.triangles.size();
    if (const auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end()) {
      p.normals = read_sized(reader_.normals(n->second, path + ".attributes.NORMAL"), vertex_count,
                             path + ".attributes.NORMAL");
      const auto position = [&](std::uint32_t v) { return p.positions[v]; };
      if (const std::size_t repaired = repair_vertex_normals(position, p.triangles, p.normals))
        stats_.warnings.push_back(repaired_normals_warning(file() + ": " + path + ".attributes.NORMAL", repaired));
    }
    const UvMapping mapping = prim.material >= 0 ? uv_mappings_[std::size_t(prim.material)] : UvMapping{};
    const std::string uv_name = "TEXCOORD_" + std::to_string(mapping.set);
    if (const auto uv = prim.attributes.find(uv_name); uv != prim.attributes.end()) {
      p.uvs = read_sized(reader_.texcoords(uv->second, path + ".attributes." + uv_name), vertex_count,
                         path + ".attributes." + uv_name);
      apply_uv_mapping(mapping, p.uvs);
    } else if (mapping.textured) {
      stats_.warnings.push_back(file() + ": " + path + ": its material's textures read " + uv_name +
                                ", which the primitive lacks; its " + std::to_string(vertex_count) +
                                " vertices show the textures' corner (0, 0)");
    }
    if (const auto c = prim.attributes.find("COLOR_0"); c != prim.attributes.end())
      p.colors = read_sized(reader_.colors(c->second, path + ".attributes.COLOR_0"), vertex_count,
                            path + ".attributes.COLOR_0");
    p.targets = read_morph_targets(prim, vertex_count, reader_, path);
    p.skin = read_skin_weights(prim, vertex_count, reader_, path);
    for (const auto& joints : p.skin.joints)
      for (std::size_t k = 0; k < kSkinInfluences; ++k)
        if (joints[k] > deformation_.max_joint || deformation_.max_joint_path.empty()) {
          deformation_.max_joint = std::max<std::uint32_t>(deformation_.max_joint, joints[k]);
          deformation_.max_joint_path = path + ".attributes.JOINTS_" + std::to_string(k / 4);
        }
    primitives_.push_back(std::move(p));
  }

  // The glTF specification's counts: a multiple of 3 for TRIANGLES, at least 3 for strips and fans.
  void check_corner_count(int mode, std::size_t count, const std::string& path) const {
    if (mode == TINYGLTF_MODE_TRIANGLES && count % 3 != 0)
      reader_.fail(path,
                   std::to_string(count) + " corners for TRIANGLES, not a multiple of 3 (a truncated or wrong array)");
    if (mode != TINYGLTF_MODE_TRIANGLES && count > 0 && count < 3)
      reader_.fail(path, std::to_string(count) + " corners for a strip or fan, which needs at least 3");
  }

  template <typename T>
  std::vector<T> read_sized(std::vector<T> values, std::uint32_t vertex_count, const std::string& path) const {
    if (values.size() != vertex_count)
      reader_.fail(path, std::to_string(values.size()) + " elements, but POSITION has " + std::to_string(vertex_count));
    return values;
  }

  // Joins the primitives: per-vertex arrays concatenated, and flat primitives split into
  // vertices of their own when the mesh needs normals for its other primitives.
  void finish() {
    const bool file_normals = options_.normals == NormalsMode::kAuto || options_.normals == NormalsMode::kFile;
    const bool any_normals = file_normals && std::any_of(primitives_.begin(), primitives_.end(),
                                                         [](const Primitive& p) { return !p.normals.empty(); });
    if (options_.normals == NormalsMode::kFile &&
        std::any_of(primitives_.begin(), primitives_.end(), [](const Primitive& p) { return p.normals.empty(); }))
      throw InputError(SourceLocation{file()}, "normals: file, but meshes[" + std::to_string(mesh_index_) +
                                                   "] has primitives without usable NORMAL");
    const bool any_uvs =
        std::any_of(primitives_.begin(), primitives_.end(), [](const Primitive& p) { return !p.uvs.empty(); });
    const bool any_colors =
        std::any_of(primitives_.begin(), primitives_.end(), [](const Primitive& p) { return !p.colors.empty(); });
    std::size_t vertices = 0, triangles = 0;
    for (const Primitive& p : primitives_) {
      vertices += any_normals && p.normals.empty() ? 3 * p.triangles.size() : p.positions.size();
      triangles += p.triangles.size();
    }
    if (vertices > kMaxMeshElements || triangles > kMaxMeshElements)
      throw InputError(SourceLocation{file()},
                       "meshes[" + std::to_string(mesh_index_) + "] has more than 2^32 - 2 vertices or triangles");
    reserve_large(out_.vertices, vertices);
    reserve_large(out_.triangles, triangles);
    if (any_normals) reserve_large(out_.normals, vertices);
    deformation_.targets.resize(target_count_);
    target_positions_.assign(target_count_, false);
    target_normals_.assign(target_count_, false);
    for (const Primitive& p : primitives_)
      for (std::size_t t = 0; t < p.targets.size(); ++t) {
        target_positions_[t] = target_positions_[t] || !p.targets[t].positions.empty();
        target_normals_[t] = target_normals_[t] || (any_normals && !p.targets[t].normals.empty());
      }
    deformation_.smooth_normals = options_.normals == NormalsMode::kSmooth;
    any_skin_ =
        std::any_of(primitives_.begin(), primitives_.end(), [](const Primitive& p) { return !p.skin.joints.empty(); });
    for (Primitive& p : primitives_) {
      if (any_normals && p.normals.empty()) append_flat(p, any_uvs, any_colors);
      else append_shared(p, any_normals, any_uvs, any_colors);
      triangle_materials_.insert(triangle_materials_.end(), p.triangles.size(), p.material);
      p = Primitive{};
    }
    if (options_.normals == NormalsMode::kSmooth) {
      out_.normals = area_weighted_vertex_normals(out_.vertices, out_.triangles);
      stats_.normals_generated = true;
    }
    const bool one_material = std::all_of(triangle_materials_.begin(), triangle_materials_.end(),
                                          [&](std::uint32_t m) { return m == triangle_materials_.front(); });
    out_.material = triangle_materials_.empty() ? kNoMaterial : triangle_materials_.front();
    if (!one_material) out_.triangle_materials = std::move(triangle_materials_);
  }

  void append_shared(const Primitive& p, bool normals, bool uvs, bool colors) {
    const auto base = std::uint32_t(out_.vertices.size());
    for (const Vec3& v : p.positions) out_.vertices.push_back({v.x, v.y, v.z});
    if (normals)
      for (const Vec3& n : p.normals) out_.normals.push_back(unit_or(n, Vec3(0, 0, 1)));
    if (uvs) append_or_fill(out_.uvs, p.uvs, p.positions.size(), TexCoord{0.0f, 0.0f});
    if (colors) append_or_fill(out_.colors, p.colors, p.positions.size(), Color(1.0f, 1.0f, 1.0f));
    for (const TriangleIndices& t : p.triangles) out_.triangles.push_back({base + t.v0, base + t.v1, base + t.v2});
    for (std::uint32_t v = 0; v < p.positions.size(); ++v) append_deformation(p, v, normals);
  }

  // Vertex v of primitive p's morph offsets and skin weights, after the merged mesh's last ones:
  // zeros where the primitive lacks what another primitive of the mesh has.
  void append_deformation(const Primitive& p, std::uint32_t v, bool normals) {
    for (std::size_t t = 0; t < target_count_; ++t) {
      MorphTarget& target = deformation_.targets[t];
      const MorphTarget* from = p.targets.empty() ? nullptr : &p.targets[t];
      if (target_positions_[t])
        target.positions.push_back(from && !from->positions.empty() ? from->positions[v] : Vec3(0.0f));
      if (normals && target_normals_[t])
        target.normals.push_back(from && !from->normals.empty() ? from->normals[v] : Vec3(0.0f));
    }
    if (any_skin_) {
      deformation_.skin.joints.push_back(p.skin.joints.empty() ? std::array<std::uint16_t, kSkinInfluences>{}
                                                               : p.skin.joints[v]);
      deformation_.skin.weights.push_back(p.skin.weights.empty() ? std::array<float, kSkinInfluences>{}
                                                                 : p.skin.weights[v]);
    }
  }

  void append_flat(const Primitive& p, bool uvs, bool colors) {
    for (const TriangleIndices& t : p.triangles) {
      const auto base = std::uint32_t(out_.vertices.size());
      const Vec3 face =
          unit_or(cross(p.positions[t.v1] - p.positions[t.v0], p.positions[t.v2] - p.positions[t.v0]), Vec3(0, 0, 1));
      for (const std::uint32_t v : {t.v0, t.v1, t.v2}) {
        out_.vertices.push_back({p.positions[v].x, p.positions[v].y, p.positions[v].z});
        out_.normals.push_back(face);
        if (uvs) out_.uvs.push_back(p.uvs.empty() ? TexCoord{0.0f, 0.0f} : p.uvs[v]);
        if (colors) out_.colors.push_back(p.colors.empty() ? Color(1.0f, 1.0f, 1.0f) : p.colors[v]);
        append_deformation(p, v, true);
      }
      deformation_.flat_triangles.push_back(std::uint32_t(out_.triangles.size()));
      out_.triangles.push_back({base, base + 1, base + 2});
    }
  }

  template <typename T>
  static void append_or_fill(std::vector<T>& out, const std::vector<T>& values, std::size_t count, const T& fill) {
    if (values.empty()) out.insert(out.end(), count, fill);
    else out.insert(out.end(), values.begin(), values.end());
  }

  const std::string& file() const { return reader_.file(); }

  const tinygltf::Model& model_;
  int mesh_index_;
  const AccessorReader& reader_;
  const MeshLoadOptions& options_;
  const std::vector<UvMapping>& uv_mappings_;
  MeshLoadStats& stats_;
  MeshDeformation& deformation_;
  std::size_t target_count_ = 0;
  bool any_skin_ = false;
  std::vector<bool> target_positions_, target_normals_;  // per target: whether any primitive offsets them
  std::vector<Primitive> primitives_;
  std::vector<std::uint32_t> triangle_materials_;
  TriangleMesh out_;
};

}  // namespace

TriangleMesh read_mesh(const tinygltf::Model& model, int mesh, const AccessorReader& reader,
                       const MeshLoadOptions& options, const std::vector<UvMapping>& uv_mappings, MeshLoadStats& stats,
                       MeshDeformation& deformation) {
  return MeshBuilder(model, mesh, reader, options, uv_mappings, stats, deformation).build();
}

}  // namespace rtpro::gltf
