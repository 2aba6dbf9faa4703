#pragma once
// A material's images registered in the render scene's list of textures, each file and colour
// space once, as they are met: for the colour every kind has and for the images a kind reads of
// its own (scene/principled_material.h).
#include "rtpro/scene/description.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace rtpro {

std::optional<ImageTexture> slot_texture(const std::optional<TextureSlotDesc>& slot, const Color& tint,
                                         std::vector<TextureImage>& textures);
// The material's diffuse colour as shading evaluates it, `color` in place of the material's own
// (a constant, or the tint of its image).
ColorTexture color_texture(const MaterialDesc& m, const Color& color, std::vector<TextureImage>& textures);

}  // namespace rtpro
