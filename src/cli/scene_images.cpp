#include "scene_images.h"

#include "rtpro/core/memory_budget.h"
#include "rtpro/image/image_io.h"

#include <chrono>
#include <string>
#include <vector>

namespace rtpro::cli {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SceneImages open_scene_images(const RenderScene& scene, std::uint64_t memory_bytes, Log& log) {
  SceneImages images;
  if (!scene.textures.empty()) {
    std::vector<TextureSource> sources;
    for (const TextureImage& texture : scene.textures)
      sources.push_back({texture.file, texture.colorspace, texture.bytes.get(), texture.where.str()});
    // Each texture's decoded floats and copies count against the render's budget (--max-memory)
    // from its header, before it is decoded.
    images.textures = open_textures(sources, memory_bytes);
    log.verbose("opened " + std::to_string(sources.size()) + " image textures");
  }
  if (scene.environment) {
    Image image;
    if (!scene.environment->file.empty()) {
      const auto read_start = std::chrono::steady_clock::now();
      image = read_image(scene.environment->file, memory_bytes);
      check_environment_radiance(image, *scene.environment);
      log.verbose("read " + scene.environment->file.string() + " (" + std::to_string(image.width) + "x" +
                  std::to_string(image.height) + ") in " + std::to_string(seconds_since(read_start)) + " s");
    }
    const auto build_start = std::chrono::steady_clock::now();
    images.environment.emplace(*scene.environment, std::move(image), environment_sampling_for(scene.render));
    log.verbose("built the environment light in " + std::to_string(seconds_since(build_start)) + " s (" +
                format_bytes(images.environment->bytes()) + ")");
  }
  return images;
}

}  // namespace rtpro::cli
