#pragma once
// A moving instance's world-to-object placements for the lanes of a packet, each at its own ray
// time. Every lane that enters a moving instance interpolates its placement and inverts it (in
// double, nine divisions): about 15% of the native backend's Whitted frame of a turning dragon,
// one lane at a time. Here four lanes are inverted at once in AVX2 doubles, by the same IEEE
// operations in the same order as inverse() runs them for one, so each lane's placement is
// placement_at's to the bit, and so is every hit in the instance.
#include "rtpro/core/transform.h"
#include "rtpro/scene/render_scene.h"

namespace rtpro {

inline constexpr unsigned kPlacementLanes = 4;

// placement_at(instance, times[k])->world_to_object into out[k] for each k < count (at most
// kPlacementLanes; the instance moves); bit k of the result is set where that placement exists
// (placement_at gives nothing where the interpolated matrix is singular).
unsigned world_to_object_lanes(const Instance& instance, const float* times, unsigned count, Affine* out);

}  // namespace rtpro
