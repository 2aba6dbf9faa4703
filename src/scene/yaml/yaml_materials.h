#pragma once
// Reads the scene file's `materials:` (see scenes/FORMAT.md): a mapping of name to material, each
// kind with its own keys, colours plain, checkered or from an image texture.
#include "rtpro/scene/description.h"
#include "yaml_document.h"

#include <filesystem>
#include <vector>

namespace rtpro {

// The materials in file order after "default" (always first, replaced when the file defines one);
// texture paths are relative to `folder`. An entry named like one of `model_materials` (a model
// file's, read as the whole scene) is read over that material, changing only the keys it gives,
// and is not added.
std::vector<MaterialDesc> read_materials(const YamlNode* node, const std::filesystem::path& folder,
                                         std::vector<MaterialDesc>* model_materials = nullptr);

}  // namespace rtpro
