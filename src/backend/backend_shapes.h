#pragma once
// The kinds of shape the backends trace, registered: each kind's backend side is one header
// (native_hit, native_hit_lanes, embree_refusal, new_embree_geometry, hits_decided_by_rtpro,
// packet_lanes_answer_alone: see sphere_backend.h). A new kind of shape is its header's include
// here and its case in visit_geometry; the native traversal, the Embree scene builder and the
// Embree backend then name whatever it still lacks.
#include "curve_backend.h"
#include "sphere_backend.h"
#include "triangle_backend.h"
#include "rtpro/scene/render_scene.h"

#include <stdexcept>
#include <variant>

namespace rtpro {

// `visit` called with the geometry's alternative, chosen by a switch over its kind: in the native
// traversal's loops this takes fewer instructions than std::visit (callgrind: 1 to 3% of the
// packet traversal's own).
template <typename Visit>
[[gnu::always_inline]] inline decltype(auto) visit_geometry(const Geometry& geometry, Visit&& visit) {
  switch (kind_of(geometry)) {
    case GeometryKind::kSpheres: return visit(*std::get_if<SphereSet>(&geometry));
    case GeometryKind::kTriangles: return visit(*std::get_if<TriangleMesh>(&geometry));
    case GeometryKind::kInstance: return visit(*std::get_if<Instance>(&geometry));
    case GeometryKind::kCurves: return visit(*std::get_if<CurveSet>(&geometry));
  }
  throw std::logic_error("visit_geometry: a geometry without a kind");
}

}  // namespace rtpro
