#pragma once
// Picks one of n items with probability proportional to its weight in constant time (Walker's
// alias method, built with Vose's stable two-list construction): lights by power. The
// probability of every item is kept exactly as used, for multiple importance sampling.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

class AliasTable {
 public:
  AliasTable() = default;
  // Weights >= 0 and finite; an all-zero (or empty) set gives an empty table.
  explicit AliasTable(std::span<const float> weights);

  bool empty() const { return bins_.empty(); }
  std::size_t size() const { return bins_.size(); }

  struct Pick {
    std::uint32_t index;
    float pmf;         // the probability of picking `index`
    float remapped_u;  // u's remaining precision, uniform in [0, 1) again, for a further choice
  };
  // u in [0, 1). The table must not be empty. Inline: its Pick returned from out of line is put
  // together on the stack and loaded back whole, a store-forwarding stall per pick.
  Pick sample(float u) const {
    const float scaled = u * static_cast<float>(bins_.size());
    const auto bin = std::min(static_cast<std::size_t>(scaled), bins_.size() - 1);
    const float within = std::min(scaled - static_cast<float>(bin), 0x1.fffffep-1f);
    const Bin& b = bins_[bin];
    if (within < b.threshold)
      return {static_cast<std::uint32_t>(bin), b.pmf, std::min(within / b.threshold, 0x1.fffffep-1f)};
    return {b.alias, bins_[b.alias].pmf, std::min((within - b.threshold) / (1.0f - b.threshold), 0x1.fffffep-1f)};
  }
  float pmf(std::uint32_t index) const { return bins_[index].pmf; }

 private:
  struct Bin {
    float threshold;  // below it the bin keeps its own item
    std::uint32_t alias;
    float pmf;  // the item's own probability
  };
  std::vector<Bin> bins_;
};

}  // namespace rtpro
