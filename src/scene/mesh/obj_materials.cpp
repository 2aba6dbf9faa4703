#include "obj_materials.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "mtl_parser.h"
#include "path_containment.h"

#include <map>
#include <set>

namespace rtpro::obj {

namespace fs = std::filesystem;

namespace {

std::string located(const std::string& file, std::uint64_t line, const std::string& message) {
  return file + ":" + std::to_string(line) + ": " + message;
}

// Resolves an mtllib name against the OBJ's folder, refusing paths that leave it, by name or
// through a symbolic link.
fs::path material_library_path(const fs::path& obj_file, const LocatedName& library) {
  const fs::path relative(library.name);
  const SourceLocation where{obj_file.string(), int(library.line)};
  if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
    throw InputError(where, "mtllib path " + ascii::quoted(library.name) + " must be relative to the OBJ's folder");
  const fs::path normal = relative.lexically_normal();
  if (normal.empty() || *normal.begin() == "..")
    throw InputError(where, "mtllib path " + ascii::quoted(library.name) + " leaves the OBJ's folder");
  const fs::path path = obj_file.parent_path() / normal;
  if (!resolves_inside(obj_file.parent_path(), path))
    throw InputError(where, "mtllib path " + ascii::quoted(library.name) +
                                " leads outside the OBJ's folder (through a symbolic link)");
  return path;
}

}  // namespace

std::vector<MaterialDesc> load_obj_materials(const fs::path& file, const std::vector<Chunk>& chunks,
                                             const std::vector<LocatedName>& used, MeshLoadStats& stats) {
  std::vector<std::string>& warnings = stats.warnings;
  std::map<std::string, MaterialDesc, std::less<>> defined;
  std::set<fs::path> loaded;
  for (const Chunk& chunk : chunks) {
    for (const LocatedName& library : chunk.material_libraries) {
      const fs::path path = material_library_path(file, library);
      if (!loaded.insert(path).second) continue;
      std::error_code not_readable;  // e.g. a name over 255 bytes: a warning, not an escaped filesystem_error
      if (!fs::is_regular_file(path, not_readable)) {
        warnings.push_back(
            located(file.string(), library.line,
                    "material library " + ascii::quoted(library.name) + " not found; its materials use defaults"));
        continue;
      }
      MaterialLibrary mtl = parse_mtl_file(path);
      stats.files_read.push_back(path);
      for (MaterialDesc& m : mtl.materials) defined.try_emplace(m.name, std::move(m));
      warnings.insert(warnings.end(), mtl.warnings.begin(), mtl.warnings.end());
    }
  }
  std::vector<MaterialDesc> materials;
  for (const LocatedName& use : used) {
    MaterialDesc& m = materials.emplace_back();
    m.name = use.name.empty() ? "default" : std::string(use.name);
    if (use.name.empty()) continue;
    if (const auto found = defined.find(use.name); found != defined.end()) {
      m = found->second;
    } else {
      warnings.push_back(
          located(file.string(), use.line,
                  "material " + ascii::quoted(m.name) + " is not defined in any material library; using defaults"));
    }
  }
  return materials;
}

}  // namespace rtpro::obj
