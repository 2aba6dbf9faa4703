#include "test_fixtures.h"

#include "rtpro/scene/mesh_loader.h"

#include <gtest/gtest.h>

namespace rtpro::test {

Image gradient_image(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = 0.1f * x + 0.01f * y + 0.3f * c;
  return image;
}

InputError mesh_load_error(const std::filesystem::path& file) {
  try {
    load_mesh_file(file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << file;
  return InputError("none");
}

std::unique_ptr<TextureLookup> open_scene_textures(const RenderScene& scene) {
  if (scene.textures.empty()) return nullptr;
  std::vector<TextureSource> sources;
  for (const TextureImage& texture : scene.textures)
    sources.push_back({texture.file, texture.colorspace, texture.bytes.get()});
  return open_textures(sources);
}

}  // namespace rtpro::test
