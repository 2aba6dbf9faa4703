#pragma once
// Random-walk subsurface scattering (Chiang, Kutz and Burley 2016, as Cycles and Arnold trace it):
// a path that takes a principled material's subsurface lobe enters the surface and walks through
// the medium under it (render/media/subsurface_medium.h), with exponential free flights and
// Henyey–Greenstein scattering, each flight a ray through the backend, until a flight reaches a
// surface: that is where it leaves, through a Lambert lobe on the far side of that surface
// (Cycles' exit), and the path goes on from there with next-event estimation as at any vertex.
//
// The flights of a coloured medium sample one channel's σt each, the channel chosen in proportion
// to the throughput times the albedo, and weight the path by the balance heuristic over the three
// channels' densities (Chiang et al.'s spectral MIS; Cycles' volume_sample_channel): unbiased in
// every channel however different the radii. After kSimilarityBounces scattering events the walk
// turns isotropic with σs(1 − g) in place of σs, the similarity relation that keeps σt(1 − g) (so
// an anisotropic walk reaches its diffusion regime as fast as an isotropic one; as Cycles).
//
// A walk gives up after kMaxWalkSteps flights (Cycles' BSSRDF_MAX_BOUNCES), or once its
// throughput falls below 10⁻⁶ in every channel: the path ends there, its light absorbed. A walk
// leaves at the first surface a flight reaches, of whichever object: an object inside another's
// subsurface medium bounds it. Its random numbers come from the caller's stream, seeded from the
// vertex's sample key, so a walk is a pure function of (pixel, sample, dimension, seed).
#include "rtpro/backend/backend.h"
#include "medium_tracking.h"
#include "subsurface_medium.h"

#include <optional>

namespace rtpro {

inline constexpr int kMaxWalkSteps = 256;
inline constexpr int kSimilarityBounces = 9;

// Where a walk leaves: its last flight (unit direction, t in scene units) and the surface that
// flight reached, with the path's throughput there (the walk's weights applied).
struct SubsurfaceExit {
  Ray ray;
  Hit hit;
  Color beta;
};

// The walk from `entry`, its first flight (origin just under the surface, unit direction into
// it), for a path of throughput `beta`; nothing when it gives up. `time`: the path's time under an
// open shutter (every flight meets moving shapes where the path's other rays meet them), else none.
std::optional<SubsurfaceExit> subsurface_walk(const Backend& backend, const SubsurfaceMedium& medium, const Ray& entry,
                                              std::optional<float> time, const Color& beta, TrackingRandom& random);

}  // namespace rtpro
