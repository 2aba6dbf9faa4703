#include "native_traversal.h"
#include "placement_lanes.h"

#include "backend_shapes.h"
#include "triangle_leaves.h"
#include "rtpro/core/overloaded.h"

#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace rtpro {

namespace {

// Precomputed per-ray data for the slab test, in SSE registers (SSE2 is part of x86-64, so no
// dispatch is needed). Lane 3 is unused: it is masked out of every result.
struct RayBoxData {
  __m128 org;
  __m128 inv_dir;
};

RayBoxData prepare(const Ray& ray) {
  return {_mm_set_ps(0.0f, ray.org.z, ray.org.y, ray.org.x),
          _mm_set_ps(0.0f, 1.0f / ray.dir.z, 1.0f / ray.dir.y, 1.0f / ray.dir.x)};
}

// Slab test of one box, all three axes at once; sets `entry` to the distance where the ray enters
// it. NaNs from 0·∞ (an origin on a slab plane of an axis the ray runs parallel to) leave that
// axis out, as the operand order of minps/maxps below arranges: each returns its second operand
// when either is NaN. The far distance is enlarged by 2·gamma(3) (pbrt) so float rounding never
// culls a box that the ray actually touches.
// The box's corners are in lanes 0-2 of `lower` and `upper`; lane 3 is replaced before any
// comparison.
inline bool hits_box(__m128 lower, __m128 upper, const RayBoxData& d, float tnear, float tmax, float& entry) {
  constexpr float kRoundingSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  const __m128 tn = _mm_mul_ps(_mm_sub_ps(lower, d.org), d.inv_dir);
  const __m128 tf = _mm_mul_ps(_mm_sub_ps(upper, d.org), d.inv_dir);
  const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
  // min(tf, tn) is NaN when tn is (axis ignored) and tn when tf is; max(tn, tf) the other way round.
  const __m128 near_axes = _mm_min_ps(tf, tn);
  const __m128 far_axes = _mm_mul_ps(_mm_max_ps(tn, tf), _mm_set1_ps(kRoundingSlack));
  const __m128 near =
      _mm_max_ps(_mm_or_ps(_mm_and_ps(xyz, near_axes), _mm_andnot_ps(xyz, _mm_set1_ps(tnear))), _mm_set1_ps(tnear));
  const __m128 far =
      _mm_min_ps(_mm_or_ps(_mm_and_ps(xyz, far_axes), _mm_andnot_ps(xyz, _mm_set1_ps(tmax))), _mm_set1_ps(tmax));
  // Largest near and smallest far over the lanes.
  __m128 t0 = _mm_max_ps(near, _mm_shuffle_ps(near, near, _MM_SHUFFLE(2, 3, 0, 1)));
  t0 = _mm_max_ps(t0, _mm_shuffle_ps(t0, t0, _MM_SHUFFLE(1, 0, 3, 2)));
  __m128 t1 = _mm_min_ps(far, _mm_shuffle_ps(far, far, _MM_SHUFFLE(2, 3, 0, 1)));
  t1 = _mm_min_ps(t1, _mm_shuffle_ps(t1, t1, _MM_SHUFFLE(1, 0, 3, 2)));
  entry = _mm_cvtss_f32(t0);
  return entry <= _mm_cvtss_f32(t1);
}

// The loads read one float past each corner (the next corner's x, or the node's index bits).
inline bool hits_box(const BBox& box, const RayBoxData& d, float tnear, float tmax, float& entry) {
  return hits_box(_mm_loadu_ps(&box.lower.x), _mm_loadu_ps(&box.upper.x), d, tnear, tmax, entry);
}

// A moving node's box at `time` (LinearBounds::at's a + t·(b − a), in registers: a box written to
// memory and read back whole would stall on store forwarding at every node).
inline bool hits_box_at(const LinearBounds& box, __m128 time, const RayBoxData& d, float tnear, float tmax,
                        float& entry) {
  const auto at = [time](const Vec3& a, const Vec3& b) {
    const __m128 from = _mm_loadu_ps(&a.x);
    return _mm_add_ps(from, _mm_mul_ps(time, _mm_sub_ps(_mm_loadu_ps(&b.x), from)));
  };
  return hits_box(at(box.at_open.lower, box.at_close.lower), at(box.at_open.upper, box.at_close.upper), d, tnear, tmax,
                  entry);
}

Ray to_object_space(const Affine& world_to_object, const Ray& ray, float tfar) {
  // The direction is not renormalised, so distances t mean the same in both spaces.
  return {world_to_object.apply_point(ray.org), ray.tnear, world_to_object.apply_vector(ray.dir), tfar};
}

Ray to_object_space(const Instance& instance, const Ray& ray, float tfar) {
  return to_object_space(instance.world_to_object, ray, tfar);
}

// The ray in a moving or static instance's space at `time`, or nothing where it misses the instance
// (its interpolated placement is singular there).
std::optional<Ray> to_object_space_at(const Instance& instance, const Ray& ray, float time, float tfar) {
  if (!instance.moving()) return to_object_space(instance, ray, tfar);
  const std::optional<InstancePlacement> placement = placement_at(instance, time);
  if (!placement) return std::nullopt;
  return to_object_space(placement->world_to_object, ray, tfar);
}

// to_object_space_at, but an instance that places its prototype as is takes the ray itself: the
// identity would give the same coordinates (a zero's sign aside, which no test below reads
// differently). A glTF file's meshes are such instances; transforming rays into them would be 17%
// of cornell_box.gltf's native profile.
std::optional<Ray> in_prototype_space(const Instance& instance, const Ray& ray, float time, float tfar) {
  if (!instance.places_as_is()) return to_object_space_at(instance, ray, time, tfar);
  Ray same = ray;
  same.tfar = tfar;
  return same;
}

// Whether a shape kind's geometry moves during the shutter (curves keep still).
template <typename Shapes>
bool moves(const Shapes& shapes) {
  if constexpr (requires { shapes.moving(); }) return shapes.moving();
  else return false;
}

// A shape's hit, at `time` where it moves.
template <typename Shapes>
[[gnu::always_inline]] inline bool shape_hit_at(const Shapes& shapes, std::uint32_t prim, const Ray& ray, float time,
                                                float t_max, ShapeHit& hit) {
  if constexpr (requires { shapes.moving(); })
    if (shapes.moving()) return native_hit_at(shapes, prim, ray, time, t_max, hit);
  return native_hit(shapes, prim, ray, t_max, hit);
}

// The far children still to visit, the last kept on top: a ray, or a packet by its first active
// lane, enters an inner node's child on its near side first (by the sign of its direction along
// the node's split axis) and comes back for the other.
struct NodeStack {
  std::uint32_t far_children[kBvhMaxDepth + 1];
  int top = 0;

