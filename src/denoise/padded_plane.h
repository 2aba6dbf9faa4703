#pragma once
// One channel of an image with a border of `pad` pixels on every side, so the denoiser's kernels
// read whole neighbourhoods without bounds checks (rows are contiguous: they vectorise).
#include <cstddef>
#include <vector>

namespace rtpro {

class PaddedPlane {
 public:
  PaddedPlane() = default;
  PaddedPlane(int width, int height, int pad)
      : width_(width), height_(height), pad_(pad), stride_(static_cast<std::size_t>(width) + 2 * pad),
        data_(stride_ * (static_cast<std::size_t>(height) + 2 * pad), 0.0f) {}

  int width() const { return width_; }
  int height() const { return height_; }
  int pad() const { return pad_; }

  // Row y (-pad <= y < height + pad), indexed by x (-pad <= x < width + pad).
  float* row(int y) { return data_.data() + (static_cast<std::size_t>(y + pad_) * stride_ + pad_); }
  const float* row(int y) const { return data_.data() + (static_cast<std::size_t>(y + pad_) * stride_ + pad_); }
  float& at(int x, int y) { return row(y)[x]; }
  float at(int x, int y) const { return row(y)[x]; }

  // Fills the border with copies of the nearest edge pixel.
  void extend_edges() {
    for (int y = 0; y < height_; ++y) {
      float* r = row(y);
      for (int x = -pad_; x < 0; ++x) r[x] = r[0];
      for (int x = width_; x < width_ + pad_; ++x) r[x] = r[width_ - 1];
    }
    for (int y = -pad_; y < 0; ++y) copy_row(0, y);
    for (int y = height_; y < height_ + pad_; ++y) copy_row(height_ - 1, y);
  }

 private:
  void copy_row(int from, int to) {
    const float* source = row(from) - pad_;
    float* target = row(to) - pad_;
    for (std::size_t i = 0; i < stride_; ++i) target[i] = source[i];
  }

  int width_ = 0, height_ = 0, pad_ = 0;
  std::size_t stride_ = 0;
  std::vector<float> data_;
};

}  // namespace rtpro
