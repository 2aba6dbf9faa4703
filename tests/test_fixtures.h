#pragma once
// Small fixtures several test files share.
#include "rtpro/core/error.h"
#include "rtpro/image/image.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/scene/render_scene.h"

#include <filesystem>
#include <memory>

namespace rtpro::test {

// An RGB image whose every pixel and channel differs: 0.1·x + 0.01·y + 0.3·c.
Image gradient_image(int width, int height);

// The InputError load_mesh_file throws for `file`; records a test failure if none is thrown.
InputError mesh_load_error(const std::filesystem::path& file);

// The scene's image textures, opened as rtpro render opens them; null when it has none.
std::unique_ptr<TextureLookup> open_scene_textures(const RenderScene& scene);

}  // namespace rtpro::test