  // The child of inner `node` to visit now; its sibling is kept for later.
  std::uint32_t descend(const BvhNode& node, const int (&dir_negative)[3]) {
    far_children[top++] = node.index + 1 - dir_negative[node.axis];
    return node.index + dir_negative[node.axis];
  }

  // The next node kept for later into `node_index`, or false when none is left.
  bool pop(std::uint32_t& node_index) {
    if (top == 0) return false;
    node_index = far_children[--top];
    return true;
  }
};

// Visits every leaf whose node box the ray enters, nearest child first: `visit(leaf, node_index)`
// returns false to stop early. `tmax` is re-read after each leaf. Where the BVH has linear bounds
// (something in the group moves), a node's box is taken at the ray's `time`, from its MotionNode.
template <typename Visit>
void traverse(const Bvh& bvh, const Ray& ray, float time, const float& tmax, Visit&& visit) {
  if (bvh.nodes.empty()) return;
  const RayBoxData box_data = prepare(ray);
  const int dir_negative[3] = {ray.dir.x < 0.0f, ray.dir.y < 0.0f, ray.dir.z < 0.0f};
  const bool linear = !bvh.motion_nodes.empty();
  const __m128 time_lanes = _mm_set1_ps(time);
  NodeStack stack;
  std::uint32_t node_index = 0;
  for (;;) {
    float entry;
    bool entered;
    BvhNode node;  // index, count and axis; the bounds only where the node keeps still
    if (linear) {
      const MotionNode& m = bvh.motion_nodes[node_index];
      entered = hits_box_at(m.bounds, time_lanes, box_data, ray.tnear, tmax, entry);
      node.index = m.index;
      node.count = m.count;
      node.axis = m.axis;
    } else {
      node = bvh.nodes[node_index];
      entered = hits_box(node.bounds, box_data, ray.tnear, tmax, entry);
    }
    if (entered) {
      if (node.is_leaf()) {
        if (!visit(node, node_index)) return;
      } else {
        node_index = stack.descend(node, dir_negative);
        continue;
      }
    }
    if (!stack.pop(node_index)) return;
  }
}

// Keeps the candidate when the shared tie rule says it is closer than the best so far.
void offer_hit(float t, float u, float v, std::uint32_t inst, const PrimitiveRef& ref, Hit& best, float& best_t) {
  if (!is_closer(t, inst, ref.geom, ref.prim, best, best_t)) return;
  best_t = t;
  best.u = u;
  best.v = v;
  best.inst_id = inst;
  best.geom_id = ref.geom;
  best.prim_id = ref.prim;
}

// The slots of a leaf's four-column chunk starting at reference `i`.
unsigned chunk_slots(const BvhNode& leaf, std::uint32_t i) {
  const std::uint32_t left = leaf.index + leaf.count - i;
  return left >= kBlockWidth ? (1u << kBlockWidth) - 1u : (1u << left) - 1u;
}

// Four triangles of a leaf from reference `i` on, as a ray at `time` meets them: from the still
// rows, or between the two steps of the moving rows around `time`.
[[gnu::target("avx2"), gnu::always_inline]] inline BlockVertices leaf_block(const TriangleLeaves& leaves,
                                                                            std::uint8_t rows, std::uint32_t i,
                                                                            const MotionSegment& segment) {
  if (rows == kStillRows) return load_block(leaves.column(i), leaves.stride);
  return load_block_between(leaves.motion_column(segment.index, i), leaves.stride, segment.fraction);
}

// A triangle leaf against one ray at `time`, four triangles at a time: every one the test accepts
// offered under the tie rule.
[[gnu::target("avx2")]] void closest_in_triangle_leaf(const Bvh& bvh, const TriangleLeaves& leaves, const BvhNode& leaf,
                                                      std::uint8_t rows, const Ray& ray, float time, std::uint32_t inst,
                                                      Hit& best, float& best_t) {
  const BlockRay block = block_ray(ray.org, ray.dir, ray.tnear);
  const MotionSegment segment = rows == kMovingRows ? motion_segment(time, leaves.motion_steps) : MotionSegment{};
  for (std::uint32_t i = leaf.index; i < leaf.index + leaf.count; i += kBlockWidth) {
    BlockHits hits;
    for (unsigned mask =
             intersect_block(leaf_block(leaves, rows, i, segment), chunk_slots(leaf, i), block, best_t, hits);
         mask != 0; mask &= mask - 1) {
      const auto j = static_cast<unsigned>(std::countr_zero(mask));
      offer_hit(hits.t[j], hits.u[j], hits.v[j], inst, bvh.refs[i + j], best, best_t);
    }
  }
}

// Whether a triangle leaf holds anything in (ray.tnear, tfar) at `time`.
[[gnu::target("avx2")]] bool any_in_triangle_leaf(const TriangleLeaves& leaves, const BvhNode& leaf, std::uint8_t rows,
                                                  const Ray& ray, float time, float tfar) {
  const BlockRay block = block_ray(ray.org, ray.dir, ray.tnear);
  const MotionSegment segment = rows == kMovingRows ? motion_segment(time, leaves.motion_steps) : MotionSegment{};
  for (std::uint32_t i = leaf.index; i < leaf.index + leaf.count; i += kBlockWidth) {
    BlockHits hits;
    for (unsigned mask = intersect_block(leaf_block(leaves, rows, i, segment), chunk_slots(leaf, i), block, tfar, hits);
         mask != 0; mask &= mask - 1)
      if (hits.t[std::countr_zero(mask)] < tfar) return true;
  }
  return false;
}

// Visits every top-level leaf whose node box some active lane enters, near child first by the
// first active lane's direction, and returns early when no lane is left active. A triangle leaf
// is tested here, each entering lane against four of its triangles at a time: `on_block_hits(lane,
// first, mask, hits)` gets the slots the test accepts (against the lane's tmax; bit j is
// reference first + j). Any other leaf's references go to `visit(ref, lanes)` one by one, with
// the mask of the entering lanes. Both return the lanes still active (occlusion retires the
// blocked ones).
// With `timed`, each lane meets the scene where it is at the lane's time (packet.time): node boxes
// from the BVH's linear bounds and deforming meshes' leaves from their moving rows, as traverse
// and closest_in_triangle_leaf take them for a single ray. Without, a deforming mesh's leaf goes
// reference by reference.
template <typename Visit, typename OnBlockHits>
[[gnu::target("avx2")]] void traverse_packet(const Bvh& bvh, const TriangleLeaves& leaves, const RayPacket& packet,
                                             bool timed, std::uint32_t active, Visit&& visit,
                                             OnBlockHits&& on_block_hits) {
  if (bvh.nodes.empty() || active == 0) return;
  const unsigned lead = static_cast<unsigned>(std::countr_zero(active));
  const int dir_negative[3] = {packet.dir_x[lead] < 0.0f, packet.dir_y[lead] < 0.0f, packet.dir_z[lead] < 0.0f};
  const bool linear = timed && !bvh.motion_nodes.empty();
  NodeStack stack;
  std::uint32_t node_index = 0;
  for (;;) {
    BvhNode node;
    std::uint32_t entering;
    if (linear) {
      const MotionNode& m = bvh.motion_nodes[node_index];
      node = {m.bounds.at_open, m.index, m.count, m.axis};
      entering = packet_hits_moving_box(m.bounds.at_open, m.bounds.at_close, packet) & active;
    } else {
      node = bvh.nodes[node_index];
      entering = packet_hits_box(node.bounds, packet) & active;
    }
    if (entering != 0) {
      if (node.is_leaf()) {
        const std::uint8_t rows = leaves.triangle_leaf[node_index];
        if (rows == kStillRows || (rows == kMovingRows && timed)) {
          for (std::uint32_t i = node.index; i < node.index + node.count; i += kBlockWidth) {
            const unsigned slots = chunk_slots(node, i);
            for (std::uint32_t lanes = entering & active; lanes != 0; lanes &= lanes - 1) {
              const auto k = static_cast<unsigned>(std::countr_zero(lanes));
              const BlockRay ray = block_ray({packet.org_x[k], packet.org_y[k], packet.org_z[k]},
                                             {packet.dir_x[k], packet.dir_y[k], packet.dir_z[k]}, packet.tnear[k]);
              const MotionSegment segment =
                  rows == kMovingRows ? motion_segment(packet.time[k], leaves.motion_steps) : MotionSegment{};
              BlockHits hits;
              const unsigned mask =
                  intersect_block(leaf_block(leaves, rows, i, segment), slots, ray, packet.tmax[k], hits);
              if (mask != 0) active = on_block_hits(k, i, mask, hits);
            }
            if (active == 0) return;
          }
        } else {
          for (std::uint32_t i = 0; i < node.count; ++i) {
            active = visit(bvh.refs[node.index + i], entering & active);
            if (active == 0) return;
          }
        }
      } else {
        node_index = stack.descend(node, dir_negative);
        continue;
      }
    }
    if (!stack.pop(node_index)) return;
  }
}

}  // namespace

