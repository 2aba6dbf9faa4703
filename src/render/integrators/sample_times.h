#pragma once
// The time of each ray an integrator traces under an open shutter: its camera sample's
// (CameraBatch::times), which every ray of the sample's path or ray tree keeps.
#include <cstddef>
#include <span>
#include <vector>

namespace rtpro {

// Each item's sample's time (an item is a path, a ray task or a shadow query; `sample_of` names
// its sample), or nothing while the shutter is closed (`sample_times` empty).
template <typename Item, typename SampleOf>
void times_of_samples(std::span<const float> sample_times, std::span<const Item> items, SampleOf&& sample_of,
                      std::vector<float>& times) {
  times.clear();
  if (sample_times.empty()) return;
  times.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) times[i] = sample_times[sample_of(items[i])];
}

}  // namespace rtpro
