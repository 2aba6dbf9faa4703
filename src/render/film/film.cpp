#include "rtpro/render/film.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

Aov parse_aov(std::string_view name) {
  if (name == "albedo") return Aov::kAlbedo;
  if (name == "normal") return Aov::kNormal;
  if (name == "depth") return Aov::kDepth;
  if (name == "object-id") return Aov::kObjectId;
  if (name == "halves") return Aov::kHalves;
  if (name == "variance") return Aov::kVariance;
  if (name == "spp") return Aov::kSpp;
  if (name == "motion") return Aov::kMotion;
  throw InputError("unknown AOV '" + std::string(name) +
                   "': expected albedo, normal, depth, object-id, halves, variance, spp or motion");
}

std::vector<std::string> aov_channel_names(Aov aov) {
  switch (aov) {
    case Aov::kAlbedo: return {"albedo.R", "albedo.G", "albedo.B"};
    case Aov::kNormal: return {"N.X", "N.Y", "N.Z"};
    case Aov::kDepth: return {"depth.Z"};
    case Aov::kObjectId: return {"object_id.id"};
    case Aov::kHalves: return {"half_a.R", "half_a.G", "half_a.B", "half_b.R", "half_b.G", "half_b.B"};
    case Aov::kVariance: return {"variance.R", "variance.G", "variance.B"};
    case Aov::kSpp: return {"spp.count"};
    case Aov::kMotion: return {"motion.X", "motion.Y", "motion.Z", "motion.W"};
  }
  throw InputError("unknown AOV");
}

namespace {
std::vector<std::string> channels_for(const std::vector<Aov>& aovs) {
  std::vector<std::string> channels{"R", "G", "B"};
  for (Aov aov : aovs)
    for (std::string& name : aov_channel_names(aov)) channels.push_back(std::move(name));
  return channels;
}
}  // namespace

FilmLayout::FilmLayout(std::vector<Aov> aovs) : aovs_(std::move(aovs)), channels_(channels_for(aovs_)) {}

void FilmLayout::resolve_row(const SumLayout& sums, const float* pixel_sums, int pixels, float* out) const {
  const auto channels = static_cast<std::size_t>(channel_count());
  const auto floats = static_cast<std::size_t>(sums.floats());
  for (int p = 0; p < pixels; ++p, pixel_sums += floats, out += channels) {
    if (!aovs_.empty()) {
      resolve(sums.load(pixel_sums), std::span<float>(out, channels));
      continue;
    }
    // The colour alone, as resolve() computes it, without assembling the pixel's accumulator.
    const int samples = SumLayout::samples(pixel_sums);
    const float inv = samples > 0 ? 1.0f / static_cast<float>(samples) : 0.0f;
    for (int c = 0; c < 3; ++c) out[c] = samples > 0 ? pixel_sums[c] * inv : 0.0f;
  }
}

void FilmLayout::resolve(const PixelAccumulator& acc, std::span<float> pixel) const {
  const int samples = acc.samples;
  float* out = pixel.data();
  if (samples == 0) {
    std::fill(pixel.begin(), pixel.end(), 0.0f);
    return;
  }
  const float inv = 1.0f / static_cast<float>(samples);
  *out++ = acc.radiance.x * inv;
  *out++ = acc.radiance.y * inv;
  *out++ = acc.radiance.z * inv;
  for (Aov aov : aovs_) {
    switch (aov) {
      case Aov::kAlbedo:
        // Averaged over all samples: background counts as black albedo, like coverage.
        *out++ = acc.albedo.x * inv;
        *out++ = acc.albedo.y * inv;
        *out++ = acc.albedo.z * inv;
        break;
      case Aov::kNormal: {
        const float len = length(acc.normal);
        const Vec3 n = len > 0.0f ? acc.normal / len : Vec3(0.0f);
        *out++ = n.x;
        *out++ = n.y;
        *out++ = n.z;
        break;
      }
      case Aov::kDepth: *out++ = acc.hits > 0 ? acc.depth_sum / static_cast<float>(acc.hits) : 0.0f; break;
      case Aov::kObjectId: *out++ = static_cast<float>(acc.first_object_id); break;
      case Aov::kHalves: {
        // One sample: both halves are that sample (no independent second estimate exists).
        const int even = (samples + 1) / 2, odd = samples / 2;
        const Color a = acc.even_radiance / static_cast<float>(even);
        const Color b = odd > 0 ? acc.odd_radiance / static_cast<float>(odd) : a;
        for (float v : {a.x, a.y, a.z, b.x, b.y, b.z}) *out++ = v;
        break;
      }
      case Aov::kVariance: {
        const float n = static_cast<float>(samples);
        for (int c = 0; c < 3; ++c) {
          const float sum = acc.radiance[c], squares = acc.radiance_squared[c];
          const float sample_variance = samples > 1 ? std::max(0.0f, (squares - sum * sum / n) / (n - 1.0f)) : 0.0f;
          *out++ = sample_variance / n;
        }
        break;
      }
      case Aov::kSpp: *out++ = static_cast<float>(samples); break;
      case Aov::kMotion: {
        const float inv_hits = acc.hits > 0 ? 1.0f / static_cast<float>(acc.hits) : 0.0f;
        for (float v : acc.motion) *out++ = v * inv_hits;
        break;
      }
    }
  }
}

}  // namespace rtpro
