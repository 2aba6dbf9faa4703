#include "obj_parser.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "rtpro/core/large_buffer.h"
#include "mapped_file.h"
#include "mesh_color.h"
#include "mesh_limits.h"
#include "mesh_text_encoding.h"
#include "mesh_triangulation.h"
#include "mesh_normals.h"
#include "obj_assembly.h"
#include "obj_cage.h"
#include "obj_chunk.h"
#include "obj_materials.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <unordered_map>

namespace rtpro {

namespace fs = std::filesystem;
using namespace obj;

namespace {

// The name under which faces before any usemtl, or after a bare `usemtl`, are keyed.
constexpr std::string_view kNoUsemtl{};
// The one smoothing group of `normals: smooth`.
constexpr std::uint32_t kWholeMeshGroup = 1;
// Distinct ignored keywords listed one by one in the warnings; the rest are summed in one line.
constexpr std::size_t kListedIgnoredKeywords = 8;

std::string located(const std::string& file, std::uint64_t line, const std::string& message) {
  return file + ":" + std::to_string(line) + ": " + message;
}

Counts assign_chunk_starts(std::vector<Chunk>& chunks) {
  Counts running;
  for (Chunk& chunk : chunks) {
    chunk.start = running;
    running += chunk.counts;
  }
  return running;
}

template <typename Visit>
void for_each_chunk(std::vector<Chunk>& chunks, Visit&& visit) {
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t i) { visit(chunks[i]); });
}

// Triangles of the chunk's first k polygons, for every k.
std::vector<std::size_t> polygon_prefix_sums(const Chunk& chunk) {
  std::vector<std::size_t> prefix{0};
  for (std::uint32_t n : chunk.triangles_of_polygon) prefix.push_back(prefix.back() + n);
  return prefix;
}

// The chunk's triangles (or their attribute triples) in file order: its triangle faces with each
// polygon's triangles inserted where the polygon was read.
TriangleIndices* merge_in_file_order(const Chunk& chunk, const TriangleIndices* faces,
                                     const std::vector<TriangleIndices>& polygon_part, TriangleIndices* out) {
  std::size_t face = 0, from_polygons = 0;
  for (std::size_t p = 0; p < chunk.polygons.size(); ++p) {
    const std::size_t until = chunk.polygons[p].triangles_before;
    out = std::copy(faces + face, faces + until, out);
    face = until;
    const std::size_t n = chunk.triangles_of_polygon[p];
    out = std::copy(polygon_part.begin() + std::ptrdiff_t(from_polygons),
                    polygon_part.begin() + std::ptrdiff_t(from_polygons + n), out);
    from_polygons += n;
  }
  return std::copy(faces + face, faces + chunk.triangles_in_slots, out);
}

// The triangles in file order. When every `f` line gave exactly one triangle the chunks filled
// `slots` completely and it is the answer; polygons and dropped faces need a new array.
std::vector<TriangleIndices> gather_triangles(const std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets,
                                              std::vector<TriangleIndices> slots) {
  const bool slots_are_exact = std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) {
    return c.triangles_in_slots == c.counts.faces && c.polygons.empty();
  });
  if (slots_are_exact) return slots;
  std::vector<TriangleIndices> all;
  resize_large(all, offsets.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t i) {
    const Chunk& chunk = chunks[i];
    merge_in_file_order(chunk, slots.data() + chunk.start.faces, chunk.polygon_triangles, all.data() + offsets[i]);
  });
  return all;
}

// The per-triangle attribute indices (normal or texture coordinate) in file order.
std::vector<TriangleIndices> gather_attribute(std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets,
                                              std::vector<TriangleIndices> Chunk::*faces,
                                              std::vector<TriangleIndices> Chunk::*polygons) {
  std::vector<TriangleIndices> all;
  resize_large(all, offsets.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t i) {
    Chunk& chunk = chunks[i];
    merge_in_file_order(chunk, (chunk.*faces).data(), chunk.*polygons, all.data() + offsets[i]);
    chunk.*faces = {};
    chunk.*polygons = {};
  });
  return all;
}

