#include "ply_parser.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "rtpro/core/large_buffer.h"
#include "mapped_file.h"
#include "mesh_color.h"
#include "mesh_limits.h"
#include "mesh_normals.h"
#include "mesh_text_encoding.h"
#include "mesh_triangulation.h"
#include "ply_header.h"
#include "ply_value_readers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace rtpro {

using namespace ply;

namespace {

struct PlyMesh {
  VertexArray vertices;
  std::vector<Vec3> normals;  // per vertex when the file has nx, ny, nz
  std::vector<TexCoord> uvs;  // per vertex when the file has u, v (or s, t)
  std::vector<Color> colors;  // per vertex when the file has red, green, blue
  std::vector<TriangleIndices> triangles;
  // Faces of more than 3 vertices read before the vertices (a rare element order): triangulated
  // once the positions are known, after the other faces.
  std::vector<std::uint32_t> polygon_corners;
  std::vector<std::uint32_t> polygon_sizes;
  std::size_t faces = 0;
  std::size_t dropped_degenerate = 0;
  std::size_t concave_polygons = 0;
  bool fan_fallback = false;
};

// Appends the triangles of the polygon with these corners (vertex indices) to ply.triangles.
void add_polygon(PlyMesh& ply, std::span<const std::uint32_t> corners, std::vector<Vec3>& points,
                 std::vector<LocalTriangle>& local) {
  points.clear();
  local.clear();
  for (const std::uint32_t c : corners) points.push_back(ply.vertices[c].position());
  const PolygonTriangulation result = triangulate_polygon(points, local);
  ply.concave_polygons += result.concave;
  ply.dropped_degenerate += result.dropped;
  ply.fan_fallback = ply.fan_fallback || result.fan_fallback;
  for (const LocalTriangle& t : local) {
    const std::uint32_t a = corners[t[0]], b = corners[t[1]], c = corners[t[2]];
    if (a == b || b == c || a == c) ++ply.dropped_degenerate;
    else ply.triangles.push_back({a, b, c});
  }
}

// The first pair of property names the element has, as indices; -1s when it has none.
std::array<int, 2> find_pair(const Element& element, std::initializer_list<std::array<std::string_view, 2>> names) {
  for (const auto& [a, b] : names) {
    const int i = element.find(a), j = element.find(b);
    if (i >= 0 && j >= 0 && !element.properties[std::size_t(i)].is_list && !element.properties[std::size_t(j)].is_list)
      return {i, j};
  }
  return {-1, -1};
}

// Integer colour channels span their type's range; float ones are 0..1 already.
double channel_scale(Type type) {
  switch (type) {
    case Type::kInt8: return 1.0 / INT8_MAX;
    case Type::kUInt8: return 1.0 / UINT8_MAX;
    case Type::kInt16: return 1.0 / INT16_MAX;
    case Type::kUInt16: return 1.0 / UINT16_MAX;
    case Type::kInt32: return 1.0 / INT32_MAX;
    case Type::kUInt32: return 1.0 / UINT32_MAX;
    case Type::kFloat32:
    case Type::kFloat64: return 1.0;
  }
  return 1.0;
}

// Walks the body element by element, keeping vertices and faces, skipping everything else.
template <typename Reader>
class BodyReader {
 public:
  BodyReader(Reader& reader, const Header& header, const std::string& file)
      : r_(reader), header_(header), file_(file) {}

  PlyMesh read(std::size_t body_bytes) {
    const Element* vertex = find_element("vertex");
    if (!vertex) throw InputError(SourceLocation{file_}, "the PLY file has no vertex element");
    if (vertex->count > kMaxMeshElements) fail_at(*vertex, "more than 2^32 - 2 vertices");
    vertex_count_ = vertex->count;
    for (const Element& element : header_.elements) {
      if (&element == vertex) {
        read_vertices(element);
        vertices_read_ = true;
      } else if (element.name == "face") read_faces(element, body_bytes);
      else skip(element);
    }
    return std::move(mesh_);
  }

 private:
  const Element* find_element(std::string_view name) const {
    for (const Element& e : header_.elements)
      if (e.name == name) return &e;
    return nullptr;
  }

  int scalar_property(const Element& element, std::string_view name) const {
    const int index = element.find(name);
    if (index >= 0 && element.properties[std::size_t(index)].is_list)
      fail_at(element, "property " + ascii::quoted(name) + " must not be a list");
    return index;
  }

