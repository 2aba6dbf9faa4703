#include "embree_ray_batches.h"

#include "embree_user_geometry.h"
#include "ray_packet.h"
#include "rtpro/core/avx2_clones.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <variant>

namespace rtpro {

namespace {

// Lane `lane` of an answered packet, or nothing where it hit nothing.
bool hit_of_lane(const RTCRayHit8& packet, unsigned lane, const EmbreeHitIds& hit_ids, Hit& hit) {
  if (packet.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = packet.ray.tfar[lane];
  hit.u = packet.hit.u[lane];
  hit.v = packet.hit.v[lane];
  hit.geom_id = packet.hit.geomID[lane];
  hit.prim_id = packet.hit.primID[lane];
  hit.inst_id = packet.hit.instID[0][lane];
  hit_ids.resolve(hit);
  return true;
}

constexpr unsigned kPacket = 8;

// Where a ray meets two triangles at exactly the same distance (through their shared edge or
// vertex), Embree's coherent stream can report the other one than the ray traced alone, depending
// on the rays it is grouped with (tests/backend/batch_queries_test.cpp). Both triangles must then
// count the hit as within them, Embree's edge test allowing one ulp of their edge functions' sum,
// so each reports a barycentric within an ulp of 0 times the ratio of the two triangles' heights
// over that edge: hits within kTieBand of an edge are traced again alone, which covers neighbours
// up to some 800 times as high.
constexpr float kTieBand = 1e-4f;

bool may_tie_with_a_neighbour(const RenderScene& scene, const Hit& hit) {
  const Group& group = hit.inst_id == kInvalidId
                           ? scene.top
                           : scene.prototypes[std::get<Instance>(scene.top.geometries[hit.inst_id]).prototype];
  if (!std::holds_alternative<TriangleMesh>(group.geometries[hit.geom_id])) return false;
  return hit.u <= kTieBand || hit.v <= kTieBand || 1.0f - hit.u - hit.v <= kTieBand;
}

// A coherent occlusion stream's context. The stream culls with its packets' frustum and its own
// test of a leaf's box (none for a root leaf), which can let a ray that runs exactly along a
// triangle's edge into a leaf whose box the ray alone misses by an ulp; Embree's edge test allows
// an ulp, so the stream meets a hit the ray alone never reaches, and whether it does depends on
// the rays it is grouped with (Embree 3.13's BVHNIntersectorStream::occludedCoherent). Such a
// candidate lies within kTieBand of the edge: the filter refuses it and marks the ray to be traced
// again alone. Any other candidate the ray alone meets too (every box on its way holds it with
// room to spare), so it stands.
struct StreamOcclusionContext {
  RTCIntersectContext base;  // first member: Embree passes &base to the filter
  const EmbreeRayTarget* target;
  std::uint32_t alone;  // bit k: ray k of the 32 met a candidate within kTieBand of an edge
};
static_assert(std::is_standard_layout_v<StreamOcclusionContext>);

// Embree's context filter (called from inside its kernels: nothing here may throw).
void refuse_edge_candidates(const RTCFilterFunctionNArguments* args) {
  auto* context = reinterpret_cast<StreamOcclusionContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    Hit hit;
    hit.u = RTCHitN_u(args->hit, args->N, i);
    hit.v = RTCHitN_v(args->hit, args->N, i);
    hit.geom_id = RTCHitN_geomID(args->hit, args->N, i);
    hit.prim_id = RTCHitN_primID(args->hit, args->N, i);
    hit.inst_id = RTCHitN_instID(args->hit, args->N, i, 0);
    context->target->hit_ids.resolve(hit);
    if (!may_tie_with_a_neighbour(context->target->render_scene, hit)) continue;
    args->valid[i] = 0;
    context->alone |= 1u << RTCRayN_id(args->ray, args->N, i);
  }
}

// Ray i's time in the shutter, 0 where the batch has no times.
inline float time_of(std::span<const float> times, std::size_t i) { return times.empty() ? 0.0f : times[i]; }

// The fields of a packet lane that do not come from the ray.
void start_packet_lane(RTCRay8& packet, unsigned lane) {
  packet.time[lane] = 0.0f;
  packet.mask[lane] = 0xFFFFFFFFu;
  packet.id[lane] = lane;
  packet.flags[lane] = 0;
}

// A coherent stream goes to Embree as packets of eight in its own layout (rtcIntersectNM with
// N = 8): with Embree's kernels at AVX2 that is its stream traversal's native width, so it
// traces the packets in place, 32 rays at a time, where an array of single rays is copied into
// packets and back. Lanes the gate refuses stay inactive (tnear 0, tfar -inf).
constexpr unsigned kStreamPackets = 4;

// A lane Embree skips: tnear 0, tfar −inf, a harmless direction.
void leave_lane_inactive(RTCRay8& ray, unsigned lane) {
  ray.org_x[lane] = ray.org_y[lane] = ray.org_z[lane] = 0.0f;
  ray.dir_x[lane] = ray.dir_y[lane] = 0.0f;
  ray.dir_z[lane] = 1.0f;
  ray.tnear[lane] = 0.0f;
  ray.tfar[lane] = -std::numeric_limits<float>::infinity();
  start_packet_lane(ray, lane);
}
RTCRay8& ray_of(RTCRay8& packet) { return packet; }
RTCRay8& ray_of(RTCRayHit8& packet) { return packet.ray; }

// Rays [first, first + 32) (fewer at the end) into the stream's lanes; tfar through `far`.
template <typename Packet, typename Far>
unsigned load_stream(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                     std::size_t first, Packet (&packets)[kStreamPackets], Far far) {
  const unsigned count = static_cast<unsigned>(std::min<std::size_t>(rays.size() - first, kStreamPackets * kPacket));
  for (unsigned k = 0; k < count;) {
    RTCRay8& packet = ray_of(packets[k / kPacket]);
    if (target.wide_loads && k % kPacket == 0 && count - k >= kPacket &&
        load_traceable_lanes(&rays[first + k], {packet.org_x, packet.org_y, packet.org_z, packet.tnear, packet.dir_x,
                                                packet.dir_y, packet.dir_z, packet.tfar})) {
      for (unsigned lane = 0; lane < kPacket; ++lane) {
        packet.tfar[lane] = far(packet.tfar[lane], packet.tnear[lane]);
        start_packet_lane(packet, lane);
        packet.time[lane] = time_of(times, first + k + lane);
        packet.id[lane] = k + lane;
      }
      k += kPacket;
      continue;
    }
    const unsigned lane = k % kPacket;
    const Ray& ray = rays[first + k];
    if (target.gate.admit(ray)) {
      packet.org_x[lane] = ray.org.x;
      packet.org_y[lane] = ray.org.y;
      packet.org_z[lane] = ray.org.z;
      packet.dir_x[lane] = ray.dir.x;
      packet.dir_y[lane] = ray.dir.y;
      packet.dir_z[lane] = ray.dir.z;
      packet.tnear[lane] = ray.tnear;
      packet.tfar[lane] = far(ray.tfar, ray.tnear);
      start_packet_lane(packet, lane);
      packet.time[lane] = time_of(times, first + k);
    } else {
      leave_lane_inactive(packet, lane);
    }
    packet.id[lane] = k;
    ++k;
  }
  for (unsigned k = count; k < kStreamPackets * kPacket; ++k)
    leave_lane_inactive(ray_of(packets[k / kPacket]), k % kPacket);
  return count;
}

}  // namespace

RTPRO_AVX2_CLONES void intersect_one_by_one(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                            std::span<const float> times, std::span<Hit> hits) {
  Hit closest_user_hit;
  EmbreeIntersectContext context;
  rtcInitIntersectContext(&context.base);
  context.closest_user_hits = &closest_user_hit;
  alignas(16) RTCRayHit query;
  query.ray.time = 0.0f;
  query.ray.mask = 0xFFFFFFFFu;
  query.ray.id = 0;
  query.ray.flags = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Ray& ray = rays[i];
    Hit& hit = hits[i];
    hit = Hit{};
    if (!target.gate.admit(ray)) continue;
    closest_user_hit = no_user_hit_yet(ray);
    set_ray_fields(ray, ray.tfar, query.ray);
    query.ray.time = time_of(times, i);
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(target.scene, &context.base, &query);
    from_embree(query, target.hit_ids, hit);
  }
}