// The usemtl and `s` state of every triangle as runs, with materials numbered in first-use order.
struct StitchedState {
  std::vector<TriangleRun> runs;
  std::vector<LocatedName> materials;  // kNoUsemtl for faces before any usemtl
};

StitchedState stitch_state(const std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets) {
  struct NamedRun {
    std::size_t first_triangle;
    LocatedName material;
    std::uint32_t smoothing;
  };
  std::vector<NamedRun> named{{0, {kNoUsemtl, 0}, kFlat}};
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    const std::vector<std::size_t> polygon_triangles = polygon_prefix_sums(chunks[c]);
    for (const StateChange& change : chunks[c].state_changes) {
      NamedRun run = named.back();
      run.first_triangle = offsets[c] + change.first_triangle + polygon_triangles[change.polygons_before];
      if (change.material_slot != kInherited) run.material = chunks[c].material_names[change.material_slot];
      if (change.smoothing != kInherited) run.smoothing = change.smoothing;
      // A run that covers no triangle changes nothing, and must not count as a material's use.
      if (named.back().first_triangle == run.first_triangle) named.pop_back();
      named.push_back(run);
    }
  }
  if (named.back().first_triangle == offsets.back()) named.pop_back();

  StitchedState state;
  std::unordered_map<std::string_view, std::uint32_t> index_of;
  for (const NamedRun& run : named) {
    const auto [entry, inserted] = index_of.try_emplace(run.material.name, std::uint32_t(state.materials.size()));
    if (inserted) state.materials.push_back(run.material);
    state.runs.push_back({std::uint32_t(run.first_triangle), entry->second, run.smoothing});
  }
  return state;
}

void warn_about_ignored_statements(const std::string& file, const std::vector<Chunk>& chunks,
                                   std::vector<std::string>& warnings) {
  std::vector<IgnoredKeyword> all;
  std::unordered_map<std::string_view, std::size_t> index_of;
  for (const Chunk& chunk : chunks) {
    for (const IgnoredKeyword& k : chunk.ignored) {
      const auto [slot, inserted] = index_of.try_emplace(k.keyword, all.size());
      if (inserted) all.push_back(k);
      else all[slot->second].count += k.count;
    }
  }
  std::uint64_t unlisted_statements = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const IgnoredKeyword& k = all[i];
    if (i < kListedIgnoredKeywords)
      warnings.push_back(
          located(file, k.first_line,
                  "ignored " + ascii::quoted(k.keyword) + " statements (" + std::to_string(k.count) + " in total)"));
    else unlisted_statements += k.count;
  }
  if (all.size() > kListedIgnoredKeywords)
    warnings.push_back(file + ": ignored " + std::to_string(unlisted_statements) + " more statements with " +
                       std::to_string(all.size() - kListedIgnoredKeywords) + " other unknown keywords");
}

// Whether the per-corner vn indices can serve as the mesh's normals; warns when they exist but cannot.
bool file_normals_usable(const std::string& file, const std::vector<Chunk>& chunks, const Counts& totals,
                         std::size_t triangles, std::vector<std::string>& warnings) {
  if (totals.normals == 0 || triangles == 0) return false;
  if (std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.every_corner_has_normal; })) return true;
  warnings.push_back(file + ": some face vertices have no normal (vn); the file's normals are not used");
  return false;
}

bool texcoords_usable(const std::string& file, const std::vector<Chunk>& chunks, const Counts& totals,
                      std::size_t triangles, std::vector<std::string>& warnings) {
  if (totals.texcoords == 0 || triangles == 0) return false;
  if (std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.every_corner_has_texcoord; }))
    return true;
  warnings.push_back(file + ": some face vertices have no texture coordinate (vt); texture coordinates dropped");
  return false;
}

