#pragma once
// How a render's samples are split into passes. A pixel's samples are taken in sample order, pass
// after pass; between passes the whole image can be looked at (adaptive sampling decides which
// pixels go on, a time limit or an interrupt stops at the last whole pass, a preview shows it).
//
// Sobol points are progressive: every aligned power-of-two run of them is well spread over the
// pixel, so passes hold 1, 1, 2, 4, ... samples (doubling) up to a step of
// clamp(√spp rounded up to a power of two, 4, 64) samples, then that step until spp. Stratified
// samples fill their strata grid row by row and only the whole grid is spread over the pixel: they
// render in one pass.
//
// The schedule depends only on spp and the sampler, so every process, thread count, tile size and
// resume of a job splits the samples alike, and a pixel's sums are added in the same order.
#include "rtpro/scene/render_settings.h"

#include <vector>

namespace rtpro {

struct SampleRange {
  int begin = 0, end = 0;  // samples [begin, end) of every pixel that takes part in the pass
  int count() const { return end - begin; }
};

class PassSchedule {
 public:
  PassSchedule(int spp, SamplerKind sampler);
  int passes() const { return static_cast<int>(ends_.size()); }
  SampleRange pass(int index) const;
  int spp() const { return ends_.empty() ? 0 : ends_.back(); }
  // The samples every pass up to and including `index` add to a pixel that takes part in all.
  int samples_through(int index) const { return ends_[static_cast<std::size_t>(index)]; }

 private:
  std::vector<int> ends_;
};

}  // namespace rtpro
