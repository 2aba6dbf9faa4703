#include "obj_assembly.h"

#include "rtpro/core/error.h"
#include "rtpro/core/large_buffer.h"
#include "mesh_limits.h"
#include "mesh_normals.h"
#include "obj_chunk.h"

#include <algorithm>
#include <unordered_map>

namespace rtpro::obj {

namespace {

// Output vertices for (position, attribute) corner keys, numbered in first-use order. The
// attribute is a normal index or a smoothing group. Most positions only ever meet one
// attribute, so the first one lives in a flat array and only the rest go to a hash map.
class CornerVertices {
 public:
  explicit CornerVertices(std::size_t positions) : first_use_(positions) {}

  std::uint32_t shared(std::uint32_t position, std::uint32_t attribute) {
    FirstUse& first = first_use_[position];
    if (first.attribute == attribute) return first.vertex;
    if (first.attribute == kUnused) {
      first = {attribute, unshared(position, attribute)};
      return first.vertex;
    }
    const std::uint64_t key = (std::uint64_t(position) << 32) | attribute;
    const auto [entry, inserted] = others_.try_emplace(key, 0u);
    if (inserted) entry->second = unshared(position, attribute);
    return entry->second;
  }

  std::uint32_t unshared(std::uint32_t position, std::uint32_t attribute) {
    if (position_of.size() >= kMaxMeshElements) throw InputError("mesh has more than 2^32 - 2 vertices");
    position_of.push_back(position);
    attribute_of.push_back(attribute);
    return std::uint32_t(position_of.size() - 1);
  }

  std::vector<std::uint32_t> position_of;
  std::vector<std::uint32_t> attribute_of;

 private:
  static constexpr std::uint32_t kUnused = ~0u;
  struct FirstUse {
    std::uint32_t attribute = kUnused;
    std::uint32_t vertex = 0;
  };
  std::vector<FirstUse> first_use_;
  std::unordered_map<std::uint64_t, std::uint32_t> others_;
};

// Shading vertices: one per (position, normal source), the first step of assembly. `position_of`
// is empty when they are the file's positions themselves.
struct ShadingVertices {
  std::vector<std::uint32_t> position_of;
  std::vector<Vec3> normals;         // per shading vertex; empty for a flat mesh
  std::size_t repaired_normals = 0;  // the file's that were zero or not finite
  std::uint32_t position(std::uint32_t v) const { return position_of.empty() ? v : position_of[v]; }
  std::size_t size(std::size_t positions) const { return position_of.empty() ? positions : position_of.size(); }
};

VertexArray gather_positions(const VertexArray& positions, const ShadingVertices& shading, std::size_t count) {
  VertexArray vertices;
  reserve_large(vertices, count);
  for (std::uint32_t v = 0; v < count; ++v) vertices.push_back(positions[shading.position(v)]);
  return vertices;
}

// Every corner keyed by (position, file normal): the normals come straight from the file.
ShadingVertices key_by_file_normals(MeshParts& parts, std::vector<TriangleIndices>& triangles) {
  CornerVertices corners(parts.positions.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    TriangleIndices& tri = triangles[t];
    const TriangleIndices& n = parts.triangle_normals[t];
    tri = {corners.shared(tri.v0, n.v0), corners.shared(tri.v1, n.v1), corners.shared(tri.v2, n.v2)};
  }
  ShadingVertices shading;
  shading.normals.reserve(corners.attribute_of.size());
  for (std::uint32_t n : corners.attribute_of) shading.normals.push_back(parts.normals[n]);
  shading.position_of = std::move(corners.position_of);
  const auto position = [&](std::uint32_t v) { return parts.positions[shading.position(v)].position(); };
  shading.repaired_normals = repair_vertex_normals(position, triangles, shading.normals);
  for (Vec3& n : shading.normals) n = unit_or(n, Vec3(0, 0, 1));
  return shading;
}

// Corners keyed by (position, smoothing group); flat triangles get vertices of their own, so
// the area-weighted normal of each of them is its face normal.
ShadingVertices key_by_smoothing_group(MeshParts& parts, std::vector<TriangleIndices>& triangles) {
  CornerVertices corners(parts.positions.size());
  std::size_t run = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    while (run + 1 < parts.runs.size() && parts.runs[run + 1].first_triangle <= t) ++run;
    const std::uint32_t group = parts.runs[run].smoothing;
    TriangleIndices& tri = triangles[t];
    if (group == kFlat) {
      tri = {corners.unshared(tri.v0, group), corners.unshared(tri.v1, group), corners.unshared(tri.v2, group)};
    } else {
      tri = {corners.shared(tri.v0, group), corners.shared(tri.v1, group), corners.shared(tri.v2, group)};
    }
  }
  ShadingVertices shading;
  shading.position_of = std::move(corners.position_of);
  shading.normals =
      area_weighted_vertex_normals(gather_positions(parts.positions, shading, shading.position_of.size()), triangles);
  return shading;
}

// The first step: which normal each corner gets. Returns whether normals were generated.
bool assign_shading(MeshParts& parts, std::vector<TriangleIndices>& triangles, ShadingVertices& shading) {
  if (!parts.triangle_normals.empty()) {
    shading = key_by_file_normals(parts, triangles);
    return false;
  }
  const auto same_smoothing = [&](const TriangleRun& r) { return r.smoothing == parts.runs.front().smoothing; };
  if (parts.runs.empty() || std::all_of(parts.runs.begin(), parts.runs.end(), same_smoothing)) {
    // One smoothing state for the whole mesh: the file's vertex list serves unchanged.
    const bool flat = parts.runs.empty() || parts.runs.front().smoothing == kFlat;
    if (flat) return false;
    shading.normals = area_weighted_vertex_normals(parts.positions, triangles);
    return true;
  }
  shading = key_by_smoothing_group(parts, triangles);
  return true;
}

}  // namespace

