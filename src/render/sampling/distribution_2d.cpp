#include "rtpro/render/distribution_2d.h"

#include "rtpro/core/memory_budget.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace rtpro {

namespace {

// Writes a row's values (non-finite and negative ones as 0) and its cdf (n + 1 entries) and returns
// its integral, 0 when no value is positive: then the distribution is uniform, and the values
// become that density's.
float build_cells(std::span<const float> values, float* func, float* cdf) {
  const std::size_t n = values.size();
  // Summed in double: a 4096-cell row of values spanning 10⁶ keeps its small cells' share.
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    func[i] = std::isfinite(values[i]) && values[i] > 0.0f ? values[i] : 0.0f;
    sum += func[i];
  }
  const auto integral = static_cast<float>(sum / static_cast<double>(n));
  if (!(sum > 0.0) || !std::isfinite(integral) || !(integral > 0.0f)) {
    std::fill(func, func + n, 1.0f);
    for (std::size_t i = 0; i <= n; ++i) cdf[i] = static_cast<float>(static_cast<double>(i) / static_cast<double>(n));
    return 0.0f;
  }
  // The running sums again, the same additions in the same order as above.
  double running = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    cdf[i] = static_cast<float>(running / sum);
    running += func[i];
  }
  cdf[n] = 1.0f;
  return integral;
}

float cell_pdf(const float* func, float integral, std::size_t cell) {
  if (integral == 0.0f) return 1.0f;
  return func[cell] / integral;
}

Distribution1D::Sample sample_cells(const float* func, const float* cdf, std::size_t n, float integral, float u) {
  // The last cell whose cdf is <= u, skipping cells of zero width.
  const float* above = std::upper_bound(cdf, cdf + n + 1, u);
  std::size_t cell = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (above - cdf) - 1));
  cell = std::min(cell, n - 1);
  const float width = cdf[cell + 1] - cdf[cell];
  float offset = width > 0.0f ? (u - cdf[cell]) / width : 0.0f;
  offset = std::clamp(offset, 0.0f, 1.0f);
  float x = (static_cast<float>(cell) + offset) / static_cast<float>(n);
  // Stay inside the cell (and below 1) when the division rounds up: the float below the cell's
  // end, which is positive, is the one whose bits are one less.
  const float end = (static_cast<float>(cell) + 1.0f) / static_cast<float>(n);
  x = std::min(x, std::bit_cast<float>(std::bit_cast<std::uint32_t>(end) - 1u));
  return {x, cell_pdf(func, integral, cell), cell};
}

}  // namespace

Distribution1D::Distribution1D(std::span<const float> func) : func_(func.size()), cdf_(func.size() + 1) {
  integral_ = build_cells(func, func_.data(), cdf_.data());
}

float Distribution1D::pdf(std::size_t cell) const { return cell_pdf(func_.data(), integral_, cell); }

Distribution1D::Sample Distribution1D::sample(float u) const {
  return sample_cells(func_.data(), cdf_.data(), func_.size(), integral_, u);
}

Distribution2D::Distribution2D(std::span<const float> func, int width, int height)
    : width_(width), height_(height),
      cells_(static_cast<std::size_t>(height) * (2 * static_cast<std::size_t>(width) + 1)),
      row_integrals_(static_cast<std::size_t>(height)) {
  const auto w = static_cast<std::size_t>(width);
  float* const values = cells_.get();
  float* const cdfs = values + static_cast<std::size_t>(height) * w;
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y) {
      const auto row = static_cast<std::size_t>(y);
      row_integrals_[row] = build_cells(func.subspan(row * w, w), values + row * w, cdfs + row * (w + 1));
    }
  });
  marginal_ = Distribution1D(row_integrals_);
}

Distribution2D::Sample Distribution2D::sample(Sample2D u) const {
  const Distribution1D::Sample row = marginal_.sample(u.y);
  const Distribution1D::Sample column = sample_cells(row_func(row.cell), row_cdf(row.cell),
                                                     static_cast<std::size_t>(width_), row_integrals_[row.cell], u.x);
  return {column.x, row.x, row.pdf * column.pdf};
}

float Distribution2D::pdf(float u, float v) const {
  const auto cell = [](float t, int n) {
    return static_cast<std::size_t>(std::clamp(static_cast<int>(t * static_cast<float>(n)), 0, n - 1));
  };
  const std::size_t y = cell(v, height_);
  return marginal_.pdf(y) * cell_pdf(row_func(y), row_integrals_[y], cell(u, width_));
}

std::size_t Distribution2D::bytes() const {
  return static_cast<std::size_t>(bytes_for(static_cast<std::uint64_t>(width_), static_cast<std::uint64_t>(height_)));
}

// Per row: its values and cdf (width + 1 entries), its integral, and the marginal's value and cdf
// entry.
std::uint64_t Distribution2D::bytes_for(std::uint64_t width, std::uint64_t height) {
  const std::uint64_t per_row = saturating_multiply(saturating_add(saturating_multiply(width, 2), 4), sizeof(float));
  return saturating_multiply(per_row, height);
}

}  // namespace rtpro
