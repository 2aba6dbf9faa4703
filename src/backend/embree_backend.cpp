// The Embree backend: the same answers as the native backend (bit-identical for top-level
// spheres, within float tolerance for triangles and instances), from Embree 3's BVHs.
#include "embree_backend.h"

#include "embree_device.h"
#include "embree_scene_builder.h"
#include "embree_spheres.h"
#include "ray_gate.h"
#include "ray_packet.h"
#include "rtpro/core/avx2_clones.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>
#include <chrono>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

// Every field Embree reads, set explicitly: a zero mask would hit nothing (Debian's Embree is
// built with ray masks).
void to_embree(const Ray& ray, float tfar, unsigned id, RTCRay& r) {
  r.org_x = ray.org.x;
  r.org_y = ray.org.y;
  r.org_z = ray.org.z;
  r.tnear = ray.tnear;
  r.dir_x = ray.dir.x;
  r.dir_y = ray.dir.y;
  r.dir_z = ray.dir.z;
  r.time = 0.0f;
  r.tfar = tfar;
  r.mask = 0xFFFFFFFFu;
  r.id = id;
  r.flags = 0;
}

// The invalid ids tell a miss apart after the query.
void to_embree(const Ray& ray, unsigned id, RTCRayHit& out) {
  to_embree(ray, ray.tfar, id, out.ray);
  out.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  out.hit.primID = RTC_INVALID_GEOMETRY_ID;
  out.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

bool from_embree(const RTCRayHit& in, Hit& hit) {
  if (in.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = in.ray.tfar;
  hit.u = in.hit.u;
  hit.v = in.hit.v;
  hit.geom_id = in.hit.geomID;
  hit.prim_id = in.hit.primID;
  hit.inst_id = in.hit.instID[0];
  return true;
}

// std::nextafter(t, 0.0f) without the libm call (0.7% of a render): one step towards zero is one
// less in the bit pattern for every non-zero float, infinity (to the largest float) included.
// Never called with NaN (the gate refuses it).
float one_step_towards_zero(float t) {
  return t == 0.0f ? t : std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) - 1u);
}

bool has_triangles(const Group& group) {
  for (const Geometry& geometry : group.geometries) {
    switch (kind_of(geometry)) {
      case GeometryKind::kTriangles: return true;
      case GeometryKind::kSpheres:
      case GeometryKind::kInstance: break;
    }
  }
  return false;
}

// Packets keep every ray's answer a function of the ray alone only where rtpro's own callbacks
// decide each hit. Embree's triangle kernels round packet lanes differently from single rays
// (2e-5 in a glTF scene), and its hybrid traversal chooses between them by how many lanes of a
// packet are active, so a triangle hit would depend on which rays share its packet: on tiles,
// threads and ranks.
bool rays_decided_by_callbacks(const RenderScene& scene) {
  if (has_triangles(scene.top)) return false;
  for (const Group& prototype : scene.prototypes)
    if (has_triangles(prototype)) return false;
  return true;
}

