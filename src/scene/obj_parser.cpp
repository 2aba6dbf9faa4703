#include "obj_parser.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "large_buffer.h"
#include "mapped_file.h"
#include "mesh_limits.h"
#include "mtl_parser.h"
#include "obj_assembly.h"
#include "obj_chunk.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace rtpro {

using ascii::quoted;

namespace fs = std::filesystem;
using namespace obj;

namespace {

// The name under which faces before any usemtl are keyed (usemtl itself needs a name).
constexpr std::string_view kNoUsemtl{};
// The smoothing group of every face in a file without `s` statements.
constexpr std::uint32_t kImplicitSmoothGroup = 1;

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

// Concatenates the per-chunk triangle normal indices in file order, chunks copied in parallel.
std::vector<TriangleIndices> concatenate_normals(std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets) {
  std::vector<TriangleIndices> all;
  resize_large(all, offsets.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t i) {
    std::vector<TriangleIndices>& part = chunks[i].triangle_normals;
    std::copy(part.begin(), part.end(), all.begin() + std::ptrdiff_t(offsets[i]));
    part = {};
  });
  return all;
}

// The triangles in file order. When every `f` line gave exactly one triangle the chunks filled
// `slots` completely and it is the answer; polygons and dropped faces leave gaps or extras, and
// the triangles are gathered into a new array.
std::vector<TriangleIndices> gather_triangles(std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets,
                                              std::vector<TriangleIndices> slots) {
  const bool slots_are_exact = std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) {
    return c.triangles_in_slots == c.counts.faces && c.more_triangles.empty();
  });
  if (slots_are_exact) return slots;
  std::vector<TriangleIndices> all;
  resize_large(all, offsets.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t i) {
    const Chunk& chunk = chunks[i];
    const auto first_slot = slots.begin() + std::ptrdiff_t(chunk.start.faces);
    const auto next = std::copy(first_slot, first_slot + std::ptrdiff_t(chunk.triangles_in_slots),
                                all.begin() + std::ptrdiff_t(offsets[i]));
    std::copy(chunk.more_triangles.begin(), chunk.more_triangles.end(), next);
  });
  return all;
}

// The usemtl and `s` state of every triangle as runs, with materials numbered in first-use order.
struct StitchedState {
  std::vector<TriangleRun> runs;
  std::vector<LocatedName> materials;  // kNoUsemtl for faces before any usemtl
};