NativeTraversal::NativeTraversal(const RenderScene& scene, bool triangle_rows) : scene_(scene) {
  const auto start = std::chrono::steady_clock::now();
  top_bvh_ = build_bvh(scene.top, scene.prototype_bounds());
  top_leaves_ = build_triangle_leaves(scene.top, top_bvh_, triangle_rows);
  prototype_bvhs_.reserve(scene.prototypes.size());
  prototype_leaves_.reserve(scene.prototypes.size());
  for (const Group& prototype : scene.prototypes) {
    prototype_bvhs_.push_back(build_bvh(prototype, {}));
    prototype_leaves_.push_back(build_triangle_leaves(prototype, prototype_bvhs_.back(), triangle_rows));
  }
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::size_t NativeTraversal::memory_bytes() const {
  std::size_t bytes = top_bvh_.memory_bytes() + top_leaves_.memory_bytes();
  for (const Bvh& bvh : prototype_bvhs_) bytes += bvh.memory_bytes();
  for (const TriangleLeaves& leaves : prototype_leaves_) bytes += leaves.memory_bytes();
  return bytes;
}

void NativeTraversal::closest_in_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves, const Ray& ray,
                                       float time, std::uint32_t inst, Hit& best, float& best_t) const {
  traverse(bvh, ray, time, best_t, [&](const BvhNode& leaf, std::uint32_t node_index) {
    if (const std::uint8_t rows = leaves.triangle_leaf[node_index]; rows != 0) {
      closest_in_triangle_leaf(bvh, leaves, leaf, rows, ray, time, inst, best, best_t);
      return true;
    }
    for (std::uint32_t i = 0; i < leaf.count; ++i) {
      const PrimitiveRef& ref = bvh.refs[leaf.index + i];
      const auto in_instance = [&](const Instance& instance) {
        const std::optional<Ray> local = in_prototype_space(instance, ray, time, best_t);
        if (local && is_traceable(*local))
          closest_in_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                           prototype_leaves_[instance.prototype], *local, time, ref.geom, best, best_t);
      };
      const auto in_shapes = [&](const auto& shapes) {
        ShapeHit hit;
        if (shape_hit_at(shapes, ref.prim, ray, time, best_t, hit))
          offer_hit(hit.t, hit.u, hit.v, inst, ref, best, best_t);
      };
      visit_geometry(group.geometries[ref.geom], Overloaded{in_instance, in_shapes});
    }
    return true;
  });
}

