#include "material_textures.h"

#include "rtpro/core/error.h"
#include "rtpro/core/special_file_kind.h"

#include <filesystem>
#include <string>

namespace rtpro {

namespace {

// The index of an image in `textures`, each file and colour space registered once.
std::uint32_t texture_index(const std::filesystem::path& file, const std::string& colorspace,
                            const std::shared_ptr<const std::vector<unsigned char>>& bytes, const SourceLocation& where,
                            std::vector<TextureImage>& textures) {
  if (const std::string problem = bytes ? std::string() : unreadable_file_problem(file); !problem.empty())
    throw InputError(where, "texture '" + file.string() + "' " + problem);
  std::uint32_t index = 0;
  while (index < textures.size() && !(textures[index].file == file && textures[index].colorspace == colorspace))
    ++index;
  if (index == textures.size()) textures.push_back({file, colorspace, bytes, where});
  return index;
}

}  // namespace

std::optional<ImageTexture> slot_texture(const std::optional<TextureSlotDesc>& slot, const Color& tint,
                                         std::vector<TextureImage>& textures) {
  if (!slot) return std::nullopt;
  return ImageTexture{texture_index(slot->file, slot->colorspace, slot->bytes, slot->where, textures), tint,
                      slot->sampling};
}

ColorTexture color_texture(const MaterialDesc& m, const Color& color, std::vector<TextureImage>& textures) {
  if (!m.color_texture.empty())
    return ImageTexture{
        texture_index(m.color_texture, m.texture_colorspace, m.texture_bytes, m.texture_where, textures), color,
        m.texture_sampling};
  if (!m.checker) return color;
  CheckerTexture checker;
  checker.inv_size = 1.0f / m.checker->size;
  checker.even = m.checker->even;
  checker.odd = m.checker->odd;
  checker.axes = m.checker->axes;
  return checker;
}

}  // namespace rtpro
