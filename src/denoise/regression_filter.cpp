#include "regression_filter.h"

#include "regression_lanes.h"
#include "regression_moments.h"

#include "rtpro/core/avx2_clones.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace rtpro {

namespace {

using namespace regression;

// Regressors at most: normal (3), inverse depth, screen x and y, the intercept. (The albedo is
// divided out of the colour instead: the regression need not explain it.)
constexpr int kMaxRegressors = 7;
// Keeps the colour distance finite where neither pixel has any variance (an exact background).
constexpr float kVarianceEpsilon = 1e-8f;
// Inverse depth may differ by this fraction of itself even on a surface facing the camera.
constexpr float kDepthRelativeSlack = 0.01f;
// Ridge regularisation of each feature's coefficient: a feature that varies, over the weighted
// window, by less than about sqrt(kRidge) adds nothing but the noise it would fit.
constexpr double kRidge = 1e-3;

struct Tile {
  int x0, y0, width, height;
};

// Per-thread work space, reused from tile to tile; nothing in it outlives a tile.
struct TileScratch {
  std::vector<float> distance;          // [padded tile pixel]: colour distances, then patch sums
  std::vector<float> across;            // the distances summed across each patch row
  std::vector<float> feature_distance;  // [tile pixel]
  std::vector<float> weights;           // [row][group][offset][lane]: see weight_lanes
  std::vector<float> wx, e;             // [offset of a window row][regressor][lane]
  std::vector<float> sums;              // [moment][pixel of a row]
};

class RegressionFilter {
 public:
  RegressionFilter(const DenoiseBuffers& buffers, const DenoiseSettings& settings)
      : b_(buffers), radius_(settings.window_radius), patch_(settings.patch_radius),
        window_(2 * settings.window_radius + 1), regressed_(regressed_features(buffers)),
        regressors_(static_cast<int>(regressed_.size()) + 3), moments_(moment_count(regressors_)),
        tolerance2_(settings.colour_tolerance * settings.colour_tolerance),
        inv_albedo2_(1.0f / (settings.albedo_tolerance * settings.albedo_tolerance)),
        inv_normal2_(1.0f / (settings.normal_tolerance * settings.normal_tolerance)),
        inv_depth2_(1.0f / (settings.depth_tolerance * settings.depth_tolerance)),
        distance_stride_(lane_chunks(kTileSize + 2 * patch_) * kLanes + kLanes) {}

  int offsets() const { return window_ * window_; }

  void prepare(TileScratch& s) const {
    const int padded = kTileSize + 2 * patch_;
    s.distance.resize(static_cast<std::size_t>(padded) * distance_stride_);
    s.across.resize(static_cast<std::size_t>(padded) * kTileSize);
    s.feature_distance.resize(kTileSize * kTileSize);
    s.weights.resize(static_cast<std::size_t>(offsets()) * kTileSize * kTileSize);
    s.wx.resize(static_cast<std::size_t>(window_) * regressors_ * kLanes);
    s.e.resize(static_cast<std::size_t>(window_) * (regressors_ + 3) * kLanes);
    s.sums.resize(static_cast<std::size_t>(moments_) * kTileSize);
  }

  void filter(const Tile& tile, TileScratch& s, Image& out) const {
    int offset = 0;
    for (int dy = -radius_; dy <= radius_; ++dy)
      for (int dx = -radius_; dx <= radius_; ++dx, ++offset) compute_weights(tile, dx, dy, offset, s);
    for (int row = 0; row < tile.height; ++row) regress_row(tile, row, s, out);
  }

 private:
  // The weights of one tile row's kLanes pixels `group` for one offset. The regression reads a
  // row's groups offset after offset, so those lie together: [row][group][offset][lane].
  float* weight_lanes(TileScratch& s, int row, int group, int offset) const {
    const std::size_t block = static_cast<std::size_t>(row) * kGroups + group;
    return s.weights.data() + (block * offsets() + offset) * kLanes;
  }