bool NativeTraversal::any_in_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves, const Ray& ray,
                                   float time) const {
  bool found = false;
  const float tfar = ray.tfar;
  traverse(bvh, ray, time, tfar, [&](const BvhNode& leaf, std::uint32_t node_index) {
    if (const std::uint8_t rows = leaves.triangle_leaf[node_index]; rows != 0) {
      found = any_in_triangle_leaf(leaves, leaf, rows, ray, time, tfar);
      return !found;
    }
    for (std::uint32_t i = 0; i < leaf.count && !found; ++i) {
      const PrimitiveRef& ref = bvh.refs[leaf.index + i];
      const auto in_instance = [&](const Instance& instance) {
        const std::optional<Ray> local = in_prototype_space(instance, ray, time, tfar);
        return local && is_traceable(*local) &&
               any_in_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                            prototype_leaves_[instance.prototype], *local, time);
      };
      const auto in_shapes = [&](const auto& shapes) {
        ShapeHit hit;
        return shape_hit_at(shapes, ref.prim, ray, time, tfar, hit) && hit.t < tfar;
      };
      found = visit_geometry(group.geometries[ref.geom], Overloaded{in_instance, in_shapes});
    }
    return !found;
  });
  return found;
}

void NativeTraversal::closest_in_packet(RayPacket& packet, bool timed, std::uint32_t active, Hit* best) const {
  closest_in_packet_group(scene_.top, top_bvh_, top_leaves_, packet, timed, active, kInvalidId, best);
}

