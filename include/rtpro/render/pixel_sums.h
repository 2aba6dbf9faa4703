#pragma once
// A pixel's sums over its samples, and which of them a render keeps. A pass's work item carries,
// and the film holds, only the sums the requested layers and adaptive sampling read, as floats:
// at 1024×1024 a colour-only pass moves 16 MB rather than the 96 MB of every sum.
#include "rtpro/render/aov.h"
#include "rtpro/render/sample_result.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

namespace rtpro {

// Per-pixel sums of the samples, in sample order.
struct PixelAccumulator {
  Color radiance;
  Color even_radiance;     // of samples 0, 2, 4, ...
  Color odd_radiance;      // of samples 1, 3, 5, ...
  Color radiance_squared;  // per channel
  Color albedo;
  Vec3 normal;
  float depth_sum = 0.0f;
  int hits = 0;
  std::uint32_t first_object_id = 0;  // of sample 0; 0 when it missed (ids are stored + 1)
  float motion[4] = {};               // of the hits: FilmMotion's forward x, y, back x, y
  int samples = 0;
  // Inline: it runs once per camera sample.
  void add(const Color& sample_radiance, const PrimaryHit& primary, int sample_index) {
    if (samples == 0) first_object_id = primary.hit ? primary.object_id + 1 : 0;
    ++samples;
    radiance += sample_radiance;
    (sample_index % 2 == 0 ? even_radiance : odd_radiance) += sample_radiance;
    radiance_squared += sample_radiance * sample_radiance;
    if (!primary.hit) return;
    albedo += primary.albedo;
    normal += primary.normal;
    depth_sum += primary.depth;
    ++hits;
    motion[0] += primary.motion.forward_x;
    motion[1] += primary.motion.forward_y;
    motion[2] += primary.motion.back_x;
    motion[3] += primary.motion.back_y;
  }
};

// The sums a render keeps, stored per pixel as floats in this order: the colour (3) and the sample
// count (1) always; then, when something reads them, the even-sample colour (3: the halves layer,
// Cycles' error), the odd-sample colour (3: halves), the squares (3: variance, relMSE error), albedo (3),
// normal (3), depth sum and hit count (2: depth, motion), the first sample's object id (1, its bit
// pattern) and the motion (4). Counts are stored as float values: exact, as no pixel takes 2^24 samples.
// Sums kept beyond what the layers read: what adaptive sampling's error reads.
struct ExtraSums {
  bool even_half = false;
  bool squares = false;
};

class SumLayout {
 public:
  // Colour and sample count only.
  SumLayout() = default;
  SumLayout(std::span<const Aov> aovs, ExtraSums extra);

  int floats() const { return floats_; }
  bool keeps_even() const { return even_ >= 0; }
  bool keeps_color_only() const { return floats_ == 4; }
  bool keeps_motion() const { return motion_ >= 0; }

  // Inline below, as they run once per pixel of every work item: writes the sums this layout keeps.
  void store(const PixelAccumulator& acc, float* out) const;
  // The kept sums; the others are 0.
  PixelAccumulator load(const float* sums) const;
  // Adds a later pass's sums of `pixels` pixels to `sums`, in place (a pixel the later pass did
  // not sample is left as it is).
  void merge(float* sums, const float* later, std::size_t pixels = 1) const;
  static int samples(const float* sums) { return static_cast<int>(sums[kSamples]); }
  // What store writes for a layout that keeps_color_only, from the colour's sum and the count alone.
  static void store_color_sums(const Color& radiance, int samples, float* out) {
    store_color(radiance, out);
    out[kSamples] = static_cast<float>(samples);
  }

 private:
  static constexpr int kSamples = 3;
  static void store_color(const Color& c, float* out) {
    out[0] = c.x;
    out[1] = c.y;
    out[2] = c.z;
  }
  static Color load_color(const float* in) { return Color(in[0], in[1], in[2]); }

  int even_ = -1, odd_ = -1, squared_ = -1, albedo_ = -1, normal_ = -1, depth_ = -1, object_id_ = -1, motion_ = -1;
  int floats_ = 4;
};

inline void SumLayout::store(const PixelAccumulator& acc, float* out) const {
  store_color(acc.radiance, out);
  out[kSamples] = static_cast<float>(acc.samples);
  if (even_ >= 0) store_color(acc.even_radiance, out + even_);
  if (odd_ >= 0) store_color(acc.odd_radiance, out + odd_);
  if (squared_ >= 0) store_color(acc.radiance_squared, out + squared_);
  if (albedo_ >= 0) store_color(acc.albedo, out + albedo_);
  if (normal_ >= 0) store_color(Color(acc.normal.x, acc.normal.y, acc.normal.z), out + normal_);
  if (depth_ >= 0) {
    out[depth_] = acc.depth_sum;
    out[depth_ + 1] = static_cast<float>(acc.hits);
  }
  if (object_id_ >= 0) out[object_id_] = std::bit_cast<float>(acc.first_object_id);
  if (motion_ >= 0)
    for (int i = 0; i < 4; ++i) out[motion_ + i] = acc.motion[i];
}

inline PixelAccumulator SumLayout::load(const float* sums) const {
  PixelAccumulator acc;
  acc.radiance = load_color(sums);
  acc.samples = samples(sums);
  if (even_ >= 0) acc.even_radiance = load_color(sums + even_);
  if (odd_ >= 0) acc.odd_radiance = load_color(sums + odd_);
  if (squared_ >= 0) acc.radiance_squared = load_color(sums + squared_);
  if (albedo_ >= 0) acc.albedo = load_color(sums + albedo_);
  if (normal_ >= 0) {
    const Color n = load_color(sums + normal_);
    acc.normal = Vec3(n.x, n.y, n.z);
  }
  if (depth_ >= 0) {
    acc.depth_sum = sums[depth_];
    acc.hits = static_cast<int>(sums[depth_ + 1]);
  }
  if (object_id_ >= 0) acc.first_object_id = std::bit_cast<std::uint32_t>(sums[object_id_]);
  if (motion_ >= 0)
    for (int i = 0; i < 4; ++i) acc.motion[i] = sums[motion_ + i];
  return acc;
}

inline void SumLayout::merge(float* sums, const float* later, std::size_t pixels) const {
  const auto floats = static_cast<std::size_t>(floats_);
  for (std::size_t p = 0; p < pixels; ++p, sums += floats, later += floats) {
    if (later[kSamples] == 0.0f) continue;
    // The first sample's id is the earliest pass's: kept once the pixel has a sample.
    const bool keep_id = object_id_ >= 0 && sums[kSamples] != 0.0f;
    const float first_id = keep_id ? sums[object_id_] : 0.0f;
    for (std::size_t i = 0; i < floats; ++i) sums[i] += later[i];
    if (object_id_ >= 0) sums[object_id_] = keep_id ? first_id : later[object_id_];
  }
}

}  // namespace rtpro