  // The weight of the neighbour `dx, dy` away, for each tile pixel: the non-local-means distance
  // of their patches (Rousselle et al. 2012: the squared difference less its expected noise, over
  // the noise), plus the feature distance, through e^-x.
  RTPRO_AVX2_CLONES void compute_weights(const Tile& tile, int dx, int dy, int offset, TileScratch& s) const {
    compute_feature_distances(tile, dx, dy, s);
    const int padded_height = tile.height + 2 * patch_;
    const int chunks = lane_chunks(tile.width + 2 * patch_);
    const Lanes epsilon = Lanes{} + kVarianceEpsilon;
    for (int row = 0; row < padded_height; ++row) {
      const int py = tile.y0 - patch_ + row;
      float* d = s.distance.data() + static_cast<std::size_t>(row) * distance_stride_;
      for (int chunk = 0; chunk < chunks; ++chunk) {
        const int x = tile.x0 - patch_ + chunk * kLanes;
        Lanes sum{};
        for (int c = 0; c < 3; ++c) {
          const Lanes vp = load_lanes(b_.variance[c].row(py) + x);
          const Lanes vq = load_lanes(b_.variance[c].row(py + dy) + x + dx);
          const Lanes noise = vp + (vp < vq ? vp : vq);
          const Lanes diff = load_lanes(b_.colour[c].row(py) + x) - load_lanes(b_.colour[c].row(py + dy) + x + dx);
          sum += (diff * diff - noise) / (epsilon + tolerance2_ * (vp + vq));
        }
        store_lanes(d + chunk * kLanes, sum);
      }
    }
    box_sum_patches(tile, s);
    const float inv_patch_area = 1.0f / static_cast<float>((2 * patch_ + 1) * (2 * patch_ + 1) * 3);
    // The neighbours inside the image: tile pixels first_inside <= i < end_inside of the rows
    // whose neighbour row is inside.
    const int first_inside = std::clamp(-(tile.x0 + dx), 0, tile.width);
    const int end_inside = std::clamp(b_.width - (tile.x0 + dx), 0, tile.width);
    for (int row = 0; row < tile.height; ++row) {
      const int qy = tile.y0 + row + dy;
      const bool row_inside = qy >= 0 && qy < b_.height;
      const float* patch = s.distance.data() + static_cast<std::size_t>(row) * kTileSize;
      const float* feature = s.feature_distance.data() + static_cast<std::size_t>(row) * kTileSize;
      for (int group = 0; group < kGroups; ++group) {
        const int i = group * kLanes;
        Lanes colour = clamped_distance(load_lanes(patch + i) * inv_patch_area);
        colour = colour > 0.0f ? colour : Lanes{};
        float* w = weight_lanes(s, row, group, offset);
        store_lanes(w, exp_negative(colour + load_lanes(feature + i)));
        for (int lane = 0; lane < kLanes; ++lane)
          if (!row_inside || i + lane < first_inside || i + lane >= end_inside) w[lane] = 0.0f;
      }
    }
  }

  // Sums s.distance (padded tile rows, distance_stride_ apart) over each tile pixel's
  // (2·patch+1)² patch, in a fixed order (across, then down), into its first tile.height rows,
  // kTileSize apart.
  RTPRO_AVX2_CLONES void box_sum_patches(const Tile& tile, TileScratch& s) const {
    const int padded_height = tile.height + 2 * patch_;
    const int taps = 2 * patch_ + 1;
    for (int row = 0; row < padded_height; ++row) {
      const float* d = s.distance.data() + static_cast<std::size_t>(row) * distance_stride_;
      float* a = s.across.data() + static_cast<std::size_t>(row) * kTileSize;
      for (int i = 0; i < kTileSize; i += kLanes) {
        Lanes sum = load_lanes(d + i);
        for (int t = 1; t < taps; ++t) sum += load_lanes(d + i + t);
        store_lanes(a + i, sum);
      }
    }
    for (int row = 0; row < tile.height; ++row) {
      const float* a = s.across.data() + static_cast<std::size_t>(row) * kTileSize;
      for (int i = 0; i < kTileSize; i += kLanes) {
        Lanes sum = load_lanes(a + i);
        for (int t = 1; t < taps; ++t) sum += load_lanes(a + static_cast<std::size_t>(t) * kTileSize + i);
        store_lanes(s.distance.data() + static_cast<std::size_t>(row) * kTileSize + i, sum);
      }
    }
  }

