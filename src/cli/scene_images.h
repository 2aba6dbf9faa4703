#pragma once
// The images a scene renders from, made ready before its render: image textures decoded to linear
// .tx copies, and the environment's image read whole with its sampling distribution built.
#include "log.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace rtpro::cli {

struct SceneImages {
  std::unique_ptr<TextureLookup> textures;      // null without image textures
  std::optional<EnvironmentLight> environment;  // empty without an environment
};

// Reads through the image layer (waiting for its load); `memory_bytes` bounds the environment's
// image and each image texture with its copies. Logs the counts and times at verbose level.
SceneImages open_scene_images(const RenderScene& scene, std::uint64_t memory_bytes, Log& log);

}  // namespace rtpro::cli