  void read_vertices(const Element& element) {
    const int axes[3] = {scalar_property(element, "x"), scalar_property(element, "y"), scalar_property(element, "z")};
    if (axes[0] < 0 || axes[1] < 0 || axes[2] < 0) fail_at(element, "the vertex element needs properties x, y and z");
    const int normal_axes[3] = {scalar_property(element, "nx"), scalar_property(element, "ny"),
                                scalar_property(element, "nz")};
    const bool has_normals = normal_axes[0] >= 0 && normal_axes[1] >= 0 && normal_axes[2] >= 0;
    const std::array<int, 2> uv =
        find_pair(element, {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}});
    const int red = element.find("red") >= 0 ? element.find("red") : element.find("diffuse_red");
    const std::array<int, 2> green_blue = element.find("red") >= 0
                                              ? find_pair(element, {{"green", "blue"}})
                                              : find_pair(element, {{"diffuse_green", "diffuse_blue"}});
    const int rgb[3] = {red, green_blue[0], green_blue[1]};
    const bool has_colors =
        rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0 && !element.properties[std::size_t(rgb[0])].is_list;
    std::vector<double> values(element.properties.size());
    reserve_large(mesh_.vertices, element.count);
    if (has_normals) reserve_large(mesh_.normals, element.count);
    if (uv[0] >= 0) reserve_large(mesh_.uvs, element.count);
    if (has_colors) reserve_large(mesh_.colors, element.count);
    for (std::uint64_t i = 0; i < element.count; ++i) {
      r_.begin_element();
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& property = element.properties[k];
        if (property.is_list) {
          skip_list(property);
          continue;
        }
        values[k] = r_.value(property.type);
        const bool is_position = int(k) == axes[0] || int(k) == axes[1] || int(k) == axes[2];
        if (is_position && !(std::fabs(float(values[k])) <= kMaxAbsCoordinate))
          r_.fail("coordinate is beyond the supported magnitude 1e16");
      }
      r_.end_element();
      const auto at = [&values](int k) { return float(values[std::size_t(k)]); };
      mesh_.vertices.push_back({at(axes[0]), at(axes[1]), at(axes[2])});
      if (has_normals) mesh_.normals.emplace_back(at(normal_axes[0]), at(normal_axes[1]), at(normal_axes[2]));
      if (uv[0] >= 0) mesh_.uvs.push_back({at(uv[0]), at(uv[1])});
      if (has_colors) {
        const auto channel = [&](int k) {
          const double scaled = values[std::size_t(k)] * channel_scale(element.properties[std::size_t(k)].type);
          return srgb_to_linear(float(std::clamp(scaled, 0.0, 1.0)));
        };
        mesh_.colors.emplace_back(channel(rgb[0]), channel(rgb[1]), channel(rgb[2]));
      }
    }
  }

  void read_faces(const Element& element, std::size_t body_bytes) {
    int list = element.find("vertex_indices");
    if (list < 0) list = element.find("vertex_index");
    if (list < 0) fail_at(element, "the face element needs a list property vertex_indices");
    const Property& indices = element.properties[std::size_t(list)];
    if (!indices.is_list || !is_integer(indices.type)) fail_at(element, "vertex_indices must be a list of integers");
    // A triangle takes at least 4 bytes of body: never reserve beyond what the file can hold.
    reserve_large(mesh_.triangles, std::min<std::uint64_t>(element.count, body_bytes / 4));
    for (std::uint64_t i = 0; i < element.count; ++i) {
      r_.begin_element();
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const Property& property = element.properties[k];
        if (int(k) == list) read_polygon(property);
        else if (property.is_list) skip_list(property);
        else r_.value(property.type);
      }
      r_.end_element();
    }
    if (mesh_.triangles.size() > kMaxMeshElements) fail_at(element, "more than 2^32 - 2 triangles");
  }

  void read_polygon(const Property& property) {
    const double count = r_.value(property.count_type);
    if (count < 3) r_.fail("a face needs at least 3 vertices, this one has " + std::to_string(std::int64_t(count)));
    corners_.clear();
    for (double c = 0; c < count; ++c) {
      const double index = r_.value(property.type);
      if (index < 0 || index >= double(vertex_count_))
        r_.fail("vertex index " + std::to_string(std::int64_t(index)) + " is out of range: the file has " +
                std::to_string(vertex_count_) + " vertices");
      corners_.push_back(std::uint32_t(index));
    }
    ++mesh_.faces;
    if (corners_.size() > 3 && vertices_read_) return add_polygon(mesh_, corners_, points_, local_);
    if (corners_.size() > 3) {
      mesh_.polygon_corners.insert(mesh_.polygon_corners.end(), corners_.begin(), corners_.end());
      mesh_.polygon_sizes.push_back(std::uint32_t(corners_.size()));
      return;
    }
    const std::uint32_t a = corners_[0], b = corners_[1], c = corners_[2];
    if (a == b || b == c || a == c) ++mesh_.dropped_degenerate;
    else mesh_.triangles.push_back({a, b, c});
  }

  void skip_list(const Property& property) {
    const double count = r_.value(property.count_type);
    if (count < 0) r_.fail("a list length must not be negative");
    for (double c = 0; c < count; ++c) r_.value(property.type);
  }

  void skip(const Element& element) {
    for (std::uint64_t i = 0; i < element.count; ++i) {
      r_.begin_element();
      for (const Property& property : element.properties) {
        if (property.is_list) skip_list(property);
        else r_.value(property.type);
      }
      r_.end_element();
    }
  }

  [[noreturn]] void fail_at(const Element& element, const std::string& message) const {
    throw InputError(SourceLocation{file_, element.line}, message);
  }

  Reader& r_;
  const Header& header_;
  const std::string& file_;
  std::uint64_t vertex_count_ = 0;
  std::vector<std::uint32_t> corners_;
  std::vector<Vec3> points_;
  std::vector<LocalTriangle> local_;
  bool vertices_read_ = false;
  PlyMesh mesh_;
};

