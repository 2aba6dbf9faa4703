#include "rtpro/render/environment_light.h"

#include "rtpro/core/large_buffer.h"

#include "rtpro/core/math_constants.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

namespace rtpro {

namespace {

float clean(float value) { return std::isfinite(value) && value > 0.0f ? value : 0.0f; }

float luminance(const Color& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

float channel_average(const Color& c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }

// The weights a bilinear reconstruction gives a texel's neighbours, averaged over one pixel's
// cell: the cell's own texel 3/4, each neighbour 1/8 (per axis).
constexpr float kCellWeights[3] = {0.125f, 0.75f, 0.125f};

float row_sin_theta(std::size_t y, std::size_t h) {
  return std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
}

// Each cell's luminance × sin θ in `func` becomes its luminance above the mean over the sphere
// (each cell weighed by its solid angle, ∝ sin θ) × sin θ, or 0; left as it was, and false, when
// no cell is above the mean. Above by less than 10⁻⁴ of the mean is not above: in an image of one
// colour the rounding of luminance × sin θ leaves some cells that far over.
bool keep_above_mean(std::span<float> func, std::size_t w, std::size_t h) {
  double weighted = 0.0, weights = 0.0;
  for (std::size_t y = 0; y < h; ++y) {
    double row = 0.0;
    for (std::size_t x = 0; x < w; ++x) row += func[y * w + x];
    weighted += row;
    weights += static_cast<double>(row_sin_theta(y, h)) * static_cast<double>(w);
  }
  if (!(weights > 0.0)) return false;
  const double mean = weighted / weights;
  const auto above = [&](std::size_t y, std::size_t x) {
    const double sin_theta = row_sin_theta(y, h);
    const double excess = static_cast<double>(func[y * w + x]) - mean * sin_theta;
    return excess > 1e-4 * mean * sin_theta ? static_cast<float>(excess) : 0.0f;
  };
  // Whether any cell is above first, then the cells in place: func stays as it was where none is.
  bool any = false;
  for (std::size_t y = 0; y < h && !any; ++y)
    for (std::size_t x = 0; x < w && !any; ++x) any = above(y, x) > 0.0f;
  if (!any) return false;
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) func[y * w + x] = above(y, x);
  return true;
}

}  // namespace

void check_environment_radiance(const Image& image, const Environment& environment) {
  const std::size_t channels = static_cast<std::size_t>(std::max(image.channel_count(), 1));
  const std::size_t colour_channels = std::min<std::size_t>(channels, 3);
  const float scale[3] = {environment.scale.x, environment.scale.y, environment.scale.z};
  std::size_t bad = 0, first = 0;
  float first_value = 0.0f;
  for (std::size_t i = 0; i < image.data.size(); ++i) {
    const std::size_t channel = i % channels;
    if (channel >= colour_channels) continue;
    const float value = image.data[i];
    // Negative values read as 0 (EXR filtering leaves small ones); the scale is 0 or more.
    const float radiance = value > 0.0f ? value * (colour_channels == 1 ? scale[1] : scale[channel]) : 0.0f;
    if (std::isfinite(value) && radiance <= kMaxEnvironmentRadiance) continue;
    if (bad++ == 0) {
      first = i / channels;
      first_value = value;
    }
  }
  if (bad == 0) return;
  const auto width = static_cast<std::size_t>(std::max(image.width, 1));
  throw InputError(SourceLocation{environment.file.string()},
                   "pixel (" + std::to_string(first % width) + ", " + std::to_string(first / width) + ") is " +
                       std::to_string(first_value) +
                       " (times the environment's color x intensity): a radiance that is not finite or above 1e12; " +
                       std::to_string(bad) + " values in all");
}

EnvironmentSampling environment_sampling_for(const RenderSettings& render) {
  return render.integrator == Integrator::kPath && render.path_sampling == PathSampling::kMis
             ? EnvironmentSampling::kAboveMean
             : EnvironmentSampling::kWhole;
}

EnvironmentLight::EnvironmentLight(const Environment& environment, Image image, EnvironmentSampling sampling)
    : to_world_(environment.to_world), to_local_(inverse(environment.to_world).value_or(Affine::identity())),
      scale_(environment.scale), visible_(environment.visible) {
  if (image.width <= 0 || image.height <= 0 || image.data.empty()) {
    mean_radiance_ = channel_average(scale_);
    return;
  }
  width_ = image.width;
  height_ = image.height;
  const auto w = static_cast<std::size_t>(width_), h = static_cast<std::size_t>(height_);
  resize_large(texels_, w * h);  // in huge pages (large_buffer.h), as the file's pixels were read
  const int channels = image.channel_count();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, h), [&](const tbb::blocked_range<std::size_t>& rows) {
    for (std::size_t y = rows.begin(); y < rows.end(); ++y)
      for (std::size_t x = 0; x < w; ++x) {
        const float* p = &image.data[(y * w + x) * static_cast<std::size_t>(channels)];
        const Color c = channels >= 3 ? Color(p[0], p[1], p[2]) : Color(p[0]);
        texels_[y * w + x] = Color(clean(c.x), clean(c.y), clean(c.z)) * scale_;
      }
  });
  image = Image();  // the file's pixels are no longer needed: keep the peak low

  // Each cell weighs what the bilinear lookup shows over it (so a cell is never 0 where the
  // lookup is not) by luminance and by sin θ, the solid angle a row's cells cover. Luminance is
  // linear, so the cell average is filtered from the texels' luminance, one axis at a time.
  // Uninitialised, in huge pages: every cell is written before it is read, and as vectors of 2 MB
  // each they took 1,024 page faults of ~13 us.
  HugePageBuffer<float> func_cells(w * h), across_cells(w * h);
  const std::span<float> func(func_cells.get(), w * h), across(across_cells.get(), w * h);
  std::vector<double> row_sums(h);
  const auto for_rows = [h](auto&& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, h), [&](const tbb::blocked_range<std::size_t>& rows) {
      for (std::size_t y = rows.begin(); y < rows.end(); ++y) body(y);
    });
  };
  for_rows([&](std::size_t y) {
    const float sin_theta = row_sin_theta(y, h);
    double row_sum = 0.0;
    for (std::size_t x = 0; x < w; ++x) {
      func[y * w + x] = luminance(texels_[y * w + x]);
      row_sum += static_cast<double>(channel_average(texels_[y * w + x])) * sin_theta;
    }
    row_sums[y] = row_sum;
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t left = x == 0 ? w - 1 : x - 1, right = x + 1 == w ? 0 : x + 1;
      across[y * w + x] = kCellWeights[0] * func[y * w + left] + kCellWeights[1] * func[y * w + x] +
                          kCellWeights[2] * func[y * w + right];
    }
  });
  for_rows([&](std::size_t y) {
    const float sin_theta = row_sin_theta(y, h);
    const std::size_t up = y == 0 ? 0 : y - 1, down = y + 1 == h ? y : y + 1;
    for (std::size_t x = 0; x < w; ++x)
      func[y * w + x] = (kCellWeights[0] * across[up * w + x] + kCellWeights[1] * across[y * w + x] +
                         kCellWeights[2] * across[down * w + x]) *
                        sin_theta;
  });
  across_cells = HugePageBuffer<float>();
  if (sampling == EnvironmentSampling::kAboveMean && keep_above_mean(func, w, h)) sampling_ = sampling;
  distribution_ = Distribution2D(func, width_, height_);
  // The sphere's mean: each row's cells cover 2π² sin θ / (w·h) of solid angle per unit of (u, v).
  double total = 0.0;
  for (double s : row_sums) total += s;
  mean_radiance_ =
      static_cast<float>(total * (2.0 * kPi * kPi) / (static_cast<double>(w) * static_cast<double>(h)) / (4.0 * kPi));
}

