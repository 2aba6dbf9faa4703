#pragma once
// Internals of the OBJ loader: the MTL libraries an OBJ names (mtllib) and the materials its
// faces use (usemtl), resolved to MaterialDescs.
#include "rtpro/scene/description.h"
#include "rtpro/scene/mesh_loader.h"
#include "obj_chunk.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::obj {

// One MaterialDesc per entry of `used` (in that order): an empty name is the default material,
// a name no library defines gets the defaults with a warning. mtllib paths must stay inside the
// OBJ's folder, by name and through symbolic links (an InputError otherwise); a missing library
// is a warning (in stats.warnings); each library read is added to stats.files_read.
std::vector<MaterialDesc> load_obj_materials(const std::filesystem::path& obj_file, const std::vector<Chunk>& chunks,
                                             const std::vector<LocatedName>& used, MeshLoadStats& stats);

}  // namespace rtpro::obj
