#pragma once
// The Phong material's shading side (its scene side is scene/phong_material.h): the Whitted model
// (colour, highlight, mirror) read as a physically plausible BSDF, so that a scene written for the
// whitted integrator path traces as it looks there. Three lobes, on whichever side wo is:
//
//   diffuse    Lambert of the material's colour kd
//   highlight  GGX reflection of constant reflectance ρs = 2·specular / (shininess + 2), roughness
//              α = √(2 / (4·shininess + 2))
//   mirror     perfect specular reflection of weight `reflectivity`
//
// The whitted integrator's highlight, specular·(r·l)^n without the 1/π its diffuse term lacks too,
// is exactly a normalised Phong lobe of albedo 2·specular / (n + 2) (the modified Phong BRDF,
// Lafortune and Willems 1994), whose width a Blinn-Phong exponent of about 4n matches; Walter et
// al. 2007 give the GGX α of a Blinn-Phong exponent as √(2 / (n + 2)). Peak and width of the
// highlight thus stay those the whitted integrator shows. Weights kd + ρs + reflectivity above 1
// (in any channel) would create light: the mirror is kept, the highlight takes at most what the
// mirror leaves, and the colour is scaled down (its hue kept) to what remains. Without highlight
// and mirror it is exactly a Lambert surface (DiffuseBsdf); with glass, smooth glass.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "microfacet.h"

#include <optional>

namespace rtpro {

// The GGX α of a Whitted highlight of exponent `shininess` (>= 0).
float phong_alpha(float shininess);
// The albedo of a Whitted highlight of weight `specular` and exponent `shininess`.
float phong_highlight_albedo(float specular, float shininess);

class PhongBsdf {
 public:
  // The lobes of the Whitted model's colour `kd`, highlight and mirror, energy kept (above).
  static PhongBsdf from_whitted(const Color& kd, float specular, float shininess, float reflectivity);

  const Color& diffuse() const { return diffuse_; }
  float highlight() const { return highlight_; }
  float mirror() const { return mirror_; }
  float alpha() const { return ggx_.alpha; }

  bool is_delta() const { return p_mirror_ == 1.0f; }
  // Filter Glossy widens the highlight; the mirror lobe, a weight of its own, stays a mirror.
  void roughen_to(float min_alpha) {
    if (ggx_.alpha < min_alpha) ggx_ = GgxDistribution{min_alpha};
  }
  // It reflects on whichever side wo is: the frame's +z is the side the ray came from.
  bool needs_outward_frame() const { return false; }
  // The diffuse and highlight lobes (the mirror only sampling finds).
  Color eval(const Vec3& wo, const Vec3& wi) const;
  // The density of sample() choosing wi through the diffuse or highlight lobe.
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // u_lobe chooses the mirror, diffuse or highlight lobe in proportion to their weights.
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const;

 private:
  PhongBsdf(const Color& diffuse, float highlight, float alpha, float mirror);
  // The highlight's f and density for wo, wi on the same side; 0 where the half vector is undefined.
  struct Highlight {
    float f, pdf;
  };
  Highlight highlight_at(const Vec3& wo, const Vec3& wi) const;

  Color diffuse_;
  float highlight_;
  float mirror_;
  GgxDistribution ggx_;
  float p_mirror_, p_diffuse_, p_highlight_;  // lobe choice, summing to 1 (0 each for a black surface)
};

struct PhongSurface;  // scene/phong_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const PhongSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
// Without glass, highlight and mirror it is a Lambert surface.
bool makes_lambert_bsdf(const PhongSurface& model);

}  // namespace rtpro