StitchedState stitch_state(const std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets) {
  const bool any_smoothing = std::any_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.has_smoothing_statement; });
  struct NamedRun {
    std::size_t first_triangle;
    LocatedName material;
    std::uint32_t smoothing;
  };
  std::vector<NamedRun> named{{0, {kNoUsemtl, 0}, any_smoothing ? kFlat : kImplicitSmoothGroup}};
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    for (const StateChange& change : chunks[c].state_changes) {
      NamedRun run = named.back();
      run.first_triangle = offsets[c] + change.first_triangle;
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

// Resolves an mtllib name against the OBJ's folder, refusing paths that leave it.
fs::path material_library_path(const fs::path& obj_file, const LocatedName& library) {
  const fs::path relative(library.name);
  const SourceLocation where{obj_file.string(), int(library.line)};
  if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
    throw InputError(where, "mtllib path " + quoted(library.name) + " must be relative to the OBJ's folder");
  const fs::path normal = relative.lexically_normal();
  if (normal.empty() || *normal.begin() == "..")
    throw InputError(where, "mtllib path " + quoted(library.name) + " leaves the OBJ's folder");
  return obj_file.parent_path() / normal;
}

std::vector<MaterialDesc> load_materials(const fs::path& file, const std::vector<Chunk>& chunks,
                                         const std::vector<LocatedName>& used, std::vector<std::string>& warnings) {
  std::map<std::string, MaterialDesc, std::less<>> defined;
  std::set<fs::path> loaded;
  for (const Chunk& chunk : chunks) {
    for (const LocatedName& library : chunk.material_libraries) {
      const fs::path path = material_library_path(file, library);
      if (!loaded.insert(path).second) continue;
      std::error_code not_readable;  // e.g. a name over 255 bytes: a warning, not an escaped filesystem_error
      if (!fs::is_regular_file(path, not_readable)) {
        warnings.push_back(located(file.string(), library.line, "material library '" + std::string(library.name) +
                                                                    "' not found; its materials use defaults"));
        continue;
      }
      MaterialLibrary mtl = parse_mtl_file(path);
      for (MaterialDesc& m : mtl.materials) defined.try_emplace(m.name, std::move(m));
      warnings.insert(warnings.end(), mtl.warnings.begin(), mtl.warnings.end());
    }
  }
  std::vector<MaterialDesc> materials;
  for (const LocatedName& use : used) {
    MaterialDesc& m = materials.emplace_back();
    m.name = use.name == kNoUsemtl ? "default" : std::string(use.name);
    if (use.name == kNoUsemtl) continue;
    if (const auto found = defined.find(use.name); found != defined.end()) {
      m = found->second;
    } else {
      warnings.push_back(located(file.string(), use.line, "material '" + m.name + "' is not defined in any material library; using defaults"));
    }
  }
  return materials;
}

void warn_about_ignored_statements(const std::string& file, const std::vector<Chunk>& chunks, std::vector<std::string>& warnings) {
  std::vector<IgnoredKeyword> all;
  for (const Chunk& chunk : chunks) {
    for (const IgnoredKeyword& k : chunk.ignored) {
      const auto same = std::find_if(all.begin(), all.end(), [&](const IgnoredKeyword& a) { return a.keyword == k.keyword; });
      if (same == all.end()) all.push_back(k);
      else same->count += k.count;
    }
  }
  for (const IgnoredKeyword& k : all)
    warnings.push_back(located(file, k.first_line, "ignored " + quoted(k.keyword) + " statements (" + std::to_string(k.count) + " in total)"));
}

// Whether the per-corner vn indices can serve as the mesh's normals; warns when they exist but cannot.
bool use_file_normals(const std::string& file, const std::vector<Chunk>& chunks, const Counts& totals,
                      std::size_t triangles, std::vector<std::string>& warnings) {
  if (totals.normals == 0 || triangles == 0) return false;
  for (const Chunk& chunk : chunks) {
    if (chunk.first_zero_normal_line != 0) {
      warnings.push_back(located(file, chunk.first_zero_normal_line, "vertex normal has zero length; generating normals instead"));
      return false;
    }
  }
  if (std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.every_corner_has_normal; })) return true;
  warnings.push_back(file + ": some face vertices have no normal (vn); generating normals instead");
  return false;
}

}  // namespace

LoadedMesh load_obj_file(const fs::path& file, std::size_t chunk_bytes) {
  const MappedFile bytes(file);
  const std::string file_name = file.string();
  std::vector<Chunk> chunks = split_into_chunks(bytes.text(), chunk_bytes);
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
                       });
  const Destination out{parts.positions.data(), parts.normals.data(), triangle_slots.data(), totals, file_name};
  for_each_chunk(chunks, [&out](Chunk& chunk) { parse_chunk(chunk, out); });
  for (const Chunk& chunk : chunks)
    if (chunk.error) std::rethrow_exception(chunk.error);

  std::vector<std::size_t> offsets{0};
  for (const Chunk& chunk : chunks) offsets.push_back(offsets.back() + chunk.triangle_count());
  if (offsets.back() > kMaxMeshElements) throw InputError(SourceLocation{file_name}, "more than 2^32 - 2 triangles");

  LoadedMesh loaded;
  std::vector<std::string>& warnings = loaded.stats.warnings;
  StitchedState state = stitch_state(chunks, offsets);
  loaded.materials = load_materials(file, chunks, state.materials, warnings);
  if (state.materials.size() == 1 && state.materials.front().name == kNoUsemtl) loaded.materials.clear();
  warn_about_ignored_statements(file_name, chunks, warnings);

  const bool file_normals = use_file_normals(file_name, chunks, totals, offsets.back(), warnings);
  parts.triangle_positions = gather_triangles(chunks, offsets, std::move(triangle_slots));
  if (file_normals) parts.triangle_normals = concatenate_normals(chunks, offsets);
  parts.runs = std::move(state.runs);

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
  }
  if (offsets.back() == 0) warnings.push_back(file_name + ": no faces");
  stats.normals_generated = assemble_mesh(std::move(parts), mesh);
  stats.vertices = mesh.vertices.size();
  stats.triangles = mesh.triangles.size();
  stats.materials = loaded.materials.size();
  return loaded;
}

}  // namespace rtpro
