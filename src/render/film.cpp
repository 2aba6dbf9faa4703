#include "rtpro/render/film.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <bit>
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
  throw InputError("unknown AOV '" + std::string(name) +
                   "': expected albedo, normal, depth, object-id, halves, variance or spp");
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

void PixelAccumulator::merge(const PixelAccumulator& later) {
  if (later.samples == 0) return;
  radiance += later.radiance;
  even_radiance += later.even_radiance;
  odd_radiance += later.odd_radiance;
  radiance_squared += later.radiance_squared;
  albedo += later.albedo;
  normal += later.normal;
  depth_sum += later.depth_sum;
  hits += later.hits;
  if (!has_first) {
    has_first = later.has_first;
    first_object_id = later.first_object_id;
  }
  samples += later.samples;
}

namespace {

void pack_color(const Color& c, float*& out) {
  *out++ = c.x;
  *out++ = c.y;
  *out++ = c.z;
}

Color unpack_color(const float*& in) {
  const Color c(in[0], in[1], in[2]);
  in += 3;
  return c;
}

template <typename T>
float bits_as_float(T value) {
  static_assert(sizeof(T) == sizeof(float));
  return std::bit_cast<float>(value);
}

}  // namespace

void pack(const PixelAccumulator& acc, float* out) {
  pack_color(acc.radiance, out);
  pack_color(acc.even_radiance, out);
  pack_color(acc.odd_radiance, out);
  pack_color(acc.radiance_squared, out);
  pack_color(acc.albedo, out);
  pack_color(Color(acc.normal.x, acc.normal.y, acc.normal.z), out);
  *out++ = acc.depth_sum;
  *out++ = bits_as_float(acc.hits);
  *out++ = bits_as_float(acc.first_object_id);
  *out++ = bits_as_float(static_cast<std::uint32_t>(acc.has_first));
  *out++ = bits_as_float(acc.samples);
}

PixelAccumulator unpack(const float* in) {
  PixelAccumulator acc;
  acc.radiance = unpack_color(in);
  acc.even_radiance = unpack_color(in);
  acc.odd_radiance = unpack_color(in);
  acc.radiance_squared = unpack_color(in);
  acc.albedo = unpack_color(in);
  const Color n = unpack_color(in);
  acc.normal = Vec3(n.x, n.y, n.z);
  acc.depth_sum = *in++;
  acc.hits = std::bit_cast<int>(*in++);
  acc.first_object_id = std::bit_cast<std::uint32_t>(*in++);
  acc.has_first = std::bit_cast<std::uint32_t>(*in++) != 0;
  acc.samples = std::bit_cast<int>(*in++);
  return acc;
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
    }
  }
}

}  // namespace rtpro
