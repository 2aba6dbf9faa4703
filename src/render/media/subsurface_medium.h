#pragma once
// The medium a random walk under a surface travels in (render/integrators/subsurface_walk.h),
// made from what an artist sets, as Cycles makes it (kernel/closure/bssrdf.h and
// integrator/subsurface_random_walk.h, Blender 3.4): a surface albedo A, a radius r and an
// anisotropy g per material. Per channel:
//
//   mean free path  ℓ = r·√(3(1 − α')) for SubsurfaceMethod::kRandomWalk, α' the single-scattering
//                   albedo whose semi-infinite dipole reflects A (Jensen et al. 2001, with the
//                   boundary term of the material's ior): r is then the diffusion length 1/σtr,
//                   how far light spreads; ℓ = r/(4π) for kRandomWalkFixedRadius
//   σt = 1/(ℓ (1 − g))   so that the reduced coefficient σt(1 − g) is 1/ℓ whatever g
//   α = σs/σt            from A by the fit of Wrenninge, Villemin and Hery ("Path Traced
//                        Subsurface Scattering using Anisotropic Phase Functions and
//                        Non-Exponential Free Flights", Pixar 2017) to brute-force walks in a
//                        half-space: a walk of albedo α under a smooth boundary reflects A
//
// α is kept at least 0.2: below it a walk would end on its first scattering events, the image's
// colour jumping as A goes to 0; what α gains there the walk's starting weight loses (× α/0.2).
#include "rtpro/core/vec3.h"
#include "rtpro/scene/principled_material.h"

#include <optional>

namespace rtpro {

struct SubsurfaceMedium {
  Color sigma_t;  // extinction per scene unit, per channel
  Color albedo;   // single-scattering albedo σs/σt, per channel
  float anisotropy;
  // Multiplies the walk's starting weight (the lower bound of α).
  Color weight;
};

// `surface_albedo` in [0, 1] per channel, `radius` above 0 per channel (scene units), anisotropy
// in [0, 0.9], `ior` the surface's (the dipole's boundary; clamped to [1.01, 3.8] as Cycles does).
SubsurfaceMedium subsurface_medium(const Color& surface_albedo, const Color& radius, float anisotropy, float ior,
                                   SubsurfaceMethod method);

// subsurface_medium of the last inputs again, as long as they repeat: making a medium costs about a
// hundred exponentials, powers and arc tangents (the dipole's bisection, the albedo fit), as much
// as tens of a walk's flights, and a scene's walks mostly start under one untextured material.
class SubsurfaceMediumCache {
 public:
  const SubsurfaceMedium& get(const Color& surface_albedo, const Color& radius, float anisotropy, float ior,
                              SubsurfaceMethod method);

 private:
  struct Inputs {
    Color surface_albedo, radius;
    float anisotropy, ior;
    SubsurfaceMethod method;
    bool operator==(const Inputs&) const = default;
  };
  std::optional<Inputs> inputs_;
  SubsurfaceMedium medium_{};
};

// The single-scattering albedo whose walk in a half-space of anisotropy g reflects `surface_albedo`.
float single_scattering_albedo(float surface_albedo, float g);

// The diffuse reflectance R_d of a semi-infinite dipole of reduced albedo α' (Jensen et al. 2001,
// eq. 5 simplified at the surface), `boundary` the 4/3·(1 + F_dr)/(1 − F_dr) term of its ior, and
// its inverse in α' (bisection: R_d grows with α').
float dipole_reflectance(float reduced_albedo, float boundary);
float dipole_reduced_albedo(float reflectance, float boundary);

}  // namespace rtpro
