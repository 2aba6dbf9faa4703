#pragma once
// Image textures, looked up through OpenImageIO's TextureSystem (mip-mapped, filtered, cached).
// OpenImageIO 2.4's TextureSystem has no per-texture colour space, so each texture is decoded
// once, when it is opened: read whole, converted from its colour space to scene-linear through
// OpenColorIO (the bundled config's "sRGB - Texture", or "Linear Rec.709 (sRGB)" for linear
// data), and written as a tiled, mip-mapped float .tx file in a private temporary folder that
// lives as long as the lookup. Shading then reads linear values only.
#include "rtpro/core/texture_sampling.h"
#include "rtpro/core/vec3.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace rtpro {

struct TextureSource {
  std::filesystem::path file;
  std::string colorspace;  // an OpenColorIO colour space of the bundled config
  // When set, the encoded image itself (an image stored inside a glTF); `file` only names it, its
  // extension telling the format.
  const std::vector<unsigned char>* bytes = nullptr;
  // Where the scene named it ("scene.yaml:12:22"), added to messages about it; may be empty.
  std::string named_at{};
};

class TextureLookup {
 public:
  virtual ~TextureLookup() = default;
  // The RGB colour of texture `index` (into the sources it was opened with) at (s, t): s across
  // the image, t down it, both 0 to 1 over the image, wrapped per axis as `sampling` says. Without
  // a footprint the finest level is read, bilinearly filtered or its nearest texel. Safe from any
  // thread.
  virtual Color lookup(std::uint32_t index, float s, float t, const TextureSampling& sampling) const = 0;
};

// Opens every source. Throws InputError naming the file (and where it was named) when one cannot
// be read or decoded, or
// when its decoded floats and texture copies would exceed `max_bytes` (0: the default budget;
// render --max-memory), checked from its header before it is decoded.
std::unique_ptr<TextureLookup> open_textures(std::span<const TextureSource> sources, std::uint64_t max_bytes = 0);

}  // namespace rtpro