// Which normals the mesh gets, from the scene's `normals:` and what the file offers; adjusts the
// smoothing runs for the flat and smooth overrides.
bool choose_file_normals(NormalsMode mode, bool usable, const std::string& file, std::vector<TriangleRun>& runs) {
  switch (mode) {
    case NormalsMode::kAuto: return usable;
    case NormalsMode::kFile:
      if (!usable)
        throw InputError(SourceLocation{file},
                         "normals: file, but the file has no usable normals (vn on every face vertex)");
      return true;
    case NormalsMode::kFlat:
      for (TriangleRun& run : runs) run.smoothing = kFlat;
      return false;
    case NormalsMode::kSmooth:
      for (TriangleRun& run : runs) run.smoothing = kWholeMeshGroup;
      return false;
  }
  return false;
}

std::vector<Color> vertex_colors(const std::vector<Chunk>& chunks, std::size_t positions) {
  const bool any = std::any_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return !c.colors.empty(); });
  if (!any) return {};
  // Vertices without a colour of their own are white: they leave a texture or material as it is.
  std::vector<Color> colors(positions, Color(1.0f, 1.0f, 1.0f));
  for (const Chunk& chunk : chunks)
    for (const VertexColor& c : chunk.colors)
      colors[c.position] = Color(srgb_to_linear(c.color.x), srgb_to_linear(c.color.y), srgb_to_linear(c.color.z));
  return colors;
}

void warn_about_faces(const std::string& file, const std::vector<Chunk>& chunks, std::size_t triangles,
                      std::vector<std::string>& warnings) {
  for (const Chunk& chunk : chunks) {
    if (chunk.first_unnamed_usemtl_line != 0) {
      warnings.push_back(located(file, chunk.first_unnamed_usemtl_line,
                                 "usemtl without a material name: those faces use the default material"));
      break;
    }
  }
  for (const Chunk& chunk : chunks) {
    if (chunk.fan_fallback_line != 0) {
      warnings.push_back(
          located(file, chunk.fan_fallback_line,
                  "concave polygon that ear clipping cannot triangulate (self-intersecting, or more than " +
                      std::to_string(kMaxEarClippedCorners) + " corners): fan-triangulated, may look wrong"));
      break;
    }
  }
  if (triangles == 0) warnings.push_back(file + ": no faces");
}

}  // namespace