// Lane `lane` of an answered packet, or nothing where it hit nothing.
bool hit_of_lane(const RTCRayHit8& packet, unsigned lane, Hit& hit) {
  if (packet.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = packet.ray.tfar[lane];
  hit.u = packet.hit.u[lane];
  hit.v = packet.hit.v[lane];
  hit.geom_id = packet.hit.geomID[lane];
  hit.prim_id = packet.hit.primID[lane];
  hit.inst_id = packet.hit.instID[0][lane];
  return true;
}

Hit no_sphere_yet(const Ray& ray) {
  Hit closest;
  closest.t = ray.tfar;
  return closest;
}

class EmbreeBackend final : public Backend {
 public:
  EmbreeBackend(const RenderScene& scene, const BackendOptions& options)
      : device_(EmbreeDevice::get(options.threads)), packets_(rays_decided_by_callbacks(scene)), wide_loads_(sphere_lanes_vectorised()) {
    const EmbreeBuildSettings settings = embree_build_settings(options);
    EmbreeDevice::Session session(*device_, options.max_memory_bytes);
    const auto start = std::chrono::steady_clock::now();
    scenes_ = build_embree_scenes(session, scene, settings);
    stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_.acceleration_bytes = static_cast<std::size_t>(std::max<std::int64_t>(0, session.allocated_bytes()));
  }

  // Releasing frees Embree memory; inside a session so another thread's build does not count it.
  ~EmbreeBackend() override {
    EmbreeDevice::Session session(*device_, 0);
    scenes_ = {};
  }

  std::string_view name() const override { return "embree"; }

  bool intersect(const Ray& ray, Hit& hit) const override {
    if (!gate_.admit(ray)) return false;
    Hit closest_sphere = no_sphere_yet(ray);
    EmbreeIntersectContext context;
    rtcInitIntersectContext(&context.base);
    context.closest_spheres = &closest_sphere;
    alignas(16) RTCRayHit query;
    to_embree(ray, 0, query);
    rtcIntersect1(scenes_.top.get(), &context.base, &query);
    return from_embree(query, hit);
  }

  // Where only spheres can be hit (packets_), every batch goes in packets of eight, camera rays
  // too: 7% faster on the demo than the coherent stream, whose regrouping costs more than it
  // gains for a handful of user-geometry primitives. Elsewhere camera rays go to Embree as a
  // stream with the coherent flag: Embree regroups them into packets, which traced camera tiles
  // 1.3–2.4× faster than one rtcIntersect1 per ray (third_party_notes/embree.md), and scattered
  // rays one by one: streams of incoherent rays were 2.7× slower than single rays.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence coherence) const override {
    if (packets_) {
      intersect_packets(rays, hits);
      return;
    }
    if (coherence == RayCoherence::kIncoherent) {
      for (std::size_t i = 0; i < rays.size(); ++i)
        if (!intersect(rays[i], hits[i])) hits[i] = Hit{};
      return;
    }
    intersect_stream(rays, hits);
  }

  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> result, RayCoherence coherence) const override {
    if (packets_) {
      occluded_packets(rays, result);
      return;
    }
    if (coherence == RayCoherence::kIncoherent) {
      for (std::size_t i = 0; i < rays.size(); ++i) result[i] = occluded(rays[i]) ? 1 : 0;
      return;
    }
    occluded_stream(rays, result);
  }

  // Embree's triangles accept t == tfar; asking for (tnear, previous float below tfar] instead
  // gives exactly the open interval (tnear, tfar) the interface promises, for every geometry.
  bool occluded(const Ray& ray) const override {
    if (!gate_.admit(ray)) return false;
    const float tfar = one_step_towards_zero(ray.tfar);
    if (!(tfar > ray.tnear)) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(16) RTCRay query;
    to_embree(ray, tfar, 0, query);
    rtcOccluded1(scenes_.top.get(), &context, &query);
    return query.tfar < 0.0f;
  }

  BackendStats stats() const override {
    BackendStats s = stats_;
    s.rejected_rays = gate_.rejected();
    return s;
  }

 private:
  static constexpr unsigned kPacket = 8;

  // The fields of a packet lane that do not come from the ray.
  static void start_packet_lane(RTCRay8& packet, unsigned lane) {
    packet.time[lane] = 0.0f;
    packet.mask[lane] = 0xFFFFFFFFu;
    packet.id[lane] = lane;
    packet.flags[lane] = 0;
  }

  // A coherent stream goes to Embree as packets of eight in its own layout (rtcIntersectNM with
  // N = 8): with Embree's kernels at AVX2 that is its stream traversal's native width, so it
  // traces the packets in place, 32 rays at a time, where an array of single rays is copied into
  // packets and back. Lanes the gate refuses stay inactive (tnear 0, tfar -inf).
  static constexpr unsigned kStreamPackets = 4;

  // A lane Embree skips: tnear 0, tfar −inf, a harmless direction.
  static void leave_lane_inactive(RTCRay8& ray, unsigned lane) {
    ray.org_x[lane] = ray.org_y[lane] = ray.org_z[lane] = 0.0f;
    ray.dir_x[lane] = ray.dir_y[lane] = 0.0f;
    ray.dir_z[lane] = 1.0f;
    ray.tnear[lane] = 0.0f;
    ray.tfar[lane] = -std::numeric_limits<float>::infinity();
    start_packet_lane(ray, lane);
  }
  static RTCRay8& ray_of(RTCRay8& packet) { return packet; }
  static RTCRay8& ray_of(RTCRayHit8& packet) { return packet.ray; }

  // Rays [first, first + 32) (fewer at the end) into the stream's lanes; tfar through `far`.
  template <typename Packet, typename Far>
  unsigned load_stream(std::span<const Ray> rays, std::size_t first, Packet (&packets)[kStreamPackets], Far far) const {
    const unsigned count = static_cast<unsigned>(std::min<std::size_t>(rays.size() - first, kStreamPackets * kPacket));
    for (unsigned k = 0; k < count;) {
      RTCRay8& packet = ray_of(packets[k / kPacket]);
      if (wide_loads_ && k % kPacket == 0 && count - k >= kPacket &&
          load_traceable_lanes(&rays[first + k], {packet.org_x, packet.org_y, packet.org_z, packet.tnear, packet.dir_x,
                                                  packet.dir_y, packet.dir_z, packet.tfar})) {
        for (unsigned lane = 0; lane < kPacket; ++lane) {
          packet.tfar[lane] = far(packet.tfar[lane], packet.tnear[lane]);
          start_packet_lane(packet, lane);
          packet.id[lane] = k + lane;
        }
        k += kPacket;
        continue;
      }
      const unsigned lane = k % kPacket;
      const Ray& ray = rays[first + k];
      if (gate_.admit(ray)) {
        packet.org_x[lane] = ray.org.x;
        packet.org_y[lane] = ray.org.y;
        packet.org_z[lane] = ray.org.z;
        packet.dir_x[lane] = ray.dir.x;
        packet.dir_y[lane] = ray.dir.y;
        packet.dir_z[lane] = ray.dir.z;
        packet.tnear[lane] = ray.tnear;
        packet.tfar[lane] = far(ray.tfar, ray.tnear);
        start_packet_lane(packet, lane);
      } else {
        leave_lane_inactive(packet, lane);
      }
      packet.id[lane] = k;
      ++k;
    }
    for (unsigned k = count; k < kStreamPackets * kPacket; ++k) leave_lane_inactive(ray_of(packets[k / kPacket]), k % kPacket);
    return count;
  }

  RTPRO_AVX2_CLONES void intersect_stream(std::span<const Ray> rays, std::span<Hit> hits) const {
    alignas(32) RTCRayHit8 packets[kStreamPackets];
    Hit closest_spheres[kStreamPackets * kPacket];
    for (std::size_t first = 0; first < rays.size(); first += kStreamPackets * kPacket) {
      const unsigned count = load_stream(rays, first, packets, [](float tfar, float) { return tfar; });
      for (unsigned k = 0; k < kStreamPackets * kPacket; ++k) {
        RTCRayHit8& packet = packets[k / kPacket];
        const unsigned lane = k % kPacket;
        closest_spheres[k] = Hit{};
        closest_spheres[k].t = packet.ray.tfar[lane];
        packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.primID[lane] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
      }
      EmbreeIntersectContext context;
      rtcInitIntersectContext(&context.base);
      context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      context.closest_spheres = closest_spheres;
      rtcIntersectNM(scenes_.top.get(), &context.base, reinterpret_cast<RTCRayHitN*>(packets), kPacket,
                     kStreamPackets, sizeof(RTCRayHit8));
      for (unsigned k = 0; k < count; ++k) {
        hits[first + k] = Hit{};
        hit_of_lane(packets[k / kPacket], k % kPacket, hits[first + k]);
      }
    }
  }

  // A segment too short for the open interval (tnear, tfar) is no query: its lane is left
  // inactive, and the ray unoccluded.
  RTPRO_AVX2_CLONES void occluded_stream(std::span<const Ray> rays, std::span<std::uint8_t> result) const {
    alignas(32) RTCRay8 packets[kStreamPackets];
    for (std::size_t first = 0; first < rays.size(); first += kStreamPackets * kPacket) {
      const unsigned count = load_stream(rays, first, packets, [](float tfar, float tnear) {
        const float below = one_step_towards_zero(tfar);
        return below > tnear ? below : -std::numeric_limits<float>::infinity();
      });
      // Embree marks an occluded ray with tfar = -inf, as inactive lanes start.
      std::uint32_t queried = 0;
      for (unsigned k = 0; k < count; ++k)
        if (packets[k / kPacket].tfar[k % kPacket] >= 0.0f) queried |= 1u << k;
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
      rtcOccludedNM(scenes_.top.get(), &context, reinterpret_cast<RTCRayN*>(packets), kPacket, kStreamPackets,
                    sizeof(RTCRay8));
      for (unsigned k = 0; k < count; ++k) {
        const bool occluded = (queried >> k & 1u) != 0 && packets[k / kPacket].tfar[k % kPacket] < 0.0f;
        result[first + k] = occluded ? 1 : 0;
      }
    }
  }

  RTPRO_AVX2_CLONES void intersect_packets(std::span<const Ray> rays, std::span<Hit> hits) const {
    alignas(32) RTCRayHit8 packet;
    alignas(32) int valid[kPacket];
    Hit closest_spheres[kPacket];
    std::size_t slots[kPacket];
    std::size_t i = 0;
    while (i < rays.size()) {
      unsigned count = 0;
      if (wide_loads_ && rays.size() - i >= kPacket &&
          load_traceable_lanes(&rays[i], {packet.ray.org_x, packet.ray.org_y, packet.ray.org_z, packet.ray.tnear,
                                          packet.ray.dir_x, packet.ray.dir_y, packet.ray.dir_z, packet.ray.tfar})) {
        for (; count < kPacket; ++count, ++i) {
          hits[i] = Hit{};
          closest_spheres[count] = no_sphere_yet(rays[i]);
          start_packet_lane(packet.ray, count);
          packet.hit.geomID[count] = RTC_INVALID_GEOMETRY_ID;
          packet.hit.primID[count] = RTC_INVALID_GEOMETRY_ID;
          packet.hit.instID[0][count] = RTC_INVALID_GEOMETRY_ID;
          valid[count] = -1;
          slots[count] = i;
        }
      }
      for (; i < rays.size() && count < kPacket; ++i) {
        hits[i] = Hit{};
        if (!gate_.admit(rays[i])) continue;
        const Ray& ray = rays[i];
        closest_spheres[count] = no_sphere_yet(ray);
        packet.ray.org_x[count] = ray.org.x;
        packet.ray.org_y[count] = ray.org.y;
        packet.ray.org_z[count] = ray.org.z;
        packet.ray.tnear[count] = ray.tnear;
        packet.ray.dir_x[count] = ray.dir.x;
        packet.ray.dir_y[count] = ray.dir.y;
        packet.ray.dir_z[count] = ray.dir.z;
        packet.ray.tfar[count] = ray.tfar;
        start_packet_lane(packet.ray, count);
        packet.hit.geomID[count] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.primID[count] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][count] = RTC_INVALID_GEOMETRY_ID;
        valid[count] = -1;
        slots[count++] = i;
      }
      if (count == 0) continue;
      for (unsigned k = count; k < kPacket; ++k) valid[k] = 0;
      EmbreeIntersectContext context;
      rtcInitIntersectContext(&context.base);
      context.closest_spheres = closest_spheres;
      rtcIntersect8(valid, scenes_.top.get(), &context.base, &packet);
      for (unsigned k = 0; k < count; ++k) hit_of_lane(packet, k, hits[slots[k]]);
    }
  }

  RTPRO_AVX2_CLONES void occluded_packets(std::span<const Ray> rays, std::span<std::uint8_t> result) const {
    alignas(32) RTCRay8 packet;
    alignas(32) int valid[kPacket];
    std::size_t slots[kPacket];
    std::size_t i = 0;
    while (i < rays.size()) {
      unsigned count = 0;
      if (wide_loads_ && rays.size() - i >= kPacket &&
          load_traceable_lanes(&rays[i], {packet.org_x, packet.org_y, packet.org_z, packet.tnear, packet.dir_x,
                                          packet.dir_y, packet.dir_z, packet.tfar})) {
        // A segment too short for the open interval is no query; such a group goes one by one.
        bool all_open = true;
        for (unsigned k = 0; k < kPacket; ++k) {
          packet.tfar[k] = one_step_towards_zero(packet.tfar[k]);
          all_open = all_open && packet.tfar[k] > packet.tnear[k];
        }
        if (all_open)
          for (; count < kPacket; ++count, ++i) {
            result[i] = 0;
            start_packet_lane(packet, count);
            valid[count] = -1;
            slots[count] = i;
          }
      }
      for (; i < rays.size() && count < kPacket; ++i) {
        result[i] = 0;
        if (!gate_.admit(rays[i])) continue;
        const Ray& ray = rays[i];
        const float tfar = one_step_towards_zero(ray.tfar);
        if (!(tfar > ray.tnear)) continue;
        packet.org_x[count] = ray.org.x;
        packet.org_y[count] = ray.org.y;
        packet.org_z[count] = ray.org.z;
        packet.tnear[count] = ray.tnear;
        packet.dir_x[count] = ray.dir.x;
        packet.dir_y[count] = ray.dir.y;
        packet.dir_z[count] = ray.dir.z;
        packet.tfar[count] = tfar;
        start_packet_lane(packet, count);
        valid[count] = -1;
        slots[count++] = i;
      }
      if (count == 0) continue;
      for (unsigned k = count; k < kPacket; ++k) valid[k] = 0;
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      rtcOccluded8(valid, scenes_.top.get(), &context, &packet);
      for (unsigned k = 0; k < count; ++k) result[slots[k]] = packet.tfar[k] < 0.0f ? 1 : 0;
    }
  }

  std::shared_ptr<EmbreeDevice> device_;
  // Rays go to Embree in packets of eight (rtcIntersect8, rtcOccluded8): one traversal
  // and one callback per sphere for up to eight rays, 1.18x faster on the demo than one
  // rtcIntersect1 per ray. Only for scenes without triangles (rays_decided_by_callbacks).
  bool packets_;
  bool wide_loads_;  // eight rays loaded at once (load_traceable_lanes needs AVX2)
  EmbreeScenes scenes_;
  BackendStats stats_;
  RayGate gate_;
};

}  // namespace

std::unique_ptr<Backend> make_embree_backend(const RenderScene& scene, const BackendOptions& options) {
  return std::make_unique<EmbreeBackend>(scene, options);
}

}  // namespace rtpro
