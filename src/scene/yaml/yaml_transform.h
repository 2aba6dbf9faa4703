#pragma once
// Reads an instance's `transform:` (see scenes/FORMAT.md): a mapping of translate/rotate/scale
// applied as scale, then rotate, then translate; a mapping with a row-major 4×4 `matrix`; or a
// list of single-key steps applied in order.
#include "rtpro/core/transform.h"
#include "yaml_document.h"

#include <string>

namespace rtpro {

// A rotation: Euler angles [x, y, z] in degrees (about x, then y, then z) or {axis, angle}.
Affine read_rotation(const YamlNode& node, const std::string& name);

// Rejects singular, ill-conditioned, non-finite and out-of-range results at `node`.
Affine read_transform(const YamlNode& node, const std::string& name);

}  // namespace rtpro
