#pragma once
// The film: the image's channel layout (beauty RGB plus optional AOV layers) and how one
// pixel's samples become its stored values. Each pixel is written exactly once.
#include "rtpro/image/image.h"
#include "rtpro/render/shading.h"

#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

enum class Aov { kAlbedo, kNormal, kDepth, kObjectId };

// "albedo", "normal", "depth", "object-id"; throws InputError listing the valid names.
Aov parse_aov(std::string_view name);
std::vector<std::string> aov_channel_names(Aov aov);  // e.g. albedo.R albedo.G albedo.B

// Per-pixel sums of the samples, in sample order.
struct PixelAccumulator {
  Color radiance;
  Color albedo;
  Vec3 normal;
  float depth_sum = 0.0f;
  int hits = 0;
  std::uint32_t first_object_id = 0;  // of sample 0; 0 when it missed (ids are stored + 1)
  bool has_first = false;
  void add(const Color& sample_radiance, const PrimaryHit& primary);
};

class Film {
 public:
  Film(int width, int height, std::vector<Aov> aovs);
  void set_pixel(int x, int y, const PixelAccumulator& acc, int samples);
  Image& image() { return image_; }
  const std::vector<Aov>& aovs() const { return aovs_; }

 private:
  Image image_;
  std::vector<Aov> aovs_;
};

}  // namespace rtpro
