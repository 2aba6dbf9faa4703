#pragma once
// The native backend's BVHs and their traversal: one BVH per group; instances transform the ray
// into object space and descend into their prototype's BVH. Single rays, and packets of eight
// through the top level (the same answers lane by lane).
#include "bvh.h"
#include "ray_packet.h"
#include "triangle_leaves.h"
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtpro {

class NativeTraversal {
 public:
  // Builds the BVHs of the scene's top level and of each prototype, with or without their
  // triangle leaves' vertex rows (triangle_leaves.h: leaves tested four triangles at a time; the
  // CPU must have AVX2).
  NativeTraversal(const RenderScene& scene, bool triangle_rows);

  // The closest hit along `ray` closer than best_t, under the shared tie rule, with the scene's
  // moving shapes where they are at `time` (scene/motion.h).
  void closest(const Ray& ray, float time, Hit& best, float& best_t) const {
    closest_in_group(scene_.top, top_bvh_, top_leaves_, ray, time, kInvalidId, best, best_t);
  }
  bool any(const Ray& ray, float time) const { return any_in_group(scene_.top, top_bvh_, top_leaves_, ray, time); }
  // The packet's `active` lanes: closest hits into best[lane] (distances in packet.tmax), or the
  // lanes that something blocks in (tnear, tfar); with `timed`, moving shapes where they are at
  // each lane's packet.time, else at time 0. Lane by lane the answers of closest and any.
  void closest_in_packet(RayPacket& packet, bool timed, std::uint32_t active, Hit* best) const;
  std::uint32_t any_in_packet(const RayPacket& packet, bool timed, std::uint32_t active) const;

  double build_seconds() const { return build_seconds_; }
  std::size_t memory_bytes() const;

 private:
  void closest_in_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves, const Ray& ray, float time,
                        std::uint32_t inst, Hit& best, float& best_t) const;
  bool any_in_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves, const Ray& ray, float time) const;
  // closest_in_packet and any_in_packet in one group: `inst` is the instance whose prototype the
  // group is (kInvalidId at the top level).
  void closest_in_packet_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves, RayPacket& packet,
                               bool timed, std::uint32_t active, std::uint32_t inst, Hit* best) const;
  std::uint32_t any_in_packet_group(const Group& group, const Bvh& bvh, const TriangleLeaves& leaves,
                                    const RayPacket& packet, bool timed, std::uint32_t active) const;

  const RenderScene& scene_;
  Bvh top_bvh_;
  TriangleLeaves top_leaves_;
  std::vector<Bvh> prototype_bvhs_;
  std::vector<TriangleLeaves> prototype_leaves_;
  double build_seconds_ = 0.0;
};

}  // namespace rtpro
