#pragma once
// Reads the scene file's `environment:` (see scenes/FORMAT.md): a latitude-longitude image or a
// constant colour, its intensity, rotation and whether the camera sees it.
#include "rtpro/scene/description.h"
#include "yaml_document.h"

#include <filesystem>
#include <optional>

namespace rtpro {

// Nothing when `node` is absent or null. `folder` is where a relative file name is looked up.
std::optional<EnvironmentDesc> read_environment(const YamlNode* node, const std::filesystem::path& folder);

}  // namespace rtpro
