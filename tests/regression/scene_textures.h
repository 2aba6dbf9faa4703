#pragma once
// The image textures and environment of a regression scene, opened as `rtpro render` opens them. Header-only and
// here, not in the shared test support: a test binary that also links the executable's image
// loader would otherwise take open_textures from it.
#include "rtpro/image/image_io.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/scene/render_scene.h"

#include <memory>
#include <optional>
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

// Nothing when the scene has no environment.
inline std::optional<EnvironmentLight> build_scene_environment(const RenderScene& scene) {
  if (!scene.environment) return std::nullopt;
  Image image;
  if (!scene.environment->file.empty()) image = read_image(scene.environment->file);
  return std::optional<EnvironmentLight>(std::in_place, *scene.environment, std::move(image),
                                         environment_sampling_for(scene.render));
}

}  // namespace rtpro::regression
