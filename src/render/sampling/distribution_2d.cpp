#include "rtpro/render/distribution_2d.h"

#include "rtpro/core/memory_budget.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace rtpro {

Distribution1D::Distribution1D(std::span<const float> func) : func_(func.size()), cdf_(func.size() + 1) {
  const std::size_t n = func.size();
  for (std::size_t i = 0; i < n; ++i) func_[i] = std::isfinite(func[i]) && func[i] > 0.0f ? func[i] : 0.0f;
  // Summed in double: a 4096-cell row of values spanning 10⁶ keeps its small cells' share.
  double sum = 0.0;
  std::vector<double> running(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    sum += func_[i];
    running[i + 1] = sum;
  }
  integral_ = static_cast<float>(sum / static_cast<double>(n));
  if (!(sum > 0.0) || !std::isfinite(integral_) || !(integral_ > 0.0f)) {
    // Nothing to prefer: uniform, and the values become that density's.
    std::fill(func_.begin(), func_.end(), 1.0f);
    for (std::size_t i = 0; i <= n; ++i) cdf_[i] = static_cast<float>(static_cast<double>(i) / static_cast<double>(n));
    integral_ = 0.0f;
    return;
  }
  for (std::size_t i = 0; i <= n; ++i) cdf_[i] = static_cast<float>(running[i] / sum);
  cdf_[n] = 1.0f;
}

float Distribution1D::pdf(std::size_t cell) const {
  if (integral_ == 0.0f) return 1.0f;
  return func_[cell] / integral_;
}

Distribution1D::Sample Distribution1D::sample(float u) const {
  const std::size_t n = func_.size();
  // The last cell whose cdf is <= u, skipping cells of zero width.
  const auto above = std::upper_bound(cdf_.begin(), cdf_.end(), u);
  std::size_t cell = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (above - cdf_.begin()) - 1));
  cell = std::min(cell, n - 1);
  const float width = cdf_[cell + 1] - cdf_[cell];
  float offset = width > 0.0f ? (u - cdf_[cell]) / width : 0.0f;
  offset = std::clamp(offset, 0.0f, 1.0f);
  float x = (static_cast<float>(cell) + offset) / static_cast<float>(n);
  // Stay inside the cell (and below 1) when the division rounds up: the float below the cell's
  // end, which is positive, is the one whose bits are one less.
  const float end = (static_cast<float>(cell) + 1.0f) / static_cast<float>(n);
  x = std::min(x, std::bit_cast<float>(std::bit_cast<std::uint32_t>(end) - 1u));
  return {x, pdf(cell), cell};
}

Distribution2D::Distribution2D(std::span<const float> func, int width, int height)
    : width_(width), height_(height), rows_(static_cast<std::size_t>(height)) {
  const auto w = static_cast<std::size_t>(width);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y)
      rows_[static_cast<std::size_t>(y)] = Distribution1D(func.subspan(static_cast<std::size_t>(y) * w, w));
  });
  std::vector<float> row_integrals(static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    row_integrals[static_cast<std::size_t>(y)] = rows_[static_cast<std::size_t>(y)].integral();
  marginal_ = Distribution1D(row_integrals);
}

Distribution2D::Sample Distribution2D::sample(Sample2D u) const {
  const Distribution1D::Sample row = marginal_.sample(u.y);
  const Distribution1D::Sample column = rows_[row.cell].sample(u.x);
  return {column.x, row.x, row.pdf * column.pdf};
}

float Distribution2D::pdf(float u, float v) const {
  const auto cell = [](float t, int n) {
    return static_cast<std::size_t>(std::clamp(static_cast<int>(t * static_cast<float>(n)), 0, n - 1));
  };
  const std::size_t y = cell(v, height_);
  return marginal_.pdf(y) * rows_[y].pdf(cell(u, width_));
}

std::size_t Distribution2D::bytes() const {
  return static_cast<std::size_t>(bytes_for(static_cast<std::uint64_t>(width_), static_cast<std::uint64_t>(height_)));
}

// Per row: the values and cdf (width + 1 entries) of its distribution, its object, and the
// marginal's value and cdf entry.
std::uint64_t Distribution2D::bytes_for(std::uint64_t width, std::uint64_t height) {
  const std::uint64_t per_row =
      saturating_add(saturating_multiply(saturating_add(saturating_multiply(width, 2), 1), sizeof(float)),
                     sizeof(Distribution1D) + 2 * sizeof(float));
  return saturating_multiply(per_row, height);
}

}  // namespace rtpro
