#pragma once
// The environment as a light: radiance arriving from every direction a ray escapes along, looked
// up in a latitude-longitude image (bilinearly filtered, wrapping around the horizon) or constant,
// and sampled in proportion to the image's luminance × sin θ from a piecewise-constant
// distribution over its pixels, with the exact solid-angle pdf of every direction for multiple
// importance sampling.
//
// Under multiple importance sampling the distribution can leave out what BSDF samples find as
// well: with EnvironmentSampling::kAboveMean each pixel weighs only its luminance above the
// image's mean (MIS compensation: Karlík, Šik, Vévoda, Skřivan and Křivánek 2019; pbrt-v4's image
// infinite light samples so under MIS). The dim sky goes to the BSDF samples, which meet it as
// often as the light samples would, and the light samples go to the sun and the bright sky.
//
// The image's frame is +Y up; its top row looks up, its centre column looks along +X and its
// quarter column (u = 0.25) along −Z: Blender's mapping of a world texture, as a scene exported
// to glTF (+Y up) sees it. `rotation` turns that frame into the world.
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"
#include "rtpro/image/image.h"
#include "rtpro/render/distribution_2d.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rtpro {

// Throws InputError naming the environment's file and the first pixel (from the top left) whose
// radiance, its value × colour × intensity, is not finite or is above kMaxEnvironmentRadiance,
// with how many such pixels there are. Call it on the image as read, before the light is built.
void check_environment_radiance(const Image& image, const Environment& environment);

// What the environment's light samples are drawn in proportion to: every pixel's luminance
// (`kWhole`), or only its luminance above the image's mean (`kAboveMean`), which is unbiased only
// where another strategy (BSDF or phase function samples, weighted by MIS) covers every direction
// the light has pdf 0 for. An image with nothing above its mean (one colour) is sampled whole.
enum class EnvironmentSampling : std::uint8_t { kWhole, kAboveMean };

// The sampling the render's integrator can use: above the mean for the path integrator's MIS.
EnvironmentSampling environment_sampling_for(const RenderSettings& render);

class EnvironmentLight {
 public:
  // `image`: the environment's file as read (scene-linear; one channel is grey, the first three
  // of more are RGB), or empty for a constant environment. Negative and non-finite values read
  // as 0. The distribution is built in parallel (oneTBB).
  EnvironmentLight(const Environment& environment, Image image, EnvironmentSampling sampling);

  // What sample() draws in proportion to: kAboveMean only when asked and the image has pixels above
  // its mean.
  EnvironmentSampling sampling() const { return sampling_; }

  // What arrives from world direction `direction` (any length but 0).
  Color radiance(const Vec3& direction) const;
  // Where a world direction falls in the image (u across from the left, v down from the top, both
  // [0, 1]; nothing to find for a constant environment): found once, for both radiance_at and
  // pdf_at, which give what radiance() and pdf() give for that direction.
  struct ImageCoordinates {
    float u, v;
  };
  ImageCoordinates image_coordinates(const Vec3& world_direction) const;
  Color radiance_at(ImageCoordinates uv) const;
  float pdf_at(ImageCoordinates uv) const;

  struct Sample {
    Vec3 direction;  // unit, world space, towards the environment
    Color radiance;
    float pdf;  // solid angle
  };
  // Nothing when the environment is black everywhere.
  std::optional<Sample> sample(Sample2D u) const;
  // sample()'s direction alone, without its pdf and radiance (pdf() and radiance() of it, bit for
  // bit sample()'s where it has one; sample() has none where that pdf is not positive and
  // finite): a light sample whose shadow ray is then stopped needs neither.
  std::optional<Vec3> sample_direction(Sample2D u) const;
  // The solid-angle pdf sample() has of `direction`.
  float pdf(const Vec3& direction) const;

  bool visible() const { return visible_; }
  // The mean of radiance() over the sphere (averaged over channels): what the light picker weighs it by.
  float mean_radiance() const { return mean_radiance_; }
  // Bytes held (image and distribution).
  std::size_t bytes() const;
  // Bytes that reading a width × height image of `channels` channels and building the light from
  // it hold at their peak, counted from the file's header before it is read: the decoded floats
  // with the light's copy beside them, then the copy with the luminance table and the sampling
  // distribution; 24 bytes a pixel for RGB. A file can be far smaller: a run-length encoded .hdr
  // of one colour compresses about 250 to 1 (17 MB of file declared 16384x16384 pixels, 6.4 GB).
  static std::uint64_t peak_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t channels);

 private:
  Color lookup(float u, float v) const;

  Affine to_world_, to_local_;
  Color scale_;
  bool visible_;
  EnvironmentSampling sampling_ = EnvironmentSampling::kWhole;
  int width_ = 0, height_ = 0;  // 0: constant
  std::vector<Color> texels_;   // width × height, top row first, scale applied
  Distribution2D distribution_;
  float mean_radiance_ = 0.0f;
};

}  // namespace rtpro
