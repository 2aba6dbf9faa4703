// The native backend: the reference answer. One BVH per group; instances transform the ray into
// object space and descend into their prototype's BVH. Kept simple and plainly correct.
#include "native_backend.h"

#include "bvh.h"
#include "wide_bvh.h"
#include "ray_gate.h"
#include "rtpro/geometry/sphere_intersect.h"
#include "rtpro/geometry/triangle_intersect.h"

#include <immintrin.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

// A ray prepared for the four-wide slab test: origin and reciprocal direction broadcast, and per
// axis which stored bound (lower or upper) is the near one.
struct RaySlabs {
  __m128 org[3];
  __m128 inv_dir[3];
  int near_bound[3];  // 0: lower bound is entered first (direction >= 0); 1: upper

  explicit RaySlabs(const Ray& ray) {
    for (int a = 0; a < 3; ++a) {
      const float inv = 1.0f / ray.dir[a];
      org[a] = _mm_set1_ps(ray.org[a]);
      inv_dir[a] = _mm_set1_ps(inv);
      near_bound[a] = inv < 0.0f ? 1 : 0;
    }
  }
};

// The slab test of four boxes at once: a bit per child whose box the ray enters within
// [tnear, tmax], and each child's entry distance. The far distance is enlarged by 2·gamma(3)
// (pbrt) so float rounding never culls a box that the ray actually touches; a 0·∞ NaN (ray in a
// box's face plane, parallel to it) is ignored by the operand order of min/max.
inline int enter_children(const WideBvhNode& node, const RaySlabs& r, float tnear, float tmax, __m128& entry) {
  constexpr float kRoundingSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  __m128 t0 = _mm_set1_ps(tnear);
  __m128 t1 = _mm_set1_ps(tmax);
  const __m128 slack = _mm_set1_ps(kRoundingSlack);
  for (int a = 0; a < 3; ++a) {
    const __m128 near_plane = _mm_load_ps(node.bounds[a][r.near_bound[a]]);
    const __m128 far_plane = _mm_load_ps(node.bounds[a][1 - r.near_bound[a]]);
    const __m128 tn = _mm_mul_ps(_mm_sub_ps(near_plane, r.org[a]), r.inv_dir[a]);
    const __m128 tf = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(far_plane, r.org[a]), r.inv_dir[a]), slack);
    t0 = _mm_max_ps(tn, t0);
    t1 = _mm_min_ps(tf, t1);
  }
  entry = t0;
  return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
}

class NativeBackend final : public Backend {
 public:
  NativeBackend(const RenderScene& scene) : scene_(scene) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<BBox> prototype_bounds = scene.prototype_bounds();
    top_bvh_ = make_wide_bvh(build_bvh(scene.top, prototype_bounds), scene.top, prototype_bounds);
    prototype_bvhs_.reserve(scene.prototypes.size());
    for (const Group& prototype : scene.prototypes)
      prototype_bvhs_.push_back(make_wide_bvh(build_bvh(prototype, {}), prototype, {}));
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  std::string_view name() const override { return "native"; }
  using Backend::intersect;
  using Backend::occluded;

  bool intersect(const Ray& ray, Hit& hit) const override {
    if (!gate_.admit(ray)) return false;
    Hit best;
    float best_t = ray.tfar;
    closest_in_group(scene_.top, top_bvh_, ray, kInvalidId, best, best_t);
    if (!best.valid()) return false;
    best.t = best_t;
    hit = best;
    return true;
  }

  bool occluded(const Ray& ray) const override {
    if (!gate_.admit(ray)) return false;
    return any_in_group(scene_.top, top_bvh_, ray);
  }

  BackendStats stats() const override {
    BackendStats s;
    s.build_seconds = build_seconds_;
    s.acceleration_bytes = top_bvh_.memory_bytes();
    for (const WideBvh& bvh : prototype_bvhs_) s.acceleration_bytes += bvh.memory_bytes();
    s.rejected_rays = gate_.rejected();
    return s;
  }

 private:
  static Ray to_object_space(const Instance& instance, const Ray& ray, float tfar) {
    // The direction is not renormalised, so distances t mean the same in both spaces.
    return {instance.world_to_object.apply_point(ray.org), ray.tnear,
            instance.world_to_object.apply_vector(ray.dir), tfar};
  }

