#pragma once
// Triangle meshes in the backends, the kind's backend side in one place (as sphere_backend.h has
// it for spheres; its scene side is scene/triangle_geometry.h): the native traversal's hits
// through geometry/triangle_intersect.h, and Embree's own triangle geometry over the shared mesh
// arrays. Registered in backend_shapes.h.
#include "embree_handles.h"
#include "ray_packet.h"
#include "shape_hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/geometry/triangle_intersect.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

namespace rtpro {

// Triangle `prim` against one ray, within (ray.tnear, t_max).
[[gnu::always_inline]] inline bool native_hit(const TriangleMesh& mesh, std::uint32_t prim, const Ray& ray, float t_max,
                                              ShapeHit& hit) {
  const TriangleIndices& tri = mesh.triangles[prim];
  TriangleHit th;
  if (!intersect_triangle(mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2), ray.org, ray.dir, ray.tnear,
                          t_max, th))
    return false;
  hit = {th.t, th.u, th.v};
  return true;
}

// Triangle `prim` of a deforming mesh against one ray at `time`, within (ray.tnear, t_max).
[[gnu::always_inline]] inline bool native_hit_at(const TriangleMesh& mesh, std::uint32_t prim, const Ray& ray,
                                                 float time, float t_max, ShapeHit& hit) {
  const TriangleIndices& tri = mesh.triangles[prim];
  TriangleHit th;
  if (!intersect_triangle(mesh.vertex_at(tri.v0, time), mesh.vertex_at(tri.v1, time), mesh.vertex_at(tri.v2, time),
                          ray.org, ray.dir, ray.tnear, t_max, th))
    return false;
  hit = {th.t, th.u, th.v};
  return true;
}

// Triangle `prim` against the `lanes` of a packet, lane by lane, as native_hit_lanes of a
// SphereSet (sphere_backend.h).
template <typename OnHit>
[[gnu::always_inline]] inline void native_hit_lanes(const TriangleMesh& mesh, std::uint32_t prim,
                                                    const RayPacket& packet, std::uint32_t lanes, OnHit&& on_hit) {
  const TriangleIndices& tri = mesh.triangles[prim];
  for (; lanes != 0; lanes &= lanes - 1) {
    const auto k = static_cast<unsigned>(std::countr_zero(lanes));
    const Ray& ray = *packet.rays[k];
    TriangleHit th;
    if (intersect_triangle(mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2), ray.org, ray.dir, ray.tnear,
                           packet.tmax[k], th))
      on_hit(k, th.t, th.u, th.v);
  }
}

// Why Embree cannot take the mesh (a vertex beyond its coordinate range, an index past the
// vertices), or nothing.
std::optional<std::string> embree_refusal(const TriangleMesh& mesh);

// Shares the mesh arrays with Embree, which must outlive the geometry.
EmbreeGeometry new_embree_geometry(RTCDevice device, const TriangleMesh& mesh, RTCBuildQuality quality);

// Triangles [first_triangle, first_triangle + triangle_count) of a static mesh as a geometry of
// their own (one of its pieces, scene/mesh_pieces.h): Embree's primIDs count from first_triangle.
EmbreeGeometry new_embree_piece(RTCDevice device, const TriangleMesh& mesh, std::uint32_t first_triangle,
                                std::uint32_t triangle_count, RTCBuildQuality quality);

// Embree's triangle kernels decide the hits (embree_backend.cpp, rays_decided_by_callbacks).
inline bool hits_decided_by_rtpro(const TriangleMesh&) { return false; }

// Embree's packets (rtcIntersect8, rtcOccluded8) of triangles stored in the BVH's leaves answer
// each lane as the ray alone, bit for bit, ties between triangles at the same distance included
// (15 M rays measured, third_party_notes/embree.md; kept by tests/backend/batch_queries_test.cpp);
// with RTC_SCENE_FLAG_COMPACT's indexed leaves they do not (nearly every barycentric moves).
inline bool packet_lanes_answer_alone(const TriangleMesh&, bool compact) { return !compact; }

}  // namespace rtpro