EnvironmentLight::ImageCoordinates EnvironmentLight::image_coordinates(const Vec3& world_direction) const {
  if (width_ == 0) return {0.0f, 0.0f};
  const Vec3 d = normalize(to_local_.apply_vector(world_direction));
  const float u = 0.5f + std::atan2(d.z, d.x) * (0.5f * kInvPi);
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) * kInvPi;
  return {u, v};
}

Color EnvironmentLight::lookup(float u, float v) const {
  const float s = u * static_cast<float>(width_) - 0.5f;
  const float t = v * static_cast<float>(height_) - 0.5f;
  const float fs = std::floor(s), ft = std::floor(t);
  const float ax = s - fs, ay = std::clamp(t - ft, 0.0f, 1.0f);
  // The column modulo the width; x is within a column of [0, width) but where u is not in [0, 1],
  // and the remainder's division is the slow way to those two cases.
  const auto wrap = [this](float x) {
    int i = static_cast<int>(x);
    if (i < 0 || i >= width_) i %= width_;
    return static_cast<std::size_t>(i < 0 ? i + width_ : i);
  };
  const auto row = [this](float y) {
    return static_cast<std::size_t>(std::clamp(static_cast<int>(y), 0, height_ - 1));
  };
  const std::size_t x0 = wrap(fs), x1 = wrap(fs + 1.0f);
  const std::size_t y0 = row(ft), y1 = row(ft + 1.0f);
  const auto w = static_cast<std::size_t>(width_);
  const Color top = texels_[y0 * w + x0] * (1.0f - ax) + texels_[y0 * w + x1] * ax;
  const Color bottom = texels_[y1 * w + x0] * (1.0f - ax) + texels_[y1 * w + x1] * ax;
  return top * (1.0f - ay) + bottom * ay;
}

