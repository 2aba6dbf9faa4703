#include "rtpro/render/tile_renderer.h"

#include "camera_samplers.h"
#include "integrator.h"
#include "rtpro/core/append_ray.h"
#include "rtpro/core/avx2_clones.h"
#include "rtpro/render/camera.h"
#include "sample_dimensions.h"

#include <algorithm>
#include <stdexcept>

namespace rtpro {

namespace {

// Samples shaded together. Large enough for the backends to trace whole batches (streams, packets)
// and to amortise each generation's bookkeeping, small enough that a batch's rays, hits and
// surfaces stay in the L2 cache.
constexpr std::size_t kSamplesPerBatch = 1024;
// A tile's pixels go in blocks of 4×4: at one or two samples a pixel, the 32 camera rays Embree
// traces as one coherent stream then cover 8×4 or 4×4 pixels, and its packets of eight 4×2, where
// rows of a 32-pixel tile gave it 32×1 strips (the dragon's 1-spp frame: 77.8 → 67 ms). Each ray's
// answer is the ray's alone, so the order changes no image.
constexpr int kBlockSide = 4;

}  // namespace

struct TileRenderer::Integration {
  Integration(const RenderScene& scene, const Backend& backend, const TextureLookup* textures,
              const EnvironmentLight* environment, const SumLayout& sums)
      : samplers(scene.render), integrator(make_integrator(scene, {backend, samplers, textures, environment,
                                                                   !sums.keeps_color_only(), sums.keeps_motion()})),
        still_camera(scene.camera) {
    still_camera.pose_steps.clear();
  }
  CameraSamplers samplers;
  SceneIntegrator integrator;
  // The scene's camera without its motion: a moving camera's samples copy it (no allocation) and
  // pose the copy at their time.
  RenderCamera still_camera;
};

struct TileRenderer::Workspace::IntegratorBuffers {
  IntegratorWorkspaces workspaces;
};

TileRenderer::Workspace::Workspace() : integrator(std::make_unique<IntegratorBuffers>()) {}
TileRenderer::Workspace::~Workspace() = default;
TileRenderer::Workspace::Workspace(Workspace&&) noexcept = default;
TileRenderer::Workspace& TileRenderer::Workspace::operator=(Workspace&&) noexcept = default;

PassSchedule render_passes(const RenderScene& scene) { return PassSchedule(scene.render.spp, scene.render.sampler); }

TileGrid render_grid(const RenderScene& scene, const PixelRegion& region, int tile_size) {
  return TileGrid(region, tile_size, render_passes(scene).passes());
}

TileRenderer::TileRenderer(const RenderScene& scene, const Backend& backend, const TileGrid& grid,
                           const SumLayout& sums, const TextureLookup* textures, const EnvironmentLight* environment)
    : scene_(scene), backend_(backend), grid_(grid), sums_(sums), schedule_(render_passes(scene)) {
  if (grid.passes() != schedule_.passes())
    throw std::logic_error("TileRenderer: the grid's passes are not the scene's pass schedule");
  if (scene.environment && !environment)
    throw std::logic_error("TileRenderer: the scene has an environment but none was built for it");
  if (!scene.textures.empty() && !textures)
    throw std::logic_error("TileRenderer: the scene has image textures but none were opened for it");
  integration_ = std::make_unique<const Integration>(scene, backend, textures, environment, sums);
}

TileRenderer::~TileRenderer() = default;

// The listed pixels of a tile, samples `range` of each.
RTPRO_AVX2_CLONES
void TileRenderer::render_pixels(SampleRange range, const Workspace::TilePixel* pixels, std::size_t pixel_count,
                                 TileResult& out, Workspace& ws) const {
  const StratifiedSampler& sampler = integration_->samplers.stratified();
  const SobolSampler& sobol = integration_->samplers.sobol();
  const int per_pixel = range.count();
  const auto image_width = static_cast<std::uint64_t>(scene_.camera.width);
  const RenderCamera& camera = scene_.camera;
  const bool lensless = camera.lens_radius == 0.0f;
  const bool pinhole = lensless && !camera.orthographic && !camera.moving();
  // Sized once per batch and written in place (a resize to the same size does nothing).
  ws.camera_rays.resize(pixel_count * static_cast<std::size_t>(per_pixel));
  ws.sample_keys.resize(ws.camera_rays.size());
  const auto key_of_pixel = [&](std::size_t i) {
    return static_cast<std::uint64_t>(pixels[i].y) * image_width + static_cast<std::uint64_t>(pixels[i].x);
  };
  ws.pixel_keys.resize(pixel_count);
  std::size_t key = 0;
  for (std::size_t i = 0; i < pixel_count; ++i) {
    // Out of the loop by hand: the keys' int stores may alias the pixel coordinates, so the
    // compiler would load them again for every sample.
    const std::uint64_t pixel_key = key_of_pixel(i);
    ws.pixel_keys[i] = pixel_key;
    for (int s = range.begin; s < range.end; ++s) ws.sample_keys[key++] = {pixel_key, s};
  }
  // Every sample's pixel offset in one batch (the same values as pixel_offset, bit for bit), whose
  // hashes run side by side.
  ws.pixel_offsets.resize(ws.sample_keys.size());
  switch (scene_.render.sampler) {
    case SamplerKind::kStratified:
      sampler.pixel_offsets(ws.pixel_keys, range.begin, per_pixel, ws.pixel_offsets);
      break;
    case SamplerKind::kSobol: sobol.sample_2d(ws.sample_keys, sample_dimension::kPixel, ws.pixel_offsets); break;
  }
  const PixelOffset* offsets = ws.pixel_offsets.data();
  ws.camera_times.clear();
  if (camera.shutter.is_open()) {
    // The time stratified as the sampler stratifies a dimension, then spread as the shutter
    // exposes (uniform for a box).
    ws.camera_times.resize(ws.sample_keys.size());
    switch (scene_.render.sampler) {
      case SamplerKind::kStratified: sampler.sample_1d(ws.sample_keys, sample_dimension::kTime, ws.camera_times); break;
      case SamplerKind::kSobol: sobol.sample_1d(ws.sample_keys, sample_dimension::kTime, ws.camera_times); break;
    }
    if (!camera.shutter.is_box())
      for (float& time : ws.camera_times) time = shutter_time(camera.shutter, time);
  }
  std::size_t next = 0;
  if (pinhole) {
    // Every sample's film point first, then the rays four at a time across pixels (camera_ray's
    // rays, bit for bit): at one sample per pixel a pixel alone has no four rays to share a
    // normalisation's square root and divisions.
    ws.film_x.resize(ws.camera_rays.size());
    ws.film_y.resize(ws.camera_rays.size());
    for (std::size_t i = 0; i < pixel_count; ++i) {
      const auto x = static_cast<float>(pixels[i].x);
      const auto y = static_cast<float>(pixels[i].y);
      for (int s = range.begin; s < range.end; ++s, ++next) {
        ws.film_x[next] = x + offsets[next].x;
        ws.film_y[next] = y + offsets[next].y;
      }
    }
    std::size_t k = 0;
    for (; k + 4 <= next; k += 4) pinhole_rays4(camera, &ws.film_x[k], &ws.film_y[k], &ws.camera_rays[k]);
    for (; k < next; ++k) copy_ray(camera_ray(camera, ws.film_x[k], ws.film_y[k], {0.5f, 0.5f}), ws.camera_rays[k]);
  } else {
    RenderCamera posed = integration_->still_camera;  // a moving camera's, at each sample's time
    for (std::size_t i = 0; i < pixel_count; ++i) {
      const int x = pixels[i].x;
      const int y = pixels[i].y;
      const std::uint64_t pixel_key = key_of_pixel(i);
      for (int s = range.begin; s < range.end; ++s, ++next) {
        const PixelOffset& offset = offsets[next];
        const Sample2D lens = lensless ? Sample2D{0.5f, 0.5f}
                              : scene_.render.sampler == SamplerKind::kStratified
                                  ? sampler.sample_2d(pixel_key, s, sample_dimension::kLens)
                                  : sobol.sample_2d(pixel_key, s, sample_dimension::kLens);
        if (camera.moving()) set_pose(posed, camera_pose_at(camera, ws.camera_times[next]));
        copy_ray(camera_ray(camera.moving() ? posed : camera, static_cast<float>(x) + offset.x,
                            static_cast<float>(y) + offset.y, lens),
                 ws.camera_rays[next]);
      }
    }
  }
  ws.samples.resize(ws.camera_rays.size());
  trace(integration_->integrator, {ws.camera_rays, ws.sample_keys, ws.samples, ws.camera_times}, out.rays,
        ws.integrator->workspaces);

  const bool color_only = sums_.keeps_color_only();
  for (std::size_t i = 0; i < pixel_count; ++i) {
    float* pixel_sums =
        out.pixels.data() + static_cast<std::size_t>(pixels[i].index) * static_cast<std::size_t>(sums_.floats());
    SampleResult* pixel_samples = &ws.samples[i * static_cast<std::size_t>(per_pixel)];
    for (int k = 0; k < per_pixel; ++k)
      if (!is_finite(pixel_samples[k].radiance)) {
        ++out.nan_samples;
        pixel_samples[k].radiance = Color(0.0f);
      }
    // The colour is summed the same way either way; the other sums cost a fifth of the Whitted
    // demo's sample loop when nothing reads them, and the whole accumulator's zeroing a tenth of
    // a one-sample frame's.
    if (color_only) {
      Color radiance(0.0f);
      for (int k = 0; k < per_pixel; ++k) radiance += pixel_samples[k].radiance;
      SumLayout::store_color_sums(radiance, per_pixel, pixel_sums);
      continue;
    }
    PixelAccumulator acc;
    for (int k = 0; k < per_pixel; ++k) acc.add(pixel_samples[k].radiance, pixel_samples[k].primary, range.begin + k);
    sums_.store(acc, pixel_sums);
  }
}

// Below render_pixels: Clang multiversions a function only where its definition precedes its calls.
TileResult TileRenderer::render(std::size_t index, const PixelRegion& tile, Workspace& ws) const {
  TileResult out;
  out.index = index;
  out.region = tile;
  out.pixels.assign(tile.pixel_count() * static_cast<std::size_t>(sums_.floats()), 0.0f);  // no samples: all zero
  const SampleRange range = schedule_.pass(grid_.pass(index));
  ws.pixels.clear();
  const PixelRegion& region = grid_.region();
  for (int by = tile.y0; by < tile.y1; by += kBlockSide)
    for (int bx = tile.x0; bx < tile.x1; bx += kBlockSide)
      for (int y = by; y < std::min(by + kBlockSide, tile.y1); ++y)
        for (int x = bx; x < std::min(bx + kBlockSide, tile.x1); ++x)
          if (!active_ ||
              (*active_)[static_cast<std::size_t>(y - region.y0) * static_cast<std::size_t>(region.width()) +
                         static_cast<std::size_t>(x - region.x0)])
            ws.pixels.push_back({static_cast<std::uint32_t>((y - tile.y0) * tile.width() + (x - tile.x0)), x, y});
  // Whole pixels per batch, about kSamplesPerBatch samples.
  const std::size_t pixels_per_batch =
      std::max<std::size_t>(1, kSamplesPerBatch / static_cast<std::size_t>(range.count()));
  for (std::size_t first = 0; first < ws.pixels.size(); first += pixels_per_batch)
    render_pixels(range, ws.pixels.data() + first, std::min(pixels_per_batch, ws.pixels.size() - first), out, ws);
  return out;
}

}  // namespace rtpro
