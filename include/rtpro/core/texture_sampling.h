#pragma once
// How an image texture is read: what it shows outside [0, 1] along each axis, and whether a
// lookup blends the four nearest texels or takes the nearest one (pixel art, glTF's NEAREST).
// Shared by the scene description, the render scene and the image layer's lookups.
#include "rtpro/core/texture_wrap.h"

namespace rtpro {

enum class TextureFilter { kLinear, kNearest };

struct TextureSampling {
  TextureWrap wrap_s = TextureWrap::kRepeat;  // across the image (u)
  TextureWrap wrap_t = TextureWrap::kRepeat;  // down the image (v)
  TextureFilter filter = TextureFilter::kLinear;
  bool operator==(const TextureSampling&) const = default;
};

}  // namespace rtpro
