#pragma once
// The image textures of a regression scene, opened as `rtpro render` opens them. Header-only and
// here, not in the shared test support: a test binary that also links the executable's image
// loader would otherwise take open_textures from it.
#include "rtpro/image/texture_lookup.h"
#include "rtpro/scene/render_scene.h"

#include <memory>
#include <vector>

namespace rtpro::regression {

// Null when the scene has none.
inline std::unique_ptr<TextureLookup> open_scene_textures(const RenderScene& scene) {
  if (scene.textures.empty()) return nullptr;
  std::vector<TextureSource> sources;
  for (const TextureImage& texture : scene.textures)
    sources.push_back({texture.file, texture.colorspace, texture.bytes.get()});
  return open_textures(sources);
}

}  // namespace rtpro::regression