LoadedMesh load_obj_file(const fs::path& file, const MeshLoadOptions& options, std::size_t chunk_bytes) {
  const MappedFile bytes(file);
  const std::string file_name = file.string();
  require_narrow_text(bytes.text(), file_name, "OBJ");
  std::vector<Chunk> chunks = split_into_chunks(without_utf8_bom(bytes.text()), chunk_bytes);
  for_each_chunk(chunks, count_chunk);
  const Counts totals = assign_chunk_starts(chunks);
  if (totals.positions > kMaxMeshElements || totals.normals > kMaxMeshElements || totals.texcoords > kMaxMeshElements ||
      totals.faces > kMaxMeshElements)
    throw InputError(SourceLocation{file_name}, "more than 2^32 - 2 vertices, normals, texture coordinates or faces");

  obj::MeshParts parts;
  std::vector<TriangleIndices> triangle_slots;
  // Filling fresh memory is bound by page faults; two arrays, two cores.
  tbb::parallel_invoke([&] { resize_large(parts.positions, totals.positions); },
                       [&] {
                         resize_large(triangle_slots, totals.faces);
                         resize_large(parts.normals, totals.normals);
                         resize_large(parts.texcoords, totals.texcoords);
                       });
  const Destination out{
      parts.positions.data(), parts.normals.data(), parts.texcoords.data(), triangle_slots.data(), totals, file_name};
  for_each_chunk(chunks, [&out](Chunk& chunk) { parse_chunk(chunk, out); });
  for (const Chunk& chunk : chunks)
    if (chunk.error) std::rethrow_exception(chunk.error);
  std::shared_ptr<PolygonCage> cage;
  if (options.keep_cage) {
    const bool cage_texcoords = totals.texcoords > 0 && std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) {
                                  return c.every_corner_has_texcoord;
                                });
    cage = std::make_shared<PolygonCage>(
        gather_cage(chunks, triangle_slots.data(), parts.positions, cage_texcoords ? &parts.texcoords : nullptr));
  }
  for_each_chunk(chunks, [&parts](Chunk& chunk) { triangulate_polygons(chunk, parts.positions); });

  std::vector<std::size_t> offsets{0};
  for (const Chunk& chunk : chunks) offsets.push_back(offsets.back() + chunk.triangle_count());
  if (offsets.back() > kMaxMeshElements) throw InputError(SourceLocation{file_name}, "more than 2^32 - 2 triangles");

  LoadedMesh loaded;
  std::vector<std::string>& warnings = loaded.stats.warnings;
  StitchedState state = stitch_state(chunks, offsets);
  loaded.materials = load_obj_materials(file, chunks, state.materials, loaded.stats);
  if (state.materials.size() == 1 && state.materials.front().name == kNoUsemtl) loaded.materials.clear();
  warn_about_ignored_statements(file_name, chunks, warnings);
  warn_about_faces(file_name, chunks, offsets.back(), warnings);

  parts.runs = std::move(state.runs);
  const bool usable_normals = file_normals_usable(file_name, chunks, totals, offsets.back(), warnings);
  const bool file_normals = choose_file_normals(options.normals, usable_normals, file_name, parts.runs);
  const bool texcoords = texcoords_usable(file_name, chunks, totals, offsets.back(), warnings);
  parts.triangle_positions = gather_triangles(chunks, offsets, std::move(triangle_slots));
  if (file_normals)
    parts.triangle_normals =
        gather_attribute(chunks, offsets, &Chunk::triangle_normals, &Chunk::polygon_triangle_normals);
  if (texcoords)
    parts.triangle_texcoords =
        gather_attribute(chunks, offsets, &Chunk::triangle_texcoords, &Chunk::polygon_triangle_texcoords);
  else parts.texcoords = {};
  parts.colors = vertex_colors(chunks, parts.positions.size());

  TriangleMesh& mesh = loaded.mesh;
  mesh.name = file.stem().string();
  for (const Chunk& chunk : chunks) {
    if (!chunk.object_name.name.empty()) {
      mesh.name = chunk.object_name.name;
      break;
    }
  }
  if (loaded.materials.size() > 1) {
    mesh.triangle_materials.resize(offsets.back());
    for (std::size_t r = 0; r < parts.runs.size(); ++r) {
      const std::size_t end = r + 1 < parts.runs.size() ? parts.runs[r + 1].first_triangle : offsets.back();
      std::fill(mesh.triangle_materials.begin() + parts.runs[r].first_triangle,
                mesh.triangle_materials.begin() + std::ptrdiff_t(end), parts.runs[r].material);
    }
  }
  mesh.material = loaded.materials.empty() ? kNoMaterial : 0;

  MeshLoadStats& stats = loaded.stats;
  for (const Chunk& chunk : chunks) {
    stats.faces += chunk.faces;
    stats.dropped_degenerate += chunk.dropped_degenerate;
    stats.concave_polygons += chunk.concave_polygons;
  }
  std::size_t repaired_normals = 0;
  stats.normals_generated = assemble_mesh(std::move(parts), mesh, repaired_normals);
  // Named at the first zero-length vn, so the user can find what to fix.
  if (repaired_normals > 0) {
    std::uint64_t line = 0;
    for (const Chunk& chunk : chunks)
      if (line == 0) line = chunk.first_zero_normal_line;
    warnings.push_back(
        repaired_normals_warning(line ? file_name + ":" + std::to_string(line) : file_name, repaired_normals));
  }
  stats.vertices = mesh.vertices.size();
  stats.triangles = mesh.triangles.size();
  stats.materials = loaded.materials.size();
  if (cage) {
    assign_cage_materials(*cage, chunks, offsets, mesh);
    loaded.cage = std::move(cage);
  }
  return loaded;
}

}  // namespace rtpro
