#pragma once
// Renders one tile: generates its camera samples, shades them in batches of whole pixels with the
// scene's integrator (whitted: shading.h; path: path_integrator.h) and resolves each pixel's samples, in sample order, into the tile's film layout.
#include "rtpro/backend/backend.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/film.h"
#include "rtpro/render/light_set.h"
#include "rtpro/render/path_integrator.h"
#include "rtpro/render/sampler.h"
#include "rtpro/render/shading.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/render_scene.h"

#include <optional>
#include <vector>

namespace rtpro {

class TileRenderer {
 public:
  // The buffers one worker thread reuses from tile to tile.
  struct Workspace {
    std::vector<Ray> camera_rays;
    std::vector<SampleKey> sample_keys;
    std::vector<PixelOffset> pixel_offsets;  // one pixel's, spp of them
    std::vector<SampleResult> samples;
    ShadingWorkspace shading;
    PathWorkspace paths;
  };

  // `textures`: the scene's image textures, opened (open_textures); required when it has any.
  // `environment`: the scene's environment, built from its image; required when it has one.
  TileRenderer(const RenderScene& scene, const Backend& backend, const FilmLayout& layout,
               const TextureLookup* textures = nullptr, const EnvironmentLight* environment = nullptr);

  TileResult render(std::size_t index, const PixelRegion& tile, Workspace& workspace) const;

  const FilmLayout& layout() const { return layout_; }

 private:
  void render_pixels(const PixelRegion& tile, std::size_t first_pixel, std::size_t pixel_count, TileResult& out,
                     Workspace& ws) const;

  const RenderScene& scene_;
  const Backend& backend_;
  const FilmLayout& layout_;
  const TextureLookup* textures_;
  const EnvironmentLight* environment_;
  StratifiedSampler sampler_;
  SobolSampler sobol_;
  std::size_t pixels_per_batch_;
  std::optional<LightSet> path_lights_;  // built for the path integrator only
};

}  // namespace rtpro
