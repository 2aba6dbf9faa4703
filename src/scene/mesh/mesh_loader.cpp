#include "rtpro/scene/mesh_loader.h"

#include "rtpro/core/error.h"
#include "obj_parser.h"
#include "ply_parser.h"

#include <algorithm>
#include <cctype>

namespace rtpro {

LoadedMesh load_mesh_file(const std::filesystem::path& file, const MeshLoadOptions& options) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".obj") return load_obj_file(file, options);
  if (extension == ".ply") return load_ply_file(file, options);
  throw InputError(SourceLocation{file.string()}, "unsupported mesh format '" + extension + "': use .obj or .ply");
}

}  // namespace rtpro
