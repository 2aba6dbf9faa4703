#pragma once
// Cem Yuksel's .hair format (the groom exchange file: www.cemyuksel.com/research/hairmodels):
// a 128-byte header ("HAIR", strand count, point count, which arrays follow, their defaults, 88
// bytes of text), then the arrays in order: segments per strand (uint16), points (3 floats),
// thickness, transparency (a float each) and colour (3 floats) per point. Little-endian.
#include "rtpro/scene/curve_geometry.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rtpro {

struct HairFile {
  std::vector<CurvePoint> points;            // radius: half the file's thickness (a diameter)
  std::vector<std::uint32_t> strand_points;  // points per strand, strand after strand
  std::vector<Color> colors;                 // per point, when the file has them
};

// Throws InputError naming the file and what is wrong: a short file or truncated arrays (the
// counts the header declares are checked against the file's size before anything is allocated),
// counts that disagree, non-finite or huge coordinates, zero, negative or NaN thickness.
HairFile read_hair_file(const std::filesystem::path& file);

}  // namespace rtpro
