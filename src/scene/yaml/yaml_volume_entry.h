#pragma once
// Reads a world entry `{type: volume, file: F.vdb, ...}` (scenes/FORMAT.md, "Volumes").
#include "rtpro/scene/volume_desc.h"
#include "yaml_document.h"

#include <filesystem>

namespace rtpro {

// `folder` resolves a file named by a value no file wrote (--set). The file must exist and end in
// .vdb; its grids are read when the scene is built.
VolumeDesc read_volume_entry(const YamlNode& node, const std::filesystem::path& folder);

}  // namespace rtpro
