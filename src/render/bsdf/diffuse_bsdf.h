#pragma once
// Lambertian reflection: the same radiance towards every direction on the side it is lit from.
#include "bsdf_from.h"
#include "bsdf_sample.h"

#include <numbers>
#include <optional>

namespace rtpro {

struct DiffuseBsdf {
  Color reflectance;  // the albedo, each channel in [0, 1]

  bool is_delta() const { return false; }
  // No microfacet lobe to roughen (render/bsdf/bsdf.h, roughen_bsdf).
  void roughen_to(float /*min_alpha*/) {}
  // It reflects on whichever side wo is: the frame's +z is the side the ray came from.
  bool needs_outward_frame() const { return false; }
  Color eval(const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) return Color(0.0f);
    return reflectance * std::numbers::inv_pi_v<float>;
  }
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // Cosine-weighted on wo's side, so f·cos/pdf is the reflectance itself. u_lobe is unused.
  std::optional<BsdfSample> sample(const Vec3& wo, float /*u_lobe*/, Sample2D u) const {
    return sample_toward(wo, sample_cosine_hemisphere(u));
  }
  // The same sample from its direction on the +z side, sample_cosine_hemisphere(u), worked out
  // beforehand (the path integrator does so for a whole generation at once).
  std::optional<BsdfSample> sample_toward(const Vec3& wo, Vec3 cosine_direction) const {
    if (wo.z == 0.0f) return std::nullopt;
    if (wo.z < 0.0f) cosine_direction.z = -cosine_direction.z;
    const float pdf = cosine_hemisphere_pdf(abs_cos_theta(cosine_direction));
    // The disk's rim maps to the horizon, where the direction carries nothing.
    if (pdf == 0.0f) return std::nullopt;
    return BsdfSample{
        reflectance * std::numbers::inv_pi_v<float>, cosine_direction, pdf, false, false, BsdfLobe::kDiffuse};
  }
};

struct DiffuseSurface;  // scene/diffuse_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const DiffuseSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const DiffuseSurface&) { return true; }

}  // namespace rtpro
