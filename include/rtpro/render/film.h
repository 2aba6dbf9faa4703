#pragma once
// The film: the image's channel layout (beauty RGB plus optional AOV layers) and how one pixel's
// samples become its stored values. Pixels are resolved into a tile's own buffer and copied into
// the image once, so a tile can travel (to another rank, to a journal) before it lands.
#include "rtpro/image/image.h"
#include "rtpro/render/aov.h"
#include "rtpro/render/pixel_sums.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// "albedo", "normal", "depth", "object-id", "halves", "variance", "spp"; throws InputError listing
// the valid names.
Aov parse_aov(std::string_view name);
std::vector<std::string> aov_channel_names(Aov aov);  // e.g. albedo.R albedo.G albedo.B

class FilmLayout {
 public:
  explicit FilmLayout(std::vector<Aov> aovs);
  const std::vector<Aov>& aovs() const { return aovs_; }
  const std::vector<std::string>& channels() const { return channels_; }
  int channel_count() const { return static_cast<int>(channels_.size()); }

  // Writes the pixel's channel_count() values to `out`; a pixel without samples is 0.
  void resolve(const PixelAccumulator& acc, std::span<float> out) const;
  // The same for `pixels` pixels of a film's sums in a row, into consecutive pixels of `out`.
  void resolve_row(const SumLayout& sums, const float* pixel_sums, int pixels, float* out) const;

 private:
  std::vector<Aov> aovs_;
  std::vector<std::string> channels_;
};

}  // namespace rtpro
