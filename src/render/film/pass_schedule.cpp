#include "rtpro/render/pass_schedule.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

int power_of_two_at_least(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

}  // namespace

PassSchedule::PassSchedule(int spp, SamplerKind sampler) {
  if (spp <= 0) return;
  switch (sampler) {
    case SamplerKind::kStratified: ends_.push_back(spp); return;
    case SamplerKind::kSobol: break;
  }
  const int step =
      std::clamp(power_of_two_at_least(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(spp))))), 4, 64);
  int done = 0;
  while (done < spp) {
    const int size = std::min(done == 0 ? 1 : std::min(done, step), spp - done);
    done += size;
    ends_.push_back(done);
  }
}

SampleRange PassSchedule::pass(int index) const {
  const auto i = static_cast<std::size_t>(index);
  return {i == 0 ? 0 : ends_[i - 1], ends_[i]};
}

}  // namespace rtpro