  // Visits every primitive whose box the ray enters within (tnear, tmax], nearer subtrees first;
  // `visit(ref)` returns false to stop early. `tmax` is re-read as it shrinks.
  template <typename Visit>
  static void traverse(const WideBvh& bvh, const Ray& ray, const float& tmax, Visit&& visit) {
    constexpr float kRoundingSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
    if (bvh.nodes.empty()) return;
    const RaySlabs slabs(ray);
    struct Pending {
      std::uint32_t node;
      float entry;  // where the ray enters its box, rounded down at most by the slack
    };
    // Each level pushes at most three siblings; the binary tree is at most kBvhMaxDepth deep
    // plus the levels that split its leaves.
    Pending stack[3 * (kBvhMaxDepth + 8) + 1];
    int top = 0;
    stack[top++] = {0, ray.tnear};
    while (top > 0) {
      const Pending pending = stack[--top];
      if (pending.entry > tmax * kRoundingSlack) continue;
      const WideBvhNode& node = bvh.nodes[pending.node];
      __m128 entry_vector;
      int mask = enter_children(node, slabs, ray.tnear, tmax, entry_vector);
      alignas(16) float entry[4];
      _mm_store_ps(entry, entry_vector);
      const int first_pushed = top;
      while (mask != 0) {
        const int c = __builtin_ctz(static_cast<unsigned>(mask));
        mask &= mask - 1;
        const std::uint32_t child = node.child[c];
        if (child & WideBvhNode::kLeafBit) {
          if (!visit(bvh.refs[child & ~WideBvhNode::kLeafBit])) return;
          continue;
        }
        // Keep this node's pushed children sorted far to near, so the nearest is popped first.
        int k = top++;
        while (k > first_pushed && stack[k - 1].entry < entry[c]) {
          stack[k] = stack[k - 1];
          --k;
        }
        stack[k] = {child, entry[c]};
      }
    }
  }

  // Keeps the candidate when the shared tie rule says it is closer than the best so far.
  static void offer_hit(float t, float u, float v, std::uint32_t inst, const PrimitiveRef& ref, Hit& best,
                        float& best_t) {
    if (!is_closer(t, inst, ref.geom, ref.prim, best, best_t)) return;
    best_t = t;
    best.u = u;
    best.v = v;
    best.inst_id = inst;
    best.geom_id = ref.geom;
    best.prim_id = ref.prim;
  }

  void closest_in_group(const Group& group, const WideBvh& bvh, const Ray& ray, std::uint32_t inst, Hit& best,
                        float& best_t) const {
    traverse(bvh, ray, best_t, [&](const PrimitiveRef& ref) {
      const Geometry& geometry = group.geometries[ref.geom];
      switch (kind_of(geometry)) {
        case GeometryKind::kSpheres: {
          const Sphere& s = std::get<SphereSet>(geometry).spheres[ref.prim];
          float t;
          if (intersect_sphere(s.center, s.radius, ray.org, ray.dir, ray.tnear, best_t, t))
            offer_hit(t, 0.0f, 0.0f, inst, ref, best, best_t);
          break;
        }
        case GeometryKind::kTriangles: {
          const TriangleMesh& mesh = std::get<TriangleMesh>(geometry);
          const TriangleIndices& tri = mesh.triangles[ref.prim];
          TriangleHit th;
          if (intersect_triangle(mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2), ray.org, ray.dir,
                                 ray.tnear, best_t, th))
            offer_hit(th.t, th.u, th.v, inst, ref, best, best_t);
          break;
        }
        case GeometryKind::kInstance: {
          const Instance& instance = std::get<Instance>(geometry);
          const Ray local = to_object_space(instance, ray, best_t);
          if (is_traceable(local))
            closest_in_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype], local,
                             ref.geom, best, best_t);
          break;
        }
      }
      return true;
    });
  }

  bool any_in_group(const Group& group, const WideBvh& bvh, const Ray& ray) const {
    bool found = false;
    const float tfar = ray.tfar;
    traverse(bvh, ray, tfar, [&](const PrimitiveRef& ref) {
      const Geometry& geometry = group.geometries[ref.geom];
      switch (kind_of(geometry)) {
        case GeometryKind::kSpheres: {
          const Sphere& s = std::get<SphereSet>(geometry).spheres[ref.prim];
          float t;
          found = intersect_sphere(s.center, s.radius, ray.org, ray.dir, ray.tnear, tfar, t) && t < tfar;
          break;
        }
        case GeometryKind::kTriangles: {
          const TriangleMesh& mesh = std::get<TriangleMesh>(geometry);
          const TriangleIndices& tri = mesh.triangles[ref.prim];
          TriangleHit th;
          found = intersect_triangle(mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2), ray.org, ray.dir,
                                     ray.tnear, tfar, th) &&
                  th.t < tfar;
          break;
        }
        case GeometryKind::kInstance: {
          const Instance& instance = std::get<Instance>(geometry);
          const Ray local = to_object_space(instance, ray, tfar);
          found = is_traceable(local) && any_in_group(scene_.prototypes[instance.prototype],
                                                      prototype_bvhs_[instance.prototype], local);
          break;
        }
      }
      return !found;
    });
    return found;
  }

  const RenderScene& scene_;
  WideBvh top_bvh_;
  std::vector<WideBvh> prototype_bvhs_;
  double build_seconds_ = 0.0;
  RayGate gate_;
};

}  // namespace

std::unique_ptr<Backend> make_native_backend(const RenderScene& scene, const BackendOptions&) {
  return std::make_unique<NativeBackend>(scene);
}

}  // namespace rtpro
