#include "obj_assembly.h"

#include "rtpro/core/error.h"
#include "large_buffer.h"
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

std::vector<PaddedVertex> gather_positions(const std::vector<PaddedVertex>& positions,
                                           const std::vector<std::uint32_t>& position_of) {
  std::vector<PaddedVertex> vertices;
  reserve_large(vertices, position_of.size());
  for (std::uint32_t p : position_of) vertices.push_back(positions[p]);
  return vertices;
}

// Every corner keyed by (position, file normal): the normals come straight from the file.
void assemble_with_file_normals(MeshParts& parts, TriangleMesh& mesh) {
  CornerVertices corners(parts.positions.size());
  mesh.triangles = std::move(parts.triangle_positions);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    TriangleIndices& tri = mesh.triangles[t];
    const TriangleIndices& n = parts.triangle_normals[t];
    tri = {corners.shared(tri.v0, n.v0), corners.shared(tri.v1, n.v1), corners.shared(tri.v2, n.v2)};
  }
  mesh.vertices = gather_positions(parts.positions, corners.position_of);
  mesh.normals.reserve(corners.attribute_of.size());
  for (std::uint32_t n : corners.attribute_of) mesh.normals.push_back(unit_or(parts.normals[n], Vec3(0, 0, 1)));
}

// Corners keyed by (position, smoothing group); flat triangles get vertices of their own.
void assemble_by_smoothing_group(MeshParts& parts, TriangleMesh& mesh) {
  CornerVertices corners(parts.positions.size());
  mesh.triangles = std::move(parts.triangle_positions);
  std::size_t run = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    while (run + 1 < parts.runs.size() && parts.runs[run + 1].first_triangle <= t) ++run;
    const std::uint32_t group = parts.runs[run].smoothing;
    TriangleIndices& tri = mesh.triangles[t];
    if (group == kFlat) {
      tri = {corners.unshared(tri.v0, group), corners.unshared(tri.v1, group), corners.unshared(tri.v2, group)};
    } else {
      tri = {corners.shared(tri.v0, group), corners.shared(tri.v1, group), corners.shared(tri.v2, group)};
    }
  }
  mesh.vertices = gather_positions(parts.positions, corners.position_of);
  mesh.normals = area_weighted_vertex_normals(mesh.vertices, mesh.triangles);
}

}  // namespace

bool assemble_mesh(MeshParts parts, TriangleMesh& mesh) {
  if (!parts.triangle_normals.empty()) {
    assemble_with_file_normals(parts, mesh);
    return false;
  }
  const auto same_smoothing = [&](const TriangleRun& r) { return r.smoothing == parts.runs.front().smoothing; };
  if (parts.runs.empty() || std::all_of(parts.runs.begin(), parts.runs.end(), same_smoothing)) {
    // One smoothing state for the whole mesh: the file's vertex list serves unchanged.
    const bool flat = !parts.runs.empty() && parts.runs.front().smoothing == kFlat;
    mesh.vertices = std::move(parts.positions);
    mesh.triangles = std::move(parts.triangle_positions);
    if (flat) return false;
    mesh.normals = area_weighted_vertex_normals(mesh.vertices, mesh.triangles);
    return true;
  }
  assemble_by_smoothing_group(parts, mesh);
  return true;
}

}  // namespace rtpro::obj
