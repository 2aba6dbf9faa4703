#pragma once
// Curves in the backends, the kind's backend side in one place (as sphere_backend.h has it for
// spheres; its scene side is scene/curve_geometry.h): the native traversal's hits through
// curve_intersect.h, and Embree's own round and flat curve geometries over the shared control
// points. The two surfaces differ within the tolerance curve_intersect.h states. Registered in
// backend_shapes.h.
#include "curve_intersect.h"
#include "embree_handles.h"
#include "ray_packet.h"
#include "shape_hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

namespace rtpro {

// Segment `prim` against one ray, within (ray.tnear, t_max).
inline bool native_hit(const CurveSet& curves, std::uint32_t prim, const Ray& ray, float t_max, ShapeHit& hit) {
  CurveHit ch;
  if (!intersect_curve_segment(bezier_segment(curves, prim), curves.shape, curves.basis, ray.org, ray.dir, ray.tnear,
                               t_max, ch))
    return false;
  hit = {ch.t, ch.u, ch.v};
  return true;
}

// Segment `prim` against the `lanes` of a packet, lane by lane.
template <typename OnHit>
inline void native_hit_lanes(const CurveSet& curves, std::uint32_t prim, const RayPacket& packet, std::uint32_t lanes,
                             OnHit&& on_hit) {
  const BezierSegment segment = bezier_segment(curves, prim);
  for (; lanes != 0; lanes &= lanes - 1) {
    const auto k = static_cast<unsigned>(std::countr_zero(lanes));
    const Ray& ray = *packet.rays[k];
    CurveHit ch;
    if (intersect_curve_segment(segment, curves.shape, curves.basis, ray.org, ray.dir, ray.tnear, packet.tmax[k], ch))
      on_hit(k, ch.t, ch.u, ch.v);
  }
}

// Why Embree cannot take the curves (a point beyond its coordinate range, a negative or
// non-finite radius, a segment past the points), or nothing.
std::optional<std::string> embree_refusal(const CurveSet& curves);

// Shares the control points and segments with Embree, which must outlive the geometry.
EmbreeGeometry new_embree_geometry(RTCDevice device, const CurveSet& curves, RTCBuildQuality quality);

// Embree's curve kernels decide the hits, and its packets answer some rays otherwise than the same
// rays alone (scenes/curves.yaml's image moved with every batch in packets).
inline bool hits_decided_by_rtpro(const CurveSet&) { return false; }
inline bool packet_lanes_answer_alone(const CurveSet&, bool /*compact*/) { return false; }

}  // namespace rtpro
