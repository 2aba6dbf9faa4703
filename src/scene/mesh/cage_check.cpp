#include "cage_check.h"

#include <algorithm>
#include <unordered_map>

namespace rtpro {

namespace {

constexpr std::uint32_t kUnused = ~0u;

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

std::string face_name(std::size_t face) { return "face " + std::to_string(face + 1); }

bool has_repeated_corner(const std::uint32_t* corners, std::uint32_t count) {
  for (std::uint32_t i = 0; i < count; ++i)
    for (std::uint32_t j = i + 1; j < count; ++j)
      if (corners[i] == corners[j]) return true;
  return false;
}

// How the kept faces use one edge: how many, and the first face walking it each way.
struct EdgeUse {
  std::uint32_t faces = 0;
  std::uint32_t forward_face = kUnused, backward_face = kUnused;
};

void check_manifold(const CheckedCage& checked, const std::string& file) {
  const PolygonCage& cage = checked.cage;
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(cage.face_vertices.size());
  std::size_t first = 0;
  for (std::size_t f = 0; f < cage.face_count(); first += cage.face_sizes[f], ++f) {
    const std::uint32_t n = cage.face_sizes[f];
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = cage.face_vertices[first + k], b = cage.face_vertices[first + (k + 1) % n];
      EdgeUse& use = edges[edge_key(a, b)];
      std::uint32_t& same_way = a < b ? use.forward_face : use.backward_face;
      const std::string here = face_name(checked.source_face[f]);
      if (++use.faces > 2)
        throw InputError(SourceLocation{file}, here + ": its edge between the file's vertices " +
                                                   std::to_string(checked.file_vertex[a] + 1) + " and " +
                                                   std::to_string(checked.file_vertex[b] + 1) +
                                                   " (counted from 1) is shared by more than two faces; a "
                                                   "subdivision cage must be manifold");
      if (same_way != kUnused)
        throw InputError(SourceLocation{file}, here + " and " + face_name(checked.source_face[same_way]) +
                                                   " walk their shared edge the same way: the cage's faces must "
                                                   "wind consistently (flip one of them)");
      same_way = std::uint32_t(f);
    }
  }
}

}  // namespace

CheckedCage check_cage(const PolygonCage& cage, const SubdivisionDesc& desc, const std::string& file) {
  CheckedCage checked;
  PolygonCage& out = checked.cage;
  std::vector<std::uint32_t> new_index(cage.positions.size(), kUnused);
  std::vector<std::uint32_t> new_uv(cage.uvs.size(), kUnused);
  std::size_t dropped = 0, first_dropped = 0, first = 0;
  for (std::size_t f = 0; f < cage.face_count(); first += cage.face_sizes[f], ++f) {
    const std::uint32_t n = cage.face_sizes[f];
    const std::uint32_t* corners = cage.face_vertices.data() + first;
    if (n < 3 || has_repeated_corner(corners, n)) {
      if (dropped++ == 0) first_dropped = f;
      continue;
    }
    if (desc.scheme == SubdivisionScheme::kLoop && n != 3)
      throw InputError(SourceLocation{file}, face_name(f) + " has " + std::to_string(n) +
                                                 " corners: Loop subdivision refines triangles only (use "
                                                 "scheme: catmull-clark for quads and polygons)");
    checked.all_quads = checked.all_quads && n == 4;
    out.face_sizes.push_back(n);
    checked.source_face.push_back(std::uint32_t(f));
    if (!cage.face_materials.empty()) out.face_materials.push_back(cage.face_materials[f]);
    for (std::uint32_t k = 0; k < n; ++k) {
      std::uint32_t& v = new_index[corners[k]];
      if (v == kUnused) {
        v = std::uint32_t(out.positions.size());
        out.positions.push_back(cage.positions[corners[k]]);
        checked.file_vertex.push_back(corners[k]);
      }
      out.face_vertices.push_back(v);
      if (cage.face_uvs.empty()) continue;
      std::uint32_t& uv = new_uv[cage.face_uvs[first + k]];
      if (uv == kUnused) {
        uv = std::uint32_t(out.uvs.size());
        out.uvs.push_back(cage.uvs[cage.face_uvs[first + k]]);
      }
      out.face_uvs.push_back(uv);
    }
  }
  if (dropped > 0)
    checked.warnings.push_back(file + ": " + face_name(first_dropped) + ": " + std::to_string(dropped) +
                               " degenerate faces (fewer than 3 corners, or a corner repeated) left out of the "
                               "subdivision cage");
  check_manifold(checked, file);

  const auto vertex = [&](std::uint32_t v, const SourceLocation& where, const std::string& what) {
    if (v >= cage.positions.size())
      throw InputError(where, what + ": vertex " + std::to_string(v) + " is out of range (the cage has " +
                                  std::to_string(cage.positions.size()) + " vertices, numbered from 0)");
    if (new_index[v] == kUnused) throw InputError(where, what + ": vertex " + std::to_string(v) + " is on no face");
    return new_index[v];
  };
  std::unordered_map<std::uint64_t, bool> cage_edges;
  first = 0;
  for (std::size_t f = 0; f < out.face_count(); first += out.face_sizes[f], ++f)
    for (std::uint32_t k = 0; k < out.face_sizes[f]; ++k)
      cage_edges[edge_key(out.face_vertices[first + k], out.face_vertices[first + (k + 1) % out.face_sizes[f]])] = true;
  for (const EdgeCrease& crease : desc.creases) {
    const std::uint32_t a = vertex(crease.v0, crease.where, "crease"), b = vertex(crease.v1, crease.where, "crease");
    if (!cage_edges.count(edge_key(a, b)))
      throw InputError(crease.where, "crease: vertices " + std::to_string(crease.v0) + " and " +
                                         std::to_string(crease.v1) + " share no edge of the cage");
    checked.creases.push_back({a, b, crease.sharpness, crease.where});
  }
  for (const VertexCorner& corner : desc.corners)
    checked.corners.push_back({vertex(corner.vertex, corner.where, "corner"), corner.sharpness, corner.where});
  return checked;
}

}  // namespace rtpro
