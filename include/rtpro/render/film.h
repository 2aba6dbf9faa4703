#pragma once
// The film: the image's channel layout (beauty RGB plus optional AOV layers) and how one pixel's
// samples become its stored values. Pixels are resolved into a tile's own buffer and copied into
// the image once, so a tile can travel (to another rank, to a journal) before it lands.
#include "rtpro/image/image.h"
#include "rtpro/render/shading.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// kHalves: the mean of the pixel's even-indexed samples and of its odd-indexed ones (two
// independent estimates, half the samples each: from their difference the denoiser bounds its
// noise estimate); kVariance: the sample variance of the pixel's mean colour; kSpp: the samples
// the pixel got (adaptive sampling stops converged pixels early).
enum class Aov { kAlbedo, kNormal, kDepth, kObjectId, kHalves, kVariance, kSpp };

// "albedo", "normal", "depth", "object-id", "halves", "variance", "spp"; throws InputError listing
// the valid names.
Aov parse_aov(std::string_view name);
std::vector<std::string> aov_channel_names(Aov aov);  // e.g. albedo.R albedo.G albedo.B

// Per-pixel sums of the samples, in sample order. A pass's sums are added to the sums of the passes
// before it (merge), in pass order, so a pixel's value depends only on its samples and the pass
// schedule.
struct PixelAccumulator {
  Color radiance;
  Color even_radiance;      // of samples 0, 2, 4, ...
  Color odd_radiance;       // of samples 1, 3, 5, ...
  Color radiance_squared;   // per channel
  Color albedo;
  Vec3 normal;
  float depth_sum = 0.0f;
  int hits = 0;
  std::uint32_t first_object_id = 0;  // of sample 0; 0 when it missed (ids are stored + 1)
  bool has_first = false;
  int samples = 0;
  // Inline: it runs once per camera sample.
  void add(const Color& sample_radiance, const PrimaryHit& primary, int sample_index) {
    ++samples;
    radiance += sample_radiance;
    (sample_index % 2 == 0 ? even_radiance : odd_radiance) += sample_radiance;
    radiance_squared += sample_radiance * sample_radiance;
    if (!has_first) {
      has_first = true;
      first_object_id = primary.hit ? primary.object_id + 1 : 0;
    }
    if (!primary.hit) return;
    albedo += primary.albedo;
    normal += primary.normal;
    depth_sum += primary.depth;
    ++hits;
  }
  // Adds the sums of later samples (the next pass's) to these.
  void merge(const PixelAccumulator& later);
};

// A PixelAccumulator as floats, bit for bit (the counts and the id as their bit patterns), for
// tiles that travel to other ranks and to resume journals.
inline constexpr int kAccumulatorFloats = 23;
void pack(const PixelAccumulator& acc, float* out);
PixelAccumulator unpack(const float* in);

class FilmLayout {
 public:
  explicit FilmLayout(std::vector<Aov> aovs);
  const std::vector<Aov>& aovs() const { return aovs_; }
  const std::vector<std::string>& channels() const { return channels_; }
  int channel_count() const { return static_cast<int>(channels_.size()); }

  // Writes the pixel's channel_count() values to `out`; a pixel without samples is 0.
  void resolve(const PixelAccumulator& acc, std::span<float> out) const;

 private:
  std::vector<Aov> aovs_;
  std::vector<std::string> channels_;
};

}  // namespace rtpro
