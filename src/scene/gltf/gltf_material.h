#pragma once
// Internals of the glTF loader: glTF's metallic-roughness materials on rtpro's Phong + mirror
// model (the table is in scenes/FORMAT.md). With F0 = mix(0.04, mean(base colour), metallic),
// gloss = (1 - roughness)^2 and the Phong exponent n = 2 / roughness^4 - 2 (the usual match of a
// Beckmann-like lobe of width roughness^2), clamped to [1, 10000]:
//   reflectivity = F0 * gloss                       (only smooth surfaces mirror)
//   color        = base colour * (1 - reflectivity) (what the mirror takes, the diffuse loses)
//   specular     = min(F0 * (n + 2) / 2, 2)         (the normalised lobe's peak), faded to 0 as
//                                                    n falls below 4, like MTL's Ns
//   shininess    = n
// rtpro's reflections are not tinted, so a polished coloured metal loses its colour. The base
// colour texture is kept as a reference (color_texture: the image's path, or
// "<file>#images[N]" for an image stored inside the glTF); alpha goes to opacity.
#include "rtpro/scene/description.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::gltf {

MaterialDesc read_material(const tinygltf::Model& model, int material, const std::filesystem::path& file,
                           std::vector<std::string>& warnings);

}  // namespace rtpro::gltf