std::uint32_t NativeTraversal::any_in_packet(const RayPacket& packet, bool timed, std::uint32_t active) const {
  return any_in_packet_group(scene_.top, top_bvh_, top_leaves_, packet, timed, active);
}

namespace {

// The `lanes` of `packet` in `instance`'s space (each at its time where `timed`) as a packet of
// their own, which `local_rays` holds the rays of; returns the lanes that are traceable there.
std::uint32_t enter_instance(const Instance& instance, const RayPacket& packet, bool timed, std::uint32_t lanes,
                             RayPacket& local, Ray (&local_rays)[kPacketSize]) {
  std::uint32_t entering = 0;
  if (timed && instance.moving()) {
    // The lanes' placements kPlacementLanes at a time (placement_at's, bit for bit).
    unsigned lane_of[kPacketSize];
    unsigned count = 0;
    for (; lanes != 0; lanes &= lanes - 1) lane_of[count++] = static_cast<unsigned>(std::countr_zero(lanes));
    for (unsigned first = 0; first < count; first += kPlacementLanes) {
      const unsigned group = std::min(kPlacementLanes, count - first);
      float times[kPlacementLanes];
      for (unsigned g = 0; g < group; ++g) times[g] = packet.time[lane_of[first + g]];
      Affine world_to_object[kPlacementLanes];
      const unsigned placed = world_to_object_lanes(instance, times, group, world_to_object);
      for (unsigned g = 0; g < group; ++g) {
        if ((placed >> g & 1u) == 0) continue;
        const unsigned k = lane_of[first + g];
        const Ray ray = to_object_space(world_to_object[g], *packet.rays[k], packet.tmax[k]);
        if (!is_traceable(ray)) continue;
        local_rays[k] = ray;
        local.set(k, local_rays[k], packet.tmax[k]);
        local.time[k] = packet.time[k];
        entering |= 1u << k;
      }
    }
    if (entering != 0) local.finish_lanes(entering);
    return entering;
  }
  for (; lanes != 0; lanes &= lanes - 1) {
    const auto k = static_cast<unsigned>(std::countr_zero(lanes));
    const std::optional<Ray> ray = timed ? to_object_space_at(instance, *packet.rays[k], packet.time[k], packet.tmax[k])
                                         : to_object_space(instance, *packet.rays[k], packet.tmax[k]);
    if (!ray || !is_traceable(*ray)) continue;
    local_rays[k] = *ray;
    local.set(k, local_rays[k], packet.tmax[k]);
    local.time[k] = packet.time[k];
    entering |= 1u << k;
  }
  if (entering != 0) local.finish_lanes(entering);
  return entering;
}

}  // namespace

