#pragma once
// Piecewise-constant distributions over [0,1) and [0,1)² (pbrt's Distribution1D/2D): sampled by
// inverting the cumulative sum, with the pdf of every point kept exactly as the sampler uses it,
// for multiple importance sampling. The environment light samples its image through one.
#include "rtpro/core/huge_page_buffer.h"
#include "rtpro/render/sampler.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

// n cells of width 1/n, each with the density func[i] / integral.
class Distribution1D {
 public:
  Distribution1D() = default;
  // Values >= 0 and finite (others count as 0); all zero gives the uniform distribution.
  explicit Distribution1D(std::span<const float> func);

  struct Sample {
    float x;    // in [0, 1)
    float pdf;  // density at x
    std::size_t cell;
  };
  // u in [0, 1).
  Sample sample(float u) const;
  float pdf(std::size_t cell) const;
  // The integral of the values over [0, 1) (their mean); 0 when all are zero.
  float integral() const { return integral_; }
  std::size_t size() const { return func_.size(); }

 private:
  std::vector<float> func_;
  std::vector<float> cdf_;  // size() + 1 entries, cdf_[0] = 0, cdf_.back() = 1
  float integral_ = 0.0f;
};

// width × height cells over [0,1)²: a marginal distribution over rows, a conditional one along
// each row. `func` is row-major (row 0 at v = 0). Rows are built in parallel (oneTBB); the result
// does not depend on the thread count. Every row's values and cdf lie in one array in huge pages
// rather than in a Distribution1D each: a 1024×512 image's rows would be a thousand allocations,
// each faulting on its first touch (~13 µs a fault on the VMs rtpro is measured on).
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(std::span<const float> func, int width, int height);

  struct Sample {
    float u, v;  // in [0, 1)
    float pdf;   // density over [0,1)²
  };
  Sample sample(Sample2D u) const;
  float pdf(float u, float v) const;  // u, v in [0, 1]; clamped to the cells
  int width() const { return width_; }
  int height() const { return height_; }
  // Bytes held, for memory figures; and what a distribution of width × height cells holds.
  std::size_t bytes() const;
  static std::uint64_t bytes_for(std::uint64_t width, std::uint64_t height);

 private:
  const float* row_func(std::size_t y) const { return cells_.get() + y * static_cast<std::size_t>(width_); }
  const float* row_cdf(std::size_t y) const {
    return cells_.get() + static_cast<std::size_t>(height_) * static_cast<std::size_t>(width_) +
           y * (static_cast<std::size_t>(width_) + 1);
  }

  int width_ = 0, height_ = 0;
  // Row y's values at row_func(y) (width entries), its cdf at row_cdf(y) (width + 1): all rows'
  // values, then all rows' cdfs. Each row's integral is the marginal's value for it.
  HugePageBuffer<float> cells_;
  std::vector<float> row_integrals_;
  Distribution1D marginal_;
};

}  // namespace rtpro
