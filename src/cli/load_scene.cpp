#include "load_scene.h"

#include "pixel_region_option.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/scene/scene_lighting.h"
#include "rtpro/scene/unused_settings.h"
#include "rtpro/image/image_io.h"
#include "rtpro/image/image_size.h"
#include "rtpro/render/environment_light.h"

namespace rtpro::cli {

namespace {

// The environment's image, from its header: a small run-length encoded file can declare gigabytes.
void add_environment_image(RenderCost& cost, const SceneDescription& scene) {
  if (!scene.environment || scene.environment->file.empty()) return;
  const ImageSize size = read_image_size(scene.environment->file);
  add_environment_cost(cost, scene.environment->file, size.width, size.height,
                       EnvironmentLight::peak_bytes(size.width, size.height, size.channels));
}

// Subdivision surfaces are made while the scene is built: they may take what the estimate left of
// the budget, and read their displacement textures through the image layer. Grids may take what
// the estimate counted for them, from their files' statistics, and what it left.
SceneBuildOptions build_options(const SceneLoad& load, const RenderCost& cost) {
  const MemoryBudget& memory = load.memory;
  SceneBuildOptions options;
  options.compact_normals = load.compact_normals;
  options.piece_triangles = load.piece_triangles;
  options.geometry_budget =
      std::max<std::uint64_t>(memory.bytes > cost.total_bytes ? memory.bytes - cost.total_bytes : 0, 1);
  const std::uint64_t left = memory.bytes > cost.total_bytes ? memory.bytes - cost.total_bytes : 0;
  options.volume_budget = std::max<std::uint64_t>(saturating_add(cost.volume_bytes, left), 1);
  options.budget_source = memory.source;
  options.read_scalar_image = [](const std::filesystem::path& file, std::uint64_t max_bytes) {
    const Image image = read_image(file, max_bytes);
    ScalarImage scalar{image.width, image.height, {}};
    if (image.width <= 0 || image.height <= 0 || image.channel_count() == 0)
      throw InputError(SourceLocation{file.string()}, "the image has no pixels");
    scalar.values.reserve(std::size_t(image.width) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) scalar.values.push_back(image.at(x, y, 0));
    return scalar;
  };
  return options;
}

}  // namespace

LoadedScene load_scene(const SceneLoad& load, Log* log,
                       const std::function<void(const SceneDescription&)>& check_description) {
  LoadedScene loaded;
  loaded.description = parse_with_overrides(load.file, load.overrides);
  if (check_description) check_description(loaded.description);
  const CameraDesc& camera = loaded.description.camera;
  check_region_fits(load.region, load.region_text, camera.width, camera.height);
  // Refused before anything large is allocated: image buffers, flattened instances, meshes.
  loaded.cost = estimate_render_cost(loaded.description, load.extra_channels);
  add_environment_image(loaded.cost, loaded.description);
  check_render_cost(loaded.cost, load.memory.bytes, load.memory.source, load.file);
  if (log)
    log->verbose("estimated memory: " + format_bytes(loaded.cost.total_bytes) + " of a budget of " +
                 format_bytes(load.memory.bytes));
  // A model read while the scene was parsed moves into the render scene: a copy would double the
  // mesh's memory while the BVH is built.
  loaded.scene = build_render_scene_taking_models(loaded.description, &loaded.report, build_options(load, loaded.cost));
  if (log) {
    for (const std::string& note : loaded.description.notes) log->info(note);
    if (const auto warning = unlit_scene_warning(loaded.scene)) log->warning(*warning);
    if (const auto warning = ignored_path_controls_warning(loaded.scene.render)) log->warning(*warning);
  }
  return loaded;
}

}  // namespace rtpro::cli
