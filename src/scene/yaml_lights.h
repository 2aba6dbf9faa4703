#pragma once
// Reads the scene file's `lights:` (see scenes/FORMAT.md): point, spot, directional, sphere and
// quad lights, each value checked where it is written.
#include "rtpro/scene/description.h"
#include "yaml_document.h"

#include <vector>

namespace rtpro {

// None when `node` is absent or null.
std::vector<LightDesc> read_lights(const YamlNode* node);

}  // namespace rtpro