PlyMesh read_body(std::string_view bytes, const Header& header, const std::string& file) {
  const std::size_t body_bytes = bytes.size() - header.body_offset;
  if (header.encoding == Encoding::kAscii) {
    AsciiReader reader(bytes, header.body_offset, header.body_line, file);
    return BodyReader<AsciiReader>(reader, header, file).read(body_bytes);
  }
  BinaryReader reader(bytes, header.body_offset, header.encoding == Encoding::kBinaryBigEndian, file);
  return BodyReader<BinaryReader>(reader, header, file).read(body_bytes);
}

void triangulate_deferred_polygons(PlyMesh& ply, MeshLoadStats& stats, const std::string& file) {
  std::vector<Vec3> points;
  std::vector<LocalTriangle> local;
  std::size_t first = 0;
  for (const std::uint32_t size : ply.polygon_sizes) {
    add_polygon(ply, std::span<const std::uint32_t>(ply.polygon_corners.data() + first, size), points, local);
    first += size;
  }
  if (ply.triangles.size() > kMaxMeshElements) throw InputError(SourceLocation{file}, "more than 2^32 - 2 triangles");
  ply.polygon_corners = {};
  stats.concave_polygons = ply.concave_polygons;
  if (ply.fan_fallback)
    stats.warnings.push_back(
        file + ": a concave polygon that ear clipping cannot triangulate (self-intersecting, or more than " +
        std::to_string(kMaxEarClippedCorners) + " corners): fan-triangulated, may look wrong");
}

// The file's normals, generated ones or none (flat), as the scene's `normals:` asks.
void choose_normals(PlyMesh& ply, NormalsMode mode, TriangleMesh& mesh, MeshLoadStats& stats, const std::string& file) {
  const bool usable = !ply.normals.empty();
  if (usable && mode != NormalsMode::kFlat && mode != NormalsMode::kSmooth) {
    const auto position = [&](std::uint32_t v) { return mesh.vertices[v].position(); };
    if (const std::size_t repaired = repair_vertex_normals(position, mesh.triangles, ply.normals))
      stats.warnings.push_back(repaired_normals_warning(file, repaired));
  }
  switch (mode) {
    case NormalsMode::kFile:
      if (!usable)
        throw InputError(SourceLocation{file}, "normals: file, but the file has no usable vertex normals (nx, ny, nz)");
      [[fallthrough]];
    case NormalsMode::kAuto:
      if (usable) {
        mesh.normals = std::move(ply.normals);
        for (Vec3& n : mesh.normals) n = unit_or(n, Vec3(0.0f, 0.0f, 1.0f));
      }
      return;
    case NormalsMode::kFlat: return;
    case NormalsMode::kSmooth:
      mesh.normals = area_weighted_vertex_normals(mesh.vertices, mesh.triangles);
      stats.normals_generated = true;
      return;
  }
}

}  // namespace

LoadedMesh load_ply_file(const std::filesystem::path& file, const MeshLoadOptions& options) {
  const MappedFile bytes(file);
  const std::string file_name = file.string();
  if (bytes.size() == 0) throw InputError(SourceLocation{file_name}, "the file is empty");
  require_narrow_text(bytes.text().substr(0, 64), file_name, "PLY");
  const Header header = parse_header(bytes.text(), file_name);
  PlyMesh ply = read_body(bytes.text(), header, file_name);

  LoadedMesh loaded;
  MeshLoadStats& stats = loaded.stats;
  stats.warnings = header.warnings;
  triangulate_deferred_polygons(ply, stats, file_name);
  TriangleMesh& mesh = loaded.mesh;
  mesh.name = file.stem().string();
  mesh.material = kNoMaterial;
  mesh.vertices = std::move(ply.vertices);
  mesh.triangles = std::move(ply.triangles);
  mesh.uvs = std::move(ply.uvs);
  mesh.colors = std::move(ply.colors);
  choose_normals(ply, options.normals, mesh, stats, file_name);
  if (mesh.triangles.empty()) stats.warnings.push_back(file_name + ": no faces");
  stats.vertices = mesh.vertices.size();
  stats.triangles = mesh.triangles.size();
  stats.faces = ply.faces;
  stats.dropped_degenerate += ply.dropped_degenerate;
  return loaded;
}

}  // namespace rtpro
