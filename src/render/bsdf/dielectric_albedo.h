#pragma once
// E(μ, α, η): the share of the energy arriving at a rough dielectric interface (GGX, α) from one
// side, at incidence cos θ = μ, that leaves it after a single scattering, reflected or refracted,
// for the exact Fresnel term (or glTF's Schlick approximation) and η = n on the far side / n on the near side (η > 1 entering the
// denser medium, η < 1 leaving it, where total internal reflection counts as reflected). What is
// missing, 1 − E, is the energy that in reality scatters between facets more than once: from 1%
// at α = 0.04 to 35% at α = 1, grazing.
//
// The energy albedo, not the radiance albedo: transmitted light carries the radiance scale
// 1/η² elsewhere (DielectricBsdf), and without it a smooth interface has E = R + T = 1 exactly.
//
// Tables over (√μ, √α) per node of t = (η' − 1)/(η' + 1), η' = max(η, 1/η), evenly spaced, one for
// each side of the interface. Each η node's pair is integrated deterministically (a fixed
// quadrature over the visible-normal sampler's unit square, as the conductor's tables) the first
// time an index near it is asked for, so a scene pays only for the indices it uses: about 0.1 s
// per node, two nodes per index. A render builds them ahead of its tiles
// (prepare_rough_dielectric_albedo), where the first tile to ask built them alone while the others
// waited.
#include <span>

namespace rtpro {

enum class GlassFresnel {
  kExact,    // fresnel_dielectric (render/bsdf/dielectric.h): DielectricBsdf
  kSchlick,  // schlick_glass_fresnel below: PrincipledBsdf's glass, untinted
};

// Schlick's F with F0 = ((η − 1)/(η + 1))², taken at the cosine on the outside: from inside
// (η < 1) that of the refracted direction, and 1 beyond the critical angle.
float schlick_glass_fresnel(float cos_incident, float eta);

float rough_dielectric_albedo(float mu, float alpha, float eta, GlassFresnel fresnel = GlassFresnel::kExact);

// An interface whose rough_dielectric_albedo a render will read: its index of refraction (either
// side's relative η reads the same nodes) and Fresnel model.
struct RoughInterface {
  float ior;
  GlassFresnel fresnel;
};
// Builds the η nodes of every interface now, side by side on the task arena's threads; call it
// outside any render task. The lookups then find them built (and still build any other).
void prepare_rough_dielectric_albedo(std::span<const RoughInterface> interfaces);

// The node value itself, integrated afresh (no table): what the tables interpolate, for tests.
float integrate_rough_dielectric_albedo(float mu, float alpha, float eta, GlassFresnel fresnel, int quadrature);

}  // namespace rtpro
