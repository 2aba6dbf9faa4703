#pragma once
// Reads an instance's `transform:` (see scenes/FORMAT.md): a mapping of translate/rotate/scale
// applied as scale, then rotate, then translate; a mapping with a row-major 4×4 `matrix`; or a
// list of single-key steps applied in order.
#include "rtpro/core/transform.h"
#include "yaml_document.h"

#include <string>

namespace rtpro {

// Rejects singular, ill-conditioned, non-finite and out-of-range results at `node`.
Affine read_transform(const YamlNode& node, const std::string& name);

}  // namespace rtpro
