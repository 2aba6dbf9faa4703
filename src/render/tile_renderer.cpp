#include "rtpro/render/tile_renderer.h"

#include "append_ray.h"
#include "rtpro/core/avx2_clones.h"
#include "rtpro/render/camera.h"
#include "rtpro/render/sample_dimensions.h"

#include <algorithm>
#include <stdexcept>

namespace rtpro {

namespace {

// Samples shaded together. Large enough for the backends to trace whole batches (streams, packets)
// and to amortise each generation's bookkeeping, small enough that a batch's rays, hits and
// surfaces stay in the L2 cache.
constexpr std::size_t kSamplesPerBatch = 1024;

}  // namespace

TileRenderer::TileRenderer(const RenderScene& scene, const Backend& backend, const FilmLayout& layout,
                           const TextureLookup* textures, const EnvironmentLight* environment)
    : scene_(scene),
      backend_(backend),
      layout_(layout),
      textures_(textures),
      environment_(environment),
      sampler_(scene.render.spp, scene.render.seed),
      sobol_(scene.render.seed),
      pixels_per_batch_(std::max<std::size_t>(1, kSamplesPerBatch / static_cast<std::size_t>(scene.render.spp))) {
  if (scene.environment && !environment)
    throw std::logic_error("TileRenderer: the scene has an environment but none was built for it");
  if (scene.render.integrator == Integrator::kPath) path_lights_.emplace(scene, environment);
  if (!scene.textures.empty() && !textures)
    throw std::logic_error("TileRenderer: the scene has image textures but none were opened for it");
}

// Pixels [first_pixel, first_pixel + pixel_count) of the tile, in row-major order.
RTPRO_AVX2_CLONES
void TileRenderer::render_pixels(const PixelRegion& tile, std::size_t first_pixel, std::size_t pixel_count,
                                 TileResult& out, Workspace& ws) const {
  const int spp = sampler_.samples_per_pixel();
  const auto image_width = static_cast<std::uint64_t>(scene_.camera.width);
  const auto tile_width = static_cast<std::size_t>(tile.width());
  const bool pinhole = scene_.camera.lens_radius == 0.0f;
  // Sized once per batch and written in place (a resize to the same size does nothing).
  ws.camera_rays.resize(pixel_count * static_cast<std::size_t>(spp));
  ws.sample_keys.resize(ws.camera_rays.size());
  ws.pixel_offsets.resize(static_cast<std::size_t>(spp));
  const PixelOffset* offsets = ws.pixel_offsets.data();
  std::size_t next = 0;
  for (std::size_t p = first_pixel; p < first_pixel + pixel_count; ++p) {
    const int x = tile.x0 + static_cast<int>(p % tile_width);
    const int y = tile.y0 + static_cast<int>(p / tile_width);
    const std::uint64_t pixel_key = static_cast<std::uint64_t>(y) * image_width + static_cast<std::uint64_t>(x);
    switch (scene_.render.sampler) {
      case SamplerKind::kStratified: sampler_.pixel_offsets(pixel_key, ws.pixel_offsets.data()); break;
      case SamplerKind::kSobol:
        for (int i = 0; i < spp; ++i) ws.pixel_offsets[static_cast<std::size_t>(i)] = sobol_.pixel_offset(pixel_key, i);
        break;
    }
    int s = 0;
    // Pinhole rays four at a time (camera_ray's rays, bit for bit), the rest one by one.
    for (; pinhole && s + 4 <= spp; s += 4, next += 4) {
      alignas(16) float px[4], py[4];
      for (int i = 0; i < 4; ++i) {
        px[i] = static_cast<float>(x) + offsets[s + i].x;
        py[i] = static_cast<float>(y) + offsets[s + i].y;
        ws.sample_keys[next + static_cast<std::size_t>(i)] = {pixel_key, s + i};
      }
      pinhole_rays4(scene_.camera, px, py, &ws.camera_rays[next]);
    }
    for (; s < spp; ++s, ++next) {
      const PixelOffset& offset = offsets[s];
      const Sample2D lens = pinhole                                             ? Sample2D{0.5f, 0.5f}
                            : scene_.render.sampler == SamplerKind::kStratified ? sampler_.sample_2d(pixel_key, s, sample_dimension::kLens)
                                                                                : sobol_.sample_2d(pixel_key, s, sample_dimension::kLens);
      copy_ray(camera_ray(scene_.camera, static_cast<float>(x) + offset.x, static_cast<float>(y) + offset.y, lens),
               ws.camera_rays[next]);
      ws.sample_keys[next] = {pixel_key, s};
    }
  }
  ws.samples.resize(ws.camera_rays.size());
  switch (scene_.render.integrator) {
    case Integrator::kWhitted:
      shade_batch(scene_, backend_, sampler_, ws.camera_rays, ws.sample_keys, ws.samples, out.rays, ws.shading,
                  textures_, environment_);
      break;
    case Integrator::kPath:
      switch (scene_.render.sampler) {
        case SamplerKind::kStratified:
          trace_paths(scene_, backend_, *path_lights_, sampler_, ws.camera_rays, ws.sample_keys, ws.samples, out.rays,
                      ws.paths, textures_);
          break;
        case SamplerKind::kSobol:
          trace_paths(scene_, backend_, *path_lights_, sobol_, ws.camera_rays, ws.sample_keys, ws.samples, out.rays,
                      ws.paths, textures_);
          break;
      }
      break;
  }

  const auto channels = static_cast<std::size_t>(layout_.channel_count());
  for (std::size_t p = 0; p < pixel_count; ++p) {
    PixelAccumulator acc;
    for (int s = 0; s < spp; ++s) {
      SampleResult& sample = ws.samples[p * static_cast<std::size_t>(spp) + static_cast<std::size_t>(s)];
      if (!is_finite(sample.radiance)) {
        ++out.nan_samples;
        sample.radiance = Color(0.0f);
      }
      acc.add(sample.radiance, sample.primary, s);
    }
    layout_.resolve(acc, spp, std::span<float>(out.pixels).subspan((first_pixel + p) * channels, channels));
  }
}

// Below render_pixels: Clang multiversions a function only where its definition precedes its calls.
TileResult TileRenderer::render(std::size_t index, const PixelRegion& tile, Workspace& ws) const {
  TileResult out;
  out.index = index;
  out.region = tile;
  out.pixels.resize(tile.pixel_count() * static_cast<std::size_t>(layout_.channel_count()));
  for (std::size_t first = 0; first < tile.pixel_count(); first += pixels_per_batch_)
    render_pixels(tile, first, std::min(pixels_per_batch_, tile.pixel_count() - first), out, ws);
  return out;
}

}  // namespace rtpro
