#pragma once
// Glass, water, any interface between two dielectrics: reflection and refraction, smooth (delta
// lobes) or rough (GGX microfacets, Walter et al. 2007, as pbrt-v4's DielectricBxDF). The local
// +z points to the outside; wo.z < 0 means the surface is seen from inside.
//
// Transmitted radiance is scaled by (n_wo / n_wi)², the change of radiance across an interface
// (pbrt's TransportMode::Radiance): a path entering glass takes 1/η², leaving it η², so a closed
// glass object in a uniform furnace neither brightens nor darkens it.
//
// Single scattering loses the light that bounces between facets more than once (a third of it at
// α = 1, grazing), and every interface a path crosses loses it again: without compensation a
// rough glass sphere in a white furnace reads 0.62 at roughness 0.7. The compensation is
// Turquin's (2019), as Cycles 4 has it for glass: reflection and transmission alike are divided by
// E(μo), the interface's single-scattering energy albedo seen from wo's side
// (render/bsdf/dielectric_albedo.h; one table for each side, since from inside total internal
// reflection changes the split, not the sum). So the energy albedo is 1 at every roughness and
// from either side. Sampling: a visible normal (Heitz 2018), reflection or refraction by the
// facet's F, and the direction kept with probability G(wo, wi)/G1(wo), else drawn again: what is
// kept is distributed exactly as the compensated f·|cos θi| (of energy), so every sample weighs
// exactly what a smooth interface's does (1, times the radiance scale), where weighting the
// single-scattering sample by G/G1/E instead compounds along the chains of internal reflections
// in a glass object (a 64×64 furnace at 256 spp, roughness 0.3: max pixel 1.69 that way; 1.000
// this way, with Russian roulette reading the throughput without the radiance scale). The pdf is
// that of single scattering times G/G1/E(μo). Unlike Kulla and Conty's added diffuse-like lobe it
// spreads the missing light along the lobes it belongs to, and a rough glass does not turn milky.
//
// What that costs is reciprocity: the scale follows wo alone, so f(wo, wi) n_wi² E(wo) =
// f(wi, wo) n_wo² E(wi) rather than without the E's. The path tracer traces radiance only, wo
// towards the camera, where this is the right adjoint; a light tracer would need the scale on wi.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "microfacet.h"

#include <algorithm>
#include <optional>

namespace rtpro {

struct DielectricBsdf {
  float eta;    // n_inside / n_outside
  float alpha;  // GGX α; below kSmoothAlpha the interface is smooth
  // Off: the bare single-scattering model (Walter et al.'s, reciprocal), for tests and comparisons.
  bool energy_compensation = true;

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

  // The factor f carries for energy compensation at wo: 1/E(μo), or nothing with it off.
  std::optional<float> compensation(const Vec3& wo) const;
};

struct DielectricSurface;  // scene/dielectric_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const DielectricSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const DielectricSurface&) { return false; }

}  // namespace rtpro
