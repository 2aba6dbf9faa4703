#pragma once
// Spheres in Embree: all spheres of a group form ONE user geometry whose callbacks call
// rtpro::intersect_sphere, the very function the native backend calls, with the float origin,
// direction and interval exactly as Embree hands them over. Top-level sphere hits are therefore
// bit-identical between the backends.
//
// Equal distances follow the shared tie rule (is_closer in hit.h): the lower (instance, geometry,
// primitive) wins. Embree leaves the hit record undefined inside callbacks, so the closest sphere
// hit of each ray is kept beside it, in a context that extends RTCIntersectContext.
#include "embree_handles.h"
#include "rtpro/backend/hit.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <type_traits>

namespace rtpro {

struct EmbreeIntersectContext {
  RTCIntersectContext base;  // first member: Embree passes &base to the callbacks
  // The closest sphere hit of each ray of the query so far, indexed by RTCRay::id. Each starts as
  // Hit{.t = ray.tfar} with invalid ids, so a sphere exactly at tfar is accepted as (tnear, tfar]
  // promises.
  Hit* closest_spheres;
};
static_assert(std::is_standard_layout_v<EmbreeIntersectContext>);

// A committed user geometry over `spheres`, which must outlive it. Queries through it must pass
// an EmbreeIntersectContext to rtcIntersect*, and plain contexts suffice for rtcOccluded*.
EmbreeGeometry new_embree_sphere_geometry(RTCDevice device, const SphereSet& spheres, RTCBuildQuality quality);

}  // namespace rtpro
