#pragma once
// Glass, water, any interface between two dielectrics: reflection and refraction, smooth (delta
// lobes) or rough (GGX microfacets, Walter et al. 2007, as pbrt-v4's DielectricBxDF). The local
// +z points to the outside; wo.z < 0 means the surface is seen from inside.
//
// Transmitted radiance is scaled by (n_wo / n_wi)², the change of radiance across an interface
// (pbrt's TransportMode::Radiance): a path entering glass takes 1/η², leaving it η², so a closed
// glass object in a uniform furnace neither brightens nor darkens it.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "microfacet.h"

#include <algorithm>
#include <optional>

namespace rtpro {

struct DielectricBsdf {
  float eta;    // n_inside / n_outside
  float alpha;  // GGX α; below kSmoothAlpha the interface is smooth

  // η = 1 separates nothing: light passes straight through, whatever α says.
  bool is_delta() const { return eta == 1.0f || GgxDistribution{alpha}.effectively_smooth(); }
  // It tells the inside (eta) from the outside: the frame's +z must point outwards.
  bool needs_outward_frame() const { return true; }
  // α raised to at least min_alpha (render/bsdf/bsdf.h, roughen_bsdf).
  void roughen_to(float min_alpha) { alpha = std::max(alpha, min_alpha); }
  Color eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // Reflection when u_lobe < F (of wo to the sampled facet), transmission otherwise, so every
  // sample carries the weight of its lobe's share and none is split.
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const;
};

struct DielectricSurface;  // scene/dielectric_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const DielectricSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const DielectricSurface&) { return false; }

}  // namespace rtpro