// An instance's lanes go through its prototype's BVH as a packet of their own: the same box and
// leaf tests lane by lane as closest_in_group's single ray in the same space.
void NativeTraversal::closest_in_packet_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves,
                                              RayPacket& packet, bool timed, std::uint32_t active, std::uint32_t inst,
                                              Hit* best) const {
  const auto on_block_hits = [&](unsigned k, std::uint32_t first, unsigned mask, const BlockHits& hits) {
    for (; mask != 0; mask &= mask - 1) {
      const auto j = static_cast<unsigned>(std::countr_zero(mask));
      offer_hit(hits.t[j], hits.u[j], hits.v[j], inst, bvh.refs[first + j], best[k], packet.tmax[k]);
    }
    return active;
  };
  const auto visit = [&](const PrimitiveRef& ref, std::uint32_t lanes) {
    const auto in_instance = [&](const Instance& instance) {
      if (instance.places_as_is()) {  // the lanes as they are (in_prototype_space)
        closest_in_packet_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                                prototype_leaves_[instance.prototype], packet, timed, lanes, ref.geom, best);
        return;
      }
      RayPacket local;
      Ray local_rays[kPacketSize];
      const std::uint32_t entering = enter_instance(instance, packet, timed, lanes, local, local_rays);
      if (entering == 0) return;
      closest_in_packet_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                              prototype_leaves_[instance.prototype], local, timed, entering, ref.geom, best);
      for (std::uint32_t done = entering; done != 0; done &= done - 1) {
        const auto k = static_cast<unsigned>(std::countr_zero(done));
        packet.tmax[k] = local.tmax[k];
      }
    };
    const auto in_shapes = [&](const auto& shapes) {
      if (timed && moves(shapes)) {
        for (; lanes != 0; lanes &= lanes - 1) {
          const auto k = static_cast<unsigned>(std::countr_zero(lanes));
          ShapeHit hit;
          if (shape_hit_at(shapes, ref.prim, *packet.rays[k], packet.time[k], packet.tmax[k], hit))
            offer_hit(hit.t, hit.u, hit.v, inst, ref, best[k], packet.tmax[k]);
        }
        return;
      }
      native_hit_lanes(shapes, ref.prim, packet, lanes, [&](unsigned k, float t, float u, float v) {
        offer_hit(t, u, v, inst, ref, best[k], packet.tmax[k]);
      });
    };
    visit_geometry(group.geometries[ref.geom], Overloaded{in_instance, in_shapes});
    return active;
  };
  traverse_packet(bvh, leaves, packet, timed, active, visit, on_block_hits);
}