  // Squared feature differences over their tolerances, summed: albedo and normal per component;
  // inverse depth against what a plane through the pixel could change over the offset; and the
  // neighbour's firefly distance.
  RTPRO_AVX2_CLONES void compute_feature_distances(const Tile& tile, int dx, int dy, TileScratch& s) const {
    const float adx = static_cast<float>(std::abs(dx)), ady = static_cast<float>(std::abs(dy));
    for (int row = 0; row < tile.height; ++row) {
      const int py = tile.y0 + row;
      for (int i = 0; i < tile.width; i += kLanes) {
        const int x = tile.x0 + i;
        Lanes sum{};
        auto add_squared = [&](int first, float inv_tolerance2) {
          for (int f = first; f < first + 3; ++f) {
            const Lanes diff =
                load_lanes(b_.features[f].row(py) + x) - load_lanes(b_.features[f].row(py + dy) + x + dx);
            sum += diff * diff * inv_tolerance2;
          }
        };
        if (b_.albedo_first >= 0) add_squared(b_.albedo_first, inv_albedo2_);
        if (b_.normal_first >= 0) add_squared(b_.normal_first, inv_normal2_);
        if (b_.depth >= 0) {
          const Lanes p = load_lanes(b_.features[b_.depth].row(py) + x);
          const Lanes diff = p - load_lanes(b_.features[b_.depth].row(py + dy) + x + dx);
          const Lanes allowed = load_lanes(b_.depth_slope_x.row(py) + x) * adx +
                                load_lanes(b_.depth_slope_y.row(py) + x) * ady + kDepthRelativeSlack * p + 1e-6f;
          sum += diff * diff * inv_depth2_ / (allowed * allowed);
        }
        if (b_.firefly_distance.width() > 0) sum += load_lanes(b_.firefly_distance.row(py + dy) + x + dx);
        store_lanes(s.feature_distance.data() + static_cast<std::size_t>(row) * kTileSize + i, clamped_distance(sum));
      }
    }
  }

  // For each pixel of one tile row: the weighted sums of the regression over the window (the
  // normal equations XᵀWX and XᵀWY), kLanes pixels and one window row at a time, then the fit's
  // value at the pixel.
  RTPRO_AVX2_CLONES void regress_row(const Tile& tile, int row, TileScratch& s, Image& out) const {
    const int py = tile.y0 + row;
    const int d = regressors_, features = d - 3;
    std::fill(s.sums.begin(), s.sums.end(), 0.0f);
    for (int lane0 = 0; lane0 < tile.width; lane0 += kLanes) {
      const int x0 = tile.x0 + lane0;
      for (int dy = -radius_; dy <= radius_; ++dy) {
        for (int column = 0; column < window_; ++column) {
          const int dx = column - radius_;
          const int offset = (dy + radius_) * window_ + column;
          // e: each regressed feature's difference from the pixel's own, the screen offset
          // (in window radii), 1 (the intercept), then the colour.
          float* e = s.e.data() + static_cast<std::size_t>(column) * (d + 3) * kLanes;
          for (int f = 0; f < features; ++f) {
            const PaddedPlane& plane = b_.features[regressed_[f]];
            store_lanes(e + f * kLanes, load_lanes(plane.row(py + dy) + x0 + dx) - load_lanes(plane.row(py) + x0));
          }
          store_lanes(e + features * kLanes, Lanes{} + static_cast<float>(dx) / static_cast<float>(radius_));
          store_lanes(e + (features + 1) * kLanes, Lanes{} + static_cast<float>(dy) / static_cast<float>(radius_));
          store_lanes(e + (d - 1) * kLanes, Lanes{} + 1.0f);
          for (int c = 0; c < 3; ++c)
            store_lanes(e + (d + c) * kLanes, load_lanes(b_.colour[c].row(py + dy) + x0 + dx));
          const Lanes w = load_lanes(weight_lanes(s, row, lane0 / kLanes, offset));
          float* wx = s.wx.data() + static_cast<std::size_t>(column) * d * kLanes;
          for (int r = 0; r < d; ++r) store_lanes(wx + r * kLanes, w * load_lanes(e + r * kLanes));
        }
        accumulate_moments(d, s.wx.data(), s.e.data(), window_, s.sums.data() + lane0);
      }
    }
    for (int i = 0; i < tile.width; ++i) {
      float fitted[3];
      solve(s.sums.data() + i, fitted);
      const int x = tile.x0 + i;
      for (int c = 0; c < 3; ++c) {
        // A fit may undershoot below zero next to a bright edge; light is never negative.
        const float value = fitted[c] * demodulation_factor(b_, x, py, c);
        out.at(x, py, c) = value > 0.0f ? value : 0.0f;
      }
    }
  }

