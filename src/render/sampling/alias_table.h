#pragma once
// Picks one of n items with probability proportional to its weight in constant time (Walker's
// alias method, built with Vose's stable two-list construction): lights by power. The
// probability of every item is kept exactly as used, for multiple importance sampling.
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
  // u in [0, 1). The table must not be empty.
  Pick sample(float u) const;
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
