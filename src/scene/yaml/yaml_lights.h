#pragma once
// Reads the scene file's `lights:` (see scenes/FORMAT.md): point, spot, directional, sphere and
// quad lights, each value checked where it is written.
#include "rtpro/scene/description.h"
#include "yaml_document.h"

#include <string>
#include <vector>

namespace rtpro {

// None when `node` is absent or null. `names`: one per light, its `name:` (empty without one).
void read_lights(const YamlNode* node, std::vector<LightDesc>& lights, std::vector<std::string>& names);

}  // namespace rtpro