// The lanes that something blocks in (tnear, tfar).
std::uint32_t NativeTraversal::any_in_packet_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves,
                                                   const RayPacket& packet, bool timed, std::uint32_t active) const {
  std::uint32_t blocked = 0;
  const auto on_block_hits = [&](unsigned k, std::uint32_t, unsigned mask, const BlockHits& hits) {
    for (; mask != 0; mask &= mask - 1)
      if (hits.t[std::countr_zero(mask)] < packet.tmax[k]) {
        blocked |= 1u << k;
        break;
      }
    return active & ~blocked;
  };
  const auto visit = [&](const PrimitiveRef& ref, std::uint32_t lanes) {
    const auto in_instance = [&](const Instance& instance) {
      if (instance.places_as_is()) {  // the lanes as they are (in_prototype_space)
        if ((lanes & ~blocked) != 0)
          blocked |= any_in_packet_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                                         prototype_leaves_[instance.prototype], packet, timed, lanes & ~blocked);
        return;
      }
      RayPacket local;
      Ray local_rays[kPacketSize];
      const std::uint32_t entering = enter_instance(instance, packet, timed, lanes & ~blocked, local, local_rays);
      if (entering == 0) return;
      blocked |= any_in_packet_group(scene_.prototypes[instance.prototype], prototype_bvhs_[instance.prototype],
                                     prototype_leaves_[instance.prototype], local, timed, entering);
    };
    const auto in_shapes = [&](const auto& shapes) {
      if (timed && moves(shapes)) {
        for (; lanes != 0; lanes &= lanes - 1) {
          const auto k = static_cast<unsigned>(std::countr_zero(lanes));
          ShapeHit hit;
          if (shape_hit_at(shapes, ref.prim, *packet.rays[k], packet.time[k], packet.tmax[k], hit) &&
              hit.t < packet.tmax[k])
            blocked |= 1u << k;
        }
        return;
      }
      native_hit_lanes(shapes, ref.prim, packet, lanes, [&](unsigned k, float t, float, float) {
        if (t < packet.tmax[k]) blocked |= 1u << k;
      });
    };
    visit_geometry(group.geometries[ref.geom], Overloaded{in_instance, in_shapes});
    return active & ~blocked;
  };
  traverse_packet(bvh, leaves, packet, timed, active, visit, on_block_hits);
  return blocked;
}

}  // namespace rtpro