bool assemble_mesh(MeshParts parts, TriangleMesh& mesh, std::size_t& repaired_normals) {
  std::vector<TriangleIndices> triangles = std::move(parts.triangle_positions);
  ShadingVertices shading;
  const bool generated = assign_shading(parts, triangles, shading);
  repaired_normals = shading.repaired_normals;
  const std::size_t shading_count = shading.size(parts.positions.size());

  // The second step: a shading vertex meeting different texture coordinates is split again, so
  // a uv seam never splits a smooth normal.
  std::vector<std::uint32_t> shading_of, texcoord_of;
  if (!parts.triangle_texcoords.empty()) {
    CornerVertices corners(shading_count);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      TriangleIndices& tri = triangles[t];
      const TriangleIndices& uv = parts.triangle_texcoords[t];
      tri = {corners.shared(tri.v0, uv.v0), corners.shared(tri.v1, uv.v1), corners.shared(tri.v2, uv.v2)};
    }
    shading_of = std::move(corners.position_of);
    texcoord_of = std::move(corners.attribute_of);
  }
  const auto shading_vertex = [&](std::uint32_t v) { return shading_of.empty() ? v : shading_of[v]; };
  const std::size_t count = shading_of.empty() ? shading_count : shading_of.size();

  if (shading.position_of.empty() && shading_of.empty()) {
    mesh.vertices = std::move(parts.positions);
  } else {
    mesh.vertices.clear();
    reserve_large(mesh.vertices, count);
    for (std::uint32_t v = 0; v < count; ++v)
      mesh.vertices.push_back(parts.positions[shading.position(shading_vertex(v))]);
  }
  if (!shading.normals.empty()) {
    if (shading_of.empty()) {
      mesh.normals = std::move(shading.normals);
    } else {
      mesh.normals.reserve(count);
      for (std::uint32_t v = 0; v < count; ++v) mesh.normals.push_back(shading.normals[shading_of[v]]);
    }
  }
  for (std::uint32_t t : texcoord_of) mesh.uvs.push_back(parts.texcoords[t]);
  if (!parts.colors.empty()) {
    mesh.colors.reserve(count);
    for (std::uint32_t v = 0; v < count; ++v) mesh.colors.push_back(parts.colors[shading.position(shading_vertex(v))]);
  }
  mesh.triangles = std::move(triangles);
  return generated;
}

}  // namespace rtpro::obj
