#include "rtpro/render/film.h"

#include "rtpro/core/error.h"

#include <cmath>

namespace rtpro {

Aov parse_aov(std::string_view name) {
  if (name == "albedo") return Aov::kAlbedo;
  if (name == "normal") return Aov::kNormal;
  if (name == "depth") return Aov::kDepth;
  if (name == "object-id") return Aov::kObjectId;
  throw InputError("unknown AOV '" + std::string(name) + "': expected albedo, normal, depth or object-id");
}

std::vector<std::string> aov_channel_names(Aov aov) {
  switch (aov) {
    case Aov::kAlbedo: return {"albedo.R", "albedo.G", "albedo.B"};
    case Aov::kNormal: return {"N.X", "N.Y", "N.Z"};
    case Aov::kDepth: return {"depth.Z"};
    case Aov::kObjectId: return {"object_id.id"};
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

void FilmLayout::resolve(const PixelAccumulator& acc, int samples, std::span<float> pixel) const {
  const float inv = 1.0f / static_cast<float>(samples);
  float* out = pixel.data();
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
    }
  }
}

}  // namespace rtpro
