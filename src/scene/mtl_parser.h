#pragma once
// Wavefront MTL material libraries, as far as rtpro's Phong materials go: newmtl, Kd (colour),
// Ks (specular weight: the mean of its three components), Ns (shininess). Other statements are
// ignored with one warning per keyword.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

struct MaterialLibrary {
  std::vector<MaterialDesc> materials;  // in file order; a repeated newmtl name keeps the first
  std::vector<std::string> warnings;    // "file:line: ..." lines
};

// Throws InputError naming file:line:column for malformed statements.
MaterialLibrary parse_mtl_file(const std::filesystem::path& file);

}  // namespace rtpro
