#pragma once
// Lambertian reflection: the same radiance towards every direction on the side it is lit from.
#include "bsdf_sample.h"

#include <numbers>
#include <optional>

namespace rtpro {

struct DiffuseBsdf {
  Color reflectance;  // the albedo, each channel in [0, 1]

  bool is_delta() const { return false; }
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
    return BsdfSample{reflectance * std::numbers::inv_pi_v<float>, cosine_direction, pdf, false, false};
  }
};

struct DiffuseSurface;  // scene/diffuse_material.h
struct Material;        // scene/render_scene.h
struct SurfacePoint;    // render/surface/surface.h
class TextureLookup;    // image/texture_lookup.h
struct SurfaceBsdf;     // render/bsdf/material_bsdf.h

// A diffuse material's BSDF at `point`, as render/bsdf/material_bsdf.h asks of every kind: written into
// `out` (its frame left to the caller), the shading normal returned.
Vec3 bsdf_from(const DiffuseSurface& model, const Material& material, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);

}  // namespace rtpro
