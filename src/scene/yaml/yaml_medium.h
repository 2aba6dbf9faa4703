#pragma once
// Reads a medium (scenes/FORMAT.md, "Media"): a material's or an entry's `interior:` and the
// scene's `medium:`.
#include "rtpro/scene/medium_kinds.h"
#include "yaml_document.h"

#include <string>

namespace rtpro {

// {sigma_a: [r, g, b], sigma_s: [r, g, b], anisotropy: g, emission: [r, g, b]}, or the albedo and
// extinction as {color: [r, g, b], density: d, ...}; `type: homogeneous` may be said. `name`
// names the mapping in messages ("material 'juice'.interior").
Medium read_medium(const YamlNode& node, const std::string& name);

}  // namespace rtpro
