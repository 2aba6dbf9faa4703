#pragma once
// Reading a command's scene, the same for `render`, `info` and `crosscheck`: the scene file (or
// standard input) with the command line's overrides applied, its up-front memory estimate checked
// against the budget before anything large is allocated, then the render scene built.
#include "log.h"
#include "memory_option.h"
#include "scene_overrides.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/render_scene.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rtpro::cli {

struct SceneLoad {
  std::string file;                      // or "-" for a YAML scene on standard input
  std::vector<SceneOverride> overrides;  // in command-line order
  MemoryBudget memory;
  int extra_channels = 0;  // AOV channels the render keeps beyond R, G, B
  // The window a render draws, refused before the estimate when it does not fit the camera;
  // `region_text` is how the command line spelled it, for the message.
  std::optional<PixelRegion> region = std::nullopt;
  std::string region_text = {};
  bool compact_normals = false;       // --compact-normals: SceneBuildOptions::compact_normals
  std::uint32_t piece_triangles = 0;  // --embree-pieces: SceneBuildOptions::piece_triangles
};

struct LoadedScene {
  SceneDescription description;
  RenderCost cost;
  SceneBuildReport report;
  RenderScene scene;
};

// Throws InputError for a scene or override in error (an override's error names its flag), a
// region outside the image, or an estimate over the budget. With a log, says the estimate at
// verbose level before the build, and after it what rtpro chose for a model file (its notes) and
// a warning when nothing lights the scene.
// `check_description`, when given, sees the parsed description before anything large is loaded
// (meshes, textures, the environment): a refusal it throws costs no loading.
LoadedScene load_scene(const SceneLoad& load, Log* log = nullptr,
                       const std::function<void(const SceneDescription&)>& check_description = {});

}  // namespace rtpro::cli