  // The fitted colour at the pixel from its sums (moment m at sums[m·kTileSize]): the intercept of
  // the weighted least-squares fit. The intercept is the last regressor, so after the Cholesky
  // factorisation M = LLᵀ only the forward substitution is needed (Lᵀβ = z ends in
  // L_dd·β_d = z_d). A regressor whose pivot vanishes (a feature constant over the window) is
  // left out of the fit.
  void solve(const float* sums, float fitted[3]) const {
    const int d = regressors_;
    double l[kMaxRegressors][kMaxRegressors];
    double z[kMaxRegressors][3];
    double diagonal[kMaxRegressors];
    int moment = 0;
    for (int r = 0; r < d; ++r)
      for (int k = 0; k <= r; ++k, ++moment) l[r][k] = sums[static_cast<std::size_t>(moment) * kTileSize];
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < 3; ++c, ++moment) z[r][c] = sums[static_cast<std::size_t>(moment) * kTileSize];
    // The intercept's own sums: the total weight and the weighted colour.
    const std::size_t intercept = static_cast<std::size_t>((d - 1) * d / 2 + d - 1);
    const double total_weight = sums[intercept * kTileSize];
    for (int r = 0; r < d - 1; ++r) l[r][r] += kRidge * (l[r][r] + total_weight);
    for (int r = 0; r < d; ++r) diagonal[r] = l[r][r];

    // In place: row r of L from row r of M and the rows above; then row r of z = L⁻¹·XᵀWY.
    for (int r = 0; r < d; ++r) {
      for (int k = 0; k <= r; ++k) {
        double sum = l[r][k];
        for (int j = 0; j < k; ++j) sum -= l[r][j] * l[k][j];
        if (k < r) l[r][k] = l[k][k] > 0.0 ? sum / l[k][k] : 0.0;
        else l[r][r] = sum > 1e-9 * diagonal[r] && sum > 0.0 ? std::sqrt(sum) : 0.0;
      }
      for (int c = 0; c < 3; ++c) {
        double sum = z[r][c];
        for (int j = 0; j < r; ++j) sum -= l[r][j] * z[j][c];
        z[r][c] = l[r][r] > 0.0 ? sum / l[r][r] : 0.0;
      }
    }
    const double pivot = l[d - 1][d - 1];
    const std::size_t weighted_colour = static_cast<std::size_t>(d * (d + 1) / 2 + 3 * (d - 1));
    for (int c = 0; c < 3; ++c) {
      double value = pivot > 0.0 ? z[d - 1][c] / pivot : 0.0;
      // The weighted mean when the fit fails: never worse than no filtering.
      if (!(pivot > 0.0) || !std::isfinite(value))
        value = total_weight > 0.0 ? sums[(weighted_colour + c) * kTileSize] / total_weight : 0.0;
      fitted[c] = static_cast<float>(value);
    }
  }

  // The features the regression fits: normal and inverse depth. (The albedo is divided out.)
  static std::vector<int> regressed_features(const DenoiseBuffers& b) {
    std::vector<int> list;
    if (b.normal_first >= 0)
      for (int c = 0; c < 3; ++c) list.push_back(b.normal_first + c);
    if (b.depth >= 0) list.push_back(b.depth);
    return list;
  }

  const DenoiseBuffers& b_;
  int radius_, patch_, window_;
  std::vector<int> regressed_;
  int regressors_, moments_;
  float tolerance2_, inv_albedo2_, inv_normal2_, inv_depth2_;
  // Row stride of the padded distance rows: whole chunks of lanes, and room for the box sum's
  // reads past the tile.
  int distance_stride_;
};

}  // namespace

// The regression reads kLanes pixels at a time: a tile's last lanes may lie past the image's
// right edge by up to kLanes - 1 pixels, beyond the window.
int regression_filter_pad(const DenoiseSettings& settings) {
  return settings.window_radius + settings.patch_radius + kLanes;
}

Image regression_filter(const DenoiseBuffers& buffers, const DenoiseSettings& settings) {
  Image out(buffers.width, buffers.height);
  const RegressionFilter filter(buffers, settings);
  std::vector<Tile> tiles;
  for (int y = 0; y < buffers.height; y += kTileSize)
    for (int x = 0; x < buffers.width; x += kTileSize)
      tiles.push_back({x, y, std::min(kTileSize, buffers.width - x), std::min(kTileSize, buffers.height - y)});
  tbb::enumerable_thread_specific<TileScratch> scratch([&] {
    TileScratch s;
    filter.prepare(s);
    return s;
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      TileScratch& s = scratch.local();
                      for (std::size_t t = range.begin(); t != range.end(); ++t) filter.filter(tiles[t], s, out);
                    });
  return out;
}

}  // namespace rtpro