Color EnvironmentLight::radiance(const Vec3& direction) const { return radiance_at(image_coordinates(direction)); }

Color EnvironmentLight::radiance_at(ImageCoordinates uv) const {
  if (width_ == 0) return scale_;
  return lookup(uv.u, uv.v);
}

std::optional<EnvironmentLight::Sample> EnvironmentLight::sample(Sample2D u) const {
  const std::optional<Vec3> direction = sample_direction(u);
  if (!direction) return std::nullopt;
  // The pdf of the direction as pdf() finds it again, so both strategies see one number.
  const ImageCoordinates uv = image_coordinates(*direction);
  const float pdf = pdf_at(uv);
  if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
  return Sample{*direction, radiance_at(uv), pdf};
}

std::optional<Vec3> EnvironmentLight::sample_direction(Sample2D u) const {
  if (!(mean_radiance_ > 0.0f)) return std::nullopt;
  if (width_ == 0) {
    // Uniform over the sphere.
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), z, r * std::sin(phi));
  }
  const Distribution2D::Sample s = distribution_.sample(u);
  const float theta = kPi * s.v, phi = 2.0f * kPi * (s.u - 0.5f);
  const float sin_theta = std::sin(theta);
  if (!(sin_theta > 0.0f) || !(s.pdf > 0.0f)) return std::nullopt;
  const Vec3 local(sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi));
  return normalize(to_world_.apply_vector(local));
}

float EnvironmentLight::pdf(const Vec3& direction) const { return pdf_at(image_coordinates(direction)); }

float EnvironmentLight::pdf_at(ImageCoordinates uv) const {
  if (!(mean_radiance_ > 0.0f)) return 0.0f;
  if (width_ == 0) return 1.0f / (4.0f * kPi);
  const float sin_theta = std::sin(kPi * uv.v);
  if (!(sin_theta > 0.0f)) return 0.0f;
  return distribution_.pdf(uv.u, uv.v) / (2.0f * kPi * kPi * sin_theta);
}

std::size_t EnvironmentLight::bytes() const { return texels_.size() * sizeof(Color) + distribution_.bytes(); }

std::uint64_t EnvironmentLight::peak_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels) {
  const std::uint64_t pixels = saturating_multiply(width, height);
  // The constructor's two phases: the file's floats beside the texels; then the texels, the
  // luminance table and, once the filtered copy is freed, the distribution built from the table.
  const std::uint64_t reading =
      saturating_multiply(pixels, saturating_add(saturating_multiply(channels, sizeof(float)), sizeof(Color)));
  const std::uint64_t filtering = saturating_multiply(pixels, sizeof(Color) + 2 * sizeof(float));
  const std::uint64_t sampling = saturating_add(saturating_multiply(pixels, sizeof(Color) + sizeof(float)),
                                                Distribution2D::bytes_for(width, height));
  return std::max({reading, filtering, sampling});
}

}  // namespace rtpro