RTPRO_AVX2_CLONES void occluded_one_by_one(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                           std::span<const float> times, std::span<std::uint8_t> result) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(16) RTCRay query;
  query.time = 0.0f;
  query.mask = 0xFFFFFFFFu;
  query.id = 0;
  query.flags = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Ray& ray = rays[i];
    result[i] = 0;
    if (!target.gate.admit(ray)) continue;
    // (tnear, the float below tfar]: exactly the open interval, as the backend's single-ray query.
    const float tfar = one_step_towards_zero(ray.tfar);
    if (!(tfar > ray.tnear)) continue;
    set_ray_fields(ray, tfar, query);
    query.time = time_of(times, i);
    rtcOccluded1(target.scene, &context, &query);
    result[i] = query.tfar < 0.0f ? 1 : 0;
  }
}

RTPRO_AVX2_CLONES void intersect_stream(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                        std::span<const float> times, std::span<Hit> hits) {
  alignas(32) RTCRayHit8 packets[kStreamPackets];
  Hit closest_user_hits[kStreamPackets * kPacket];
  for (std::size_t first = 0; first < rays.size(); first += kStreamPackets * kPacket) {
    // The stream misses hits exactly at tfar, which (tnear, tfar] includes: it is asked for one
    // float further, and a hit beyond tfar is a miss.
    const unsigned count = load_stream(target, rays, times, first, packets,
                                       [](float tfar, float) { return one_step_away_from_zero(tfar); });
    for (unsigned k = 0; k < kStreamPackets * kPacket; ++k) {
      RTCRayHit8& packet = packets[k / kPacket];
      const unsigned lane = k % kPacket;
      closest_user_hits[k] = Hit{};
      closest_user_hits[k].t = packet.ray.tfar[lane];
      packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.primID[lane] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
    EmbreeIntersectContext context;
    rtcInitIntersectContext(&context.base);
    context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    context.closest_user_hits = closest_user_hits;
    rtcIntersectNM(target.scene, &context.base, reinterpret_cast<RTCRayHitN*>(packets), kPacket, kStreamPackets,
                   sizeof(RTCRayHit8));
    for (unsigned k = 0; k < count; ++k) {
      Hit& hit = hits[first + k];
      hit = Hit{};
      if (!hit_of_lane(packets[k / kPacket], k % kPacket, target.hit_ids, hit)) continue;
      if (hit.t > rays[first + k].tfar) hit = Hit{};
      else if (may_tie_with_a_neighbour(target.render_scene, hit))
        intersect_one_by_one(target, rays.subspan(first + k, 1), times.empty() ? times : times.subspan(first + k, 1),
                             std::span<Hit>(&hit, 1));
    }
  }
}

// A segment too short for the open interval (tnear, tfar) is no query: its lane is left
// inactive, and the ray unoccluded.
RTPRO_AVX2_CLONES void occluded_stream(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                       std::span<const float> times, std::span<std::uint8_t> result) {
  alignas(32) RTCRay8 packets[kStreamPackets];
  for (std::size_t first = 0; first < rays.size(); first += kStreamPackets * kPacket) {
    const unsigned count = load_stream(target, rays, times, first, packets, [](float tfar, float tnear) {
      const float below = one_step_towards_zero(tfar);
      return below > tnear ? below : -std::numeric_limits<float>::infinity();
    });
    // Embree marks an occluded ray with tfar = -inf, as inactive lanes start.
    std::uint32_t queried = 0;
    for (unsigned k = 0; k < count; ++k)
      if (packets[k / kPacket].tfar[k % kPacket] >= 0.0f) queried |= 1u << k;
    StreamOcclusionContext context;
    rtcInitIntersectContext(&context.base);
    context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    context.base.filter = refuse_edge_candidates;
    context.target = &target;
    context.alone = 0;
    rtcOccludedNM(target.scene, &context.base, reinterpret_cast<RTCRayN*>(packets), kPacket, kStreamPackets,
                  sizeof(RTCRay8));
    for (unsigned k = 0; k < count; ++k) {
      const bool occluded = (queried >> k & 1u) != 0 && packets[k / kPacket].tfar[k % kPacket] < 0.0f;
      result[first + k] = occluded ? 1 : 0;
      if (!occluded && (context.alone >> k & 1u) != 0)
        occluded_one_by_one(target, rays.subspan(first + k, 1), times.empty() ? times : times.subspan(first + k, 1),
                            result.subspan(first + k, 1));
    }
  }
}

RTPRO_AVX2_CLONES void intersect_packets(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                         std::span<const float> times, std::span<Hit> hits) {
  alignas(32) RTCRayHit8 packet;
  alignas(32) int valid[kPacket];
  Hit closest_user_hits[kPacket];
  std::size_t slots[kPacket];
  std::size_t i = 0;
  while (i < rays.size()) {
    unsigned count = 0;
    if (target.wide_loads && rays.size() - i >= kPacket &&
        load_traceable_lanes(&rays[i], {packet.ray.org_x, packet.ray.org_y, packet.ray.org_z, packet.ray.tnear,
                                        packet.ray.dir_x, packet.ray.dir_y, packet.ray.dir_z, packet.ray.tfar})) {
      for (; count < kPacket; ++count, ++i) {
        hits[i] = Hit{};
        closest_user_hits[count] = no_user_hit_yet(rays[i]);
        start_packet_lane(packet.ray, count);
        packet.ray.time[count] = time_of(times, i);
        packet.hit.geomID[count] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.primID[count] = RTC_INVALID_GEOMETRY_ID;
        packet.hit.instID[0][count] = RTC_INVALID_GEOMETRY_ID;
        valid[count] = -1;
        slots[count] = i;
      }
    }
    for (; i < rays.size() && count < kPacket; ++i) {
      hits[i] = Hit{};
      if (!target.gate.admit(rays[i])) continue;
      const Ray& ray = rays[i];
      closest_user_hits[count] = no_user_hit_yet(ray);
      packet.ray.org_x[count] = ray.org.x;
      packet.ray.org_y[count] = ray.org.y;
      packet.ray.org_z[count] = ray.org.z;
      packet.ray.tnear[count] = ray.tnear;
      packet.ray.dir_x[count] = ray.dir.x;
      packet.ray.dir_y[count] = ray.dir.y;
      packet.ray.dir_z[count] = ray.dir.z;
      packet.ray.tfar[count] = ray.tfar;
      start_packet_lane(packet.ray, count);
      packet.ray.time[count] = time_of(times, i);
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
    context.closest_user_hits = closest_user_hits;
    rtcIntersect8(valid, target.scene, &context.base, &packet);
    for (unsigned k = 0; k < count; ++k) hit_of_lane(packet, k, target.hit_ids, hits[slots[k]]);
  }
}

RTPRO_AVX2_CLONES void occluded_packets(const EmbreeRayTarget& target, std::span<const Ray> rays,
                                        std::span<const float> times, std::span<std::uint8_t> result) {
  alignas(32) RTCRay8 packet;
  alignas(32) int valid[kPacket];
  std::size_t slots[kPacket];
  std::size_t i = 0;
  while (i < rays.size()) {
    unsigned count = 0;
    if (target.wide_loads && rays.size() - i >= kPacket &&
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
          packet.time[count] = time_of(times, i);
          valid[count] = -1;
          slots[count] = i;
        }
    }
    for (; i < rays.size() && count < kPacket; ++i) {
      result[i] = 0;
      if (!target.gate.admit(rays[i])) continue;
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
      packet.time[count] = time_of(times, i);
      valid[count] = -1;
      slots[count++] = i;
    }
    if (count == 0) continue;
    for (unsigned k = count; k < kPacket; ++k) valid[k] = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded8(valid, target.scene, &context, &packet);
    for (unsigned k = 0; k < count; ++k) result[slots[k]] = packet.tfar[k] < 0.0f ? 1 : 0;
  }
}

}  // namespace rtpro
