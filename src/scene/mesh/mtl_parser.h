#pragma once
// Wavefront MTL material libraries, mapped onto rtpro's Phong materials (scenes/FORMAT.md has the
// table):
// - Kd: colour. Ks: highlight weight, the mean of its components. Ns: the Phong exponent, at
//   least 1; below kFullHighlightNs the highlight weight fades with Ns to nothing at Ns 0, because
//   an exponent near 0 is no highlight but a second, view-independent diffuse layer of Ks (3ds
//   Max writes `Ns 0` with strong Ks, which turned whole objects white).
// - d (dissolve) or Tr (1 - d): MaterialDesc::opacity, kept but not rendered (a warning when < 1).
// - map_Kd: MaterialDesc::color_texture, resolved against the MTL's folder (the last word of the
//   statement; options before it are skipped); kept for texturing, not rendered yet. A path that
//   is absolute or leaves the folder is dropped with a warning.
// - Ni (index of refraction), Ka, Ke, illum and other map_* are read by other renderers but have
//   no counterpart here: ignored with one warning per keyword, like unknown statements.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

// Ns from which the highlight keeps its full Ks weight.
inline constexpr float kFullHighlightNs = 4.0f;

struct MaterialLibrary {
  std::vector<MaterialDesc> materials;  // in file order; a repeated newmtl name keeps the first
  std::vector<std::string> warnings;    // "file:line: ..." lines
};

// Throws InputError naming file:line:column for malformed statements.
MaterialLibrary parse_mtl_file(const std::filesystem::path& file);

}  // namespace rtpro
