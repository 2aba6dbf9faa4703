#include "alias_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtpro {

AliasTable::AliasTable(std::span<const float> weights) {
  double total = 0.0;
  for (const float w : weights) {
    if (!(w >= 0.0f) || !std::isfinite(w)) throw std::invalid_argument("AliasTable: weights must be finite and >= 0");
    total += w;
  }
  if (weights.empty() || !(total > 0.0)) return;
  const std::size_t n = weights.size();
  bins_.resize(n);
  // Each item's probability scaled by n: a bin is exactly full at 1. Doubles through the
  // construction so thresholds of a million lights stay accurate.
  std::vector<double> scaled(n);
  std::vector<std::uint32_t> small, large;
  for (std::size_t i = 0; i < n; ++i) {
    bins_[i].pmf = static_cast<float>(weights[i] / total);
    scaled[i] = weights[i] / total * static_cast<double>(n);
    bins_[i].alias = static_cast<std::uint32_t>(i);
    (scaled[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
  }
  while (!small.empty() && !large.empty()) {
    const std::uint32_t s = small.back(), l = large.back();
    small.pop_back();
    bins_[s].threshold = static_cast<float>(scaled[s]);
    bins_[s].alias = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left is full up to rounding.
  for (const std::uint32_t i : small) bins_[i].threshold = 1.0f;
  for (const std::uint32_t i : large) bins_[i].threshold = 1.0f;
}

}  // namespace rtpro
