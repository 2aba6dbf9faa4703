#pragma once
// The shading data of the hits ahead in a batch, fetched while an earlier hit is shaded. A batch's
// hits scatter over the scene's arrays, so on a large mesh or groom each surface's first loads
// missed the cache: on Embree's furBall_A, curve_surface waited on its segment's index and control
// points for two thirds of its time. Each hit takes two steps, as its data does: its index (a
// segment's first control point, a triangle's vertex indices) `kIndexAhead` hits ahead, then what
// the index names `kDataAhead` hits ahead, by when the index has arrived. Every step is inlined:
// GCC takes a function whose only effect is a prefetch for one without effects, and drops its calls.
// Where the scene's shading data fits in a core's cache the fetches find nothing to hide and only
// cost their lookups (3% of the Whitted demo's instructions): hit_prefetch_pays tells, once per
// render, and a HitPrefetch made with `pays` false fetches nothing.
#include "rtpro/backend/hit.h"
#include "rtpro/scene/motion.h"
#include "rtpro/scene/render_scene.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <variant>
#include <vector>

namespace rtpro {

// Whether the scene's shading data (spheres, triangles with their vertices and normals, curves, at
// every motion step) is larger than kHitPrefetchFromBytes, half of a small core's L2 cache.
inline constexpr std::size_t kHitPrefetchFromBytes = std::size_t{256} << 10;
bool hit_prefetch_pays(const RenderScene& scene);

class HitPrefetch {
 public:
  static constexpr std::size_t kIndexAhead = 16;
  static constexpr std::size_t kDataAhead = 8;

  // `times`: each hit's ray time (scene/motion.h), or empty while the shutter is closed; a
  // deforming mesh is read at the steps around it. `pays`: hit_prefetch_pays(scene).
  HitPrefetch(const RenderScene& scene, bool pays, std::span<const Hit> hits, std::span<const float> times = {})
      : scene_(scene), hits_(pays ? hits : std::span<const Hit>()), times_(times) {
    for (std::size_t i = 0; i < std::min(kIndexAhead, hits_.size()); ++i) fetch_index(i);
    for (std::size_t i = 0; i < std::min(kDataAhead, hits_.size()); ++i) fetch_data(i);
  }

  // Called before hit i is shaded.
  [[gnu::always_inline]] void before(std::size_t i) const {
    if (i + kIndexAhead < hits_.size()) fetch_index(i + kIndexAhead);
    if (i + kDataAhead < hits_.size()) fetch_data(i + kDataAhead);
  }

 private:
  [[gnu::always_inline]] const Geometry* geometry_of(const Hit& hit) const {
    if (!hit.valid()) return nullptr;
    if (hit.inst_id == kInvalidId) return &scene_.top.geometries[hit.geom_id];
    const auto* instance = std::get_if<Instance>(&scene_.top.geometries[hit.inst_id]);
    return instance != nullptr ? &scene_.prototypes[instance->prototype].geometries[hit.geom_id] : nullptr;
  }

  [[gnu::always_inline]] void fetch_index(std::size_t i) const {
    const Hit& hit = hits_[i];
    const Geometry* geometry = geometry_of(hit);
    if (geometry == nullptr) return;
    switch (kind_of(*geometry)) {
      case GeometryKind::kSpheres: __builtin_prefetch(&std::get<SphereSet>(*geometry).spheres[hit.prim_id]); break;
      case GeometryKind::kTriangles:
        __builtin_prefetch(&std::get<TriangleMesh>(*geometry).triangles[hit.prim_id]);
        break;
      case GeometryKind::kCurves: __builtin_prefetch(&std::get<CurveSet>(*geometry).segments[hit.prim_id]); break;
      case GeometryKind::kInstance: break;
    }
  }

  [[gnu::always_inline]] void fetch_data(std::size_t i) const {
    const Hit& hit = hits_[i];
    const Geometry* geometry = geometry_of(hit);
    if (geometry == nullptr) return;
    switch (kind_of(*geometry)) {
      case GeometryKind::kSpheres: break;  // the sphere is its own data
      case GeometryKind::kTriangles: {
        const TriangleMesh& mesh = std::get<TriangleMesh>(*geometry);
        const TriangleIndices& triangle = mesh.triangles[hit.prim_id];
        if (mesh.moving() && !times_.empty()) {
          const MotionSegment segment = motion_segment(times_[i], mesh.vertex_steps.size());
          const VertexArray& from = mesh.vertex_steps[segment.index];
          const VertexArray& to = mesh.vertex_steps[segment.index + 1];
          const bool moving_normals = !mesh.normal_steps.empty();
          const std::vector<Vec3>& normals = moving_normals ? mesh.normal_steps[segment.index] : mesh.normals;
          for (const std::uint32_t v : {triangle.v0, triangle.v1, triangle.v2}) {
            __builtin_prefetch(&from[v]);
            __builtin_prefetch(&to[v]);
            if (!normals.empty()) __builtin_prefetch(&normals[v]);
            if (!moving_normals && !mesh.packed_normals.empty()) __builtin_prefetch(&mesh.packed_normals[v]);
            if (moving_normals) __builtin_prefetch(&mesh.normal_steps[segment.index + 1][v]);
          }
          break;
        }
        for (const std::uint32_t v : {triangle.v0, triangle.v1, triangle.v2}) {
          __builtin_prefetch(&mesh.vertices[v]);
          if (!mesh.normals.empty()) __builtin_prefetch(&mesh.normals[v]);
          if (!mesh.packed_normals.empty()) __builtin_prefetch(&mesh.packed_normals[v]);
        }
        break;
      }
      case GeometryKind::kCurves: {
        const CurveSet& curves = std::get<CurveSet>(*geometry);
        const std::uint32_t first = curves.segments[hit.prim_id];
        __builtin_prefetch(&curves.points[first]);
        __builtin_prefetch(&curves.points[first + control_points_per_segment(curves.basis) - 1]);
        break;
      }
      case GeometryKind::kInstance: break;
    }
  }

  const RenderScene& scene_;
  std::span<const Hit> hits_;
  std::span<const float> times_;
};

}  // namespace rtpro
