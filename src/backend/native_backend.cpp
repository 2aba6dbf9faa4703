// The native backend: the reference answer. One BVH per group (native_traversal.h), rays gated
// and batched into packets of eight here. Kept simple and plainly correct.
#include "native_backend.h"

#include "native_traversal.h"
#include "ray_gate.h"
#include "ray_packet.h"
#include "sphere_lanes.h"

#include <bit>
#include <span>

namespace rtpro {

namespace {

// Loads the next rays of the batch, from `i` on, into `packet`: eight at once when the next eight
// are all traceable, else one by one up to eight that the gate admits. `answer_none(i)` runs for
// every ray it passes, loaded or refused, and slots[k] is lane k's ray. Returns the lanes filled,
// 0 only at the end of the batch.
template <typename AnswerNone>
[[gnu::always_inline]] inline unsigned next_packet(std::span<const Ray> rays, std::size_t& i, const RayGate& gate,
                                                   RayPacket& packet, std::size_t (&slots)[kPacketSize],
                                                   AnswerNone&& answer_none) {
  unsigned count = 0;
  if (rays.size() - i >= kPacketSize && packet.load_traceable(&rays[i])) {
    for (; count < kPacketSize; ++count, ++i) {
      answer_none(i);
      slots[count] = i;
    }
    return count;
  }
  for (; i < rays.size() && count < kPacketSize; ++i) {
    answer_none(i);
    if (!gate.admit(rays[i])) continue;
    packet.set(count, rays[i], rays[i].tfar);
    slots[count++] = i;
  }
  if (count != 0) packet.finish(count);
  return count;
}

class NativeBackend final : public Backend {
 public:
  NativeBackend(const RenderScene& scene) : packets_(sphere_lanes_vectorised()), bvhs_(scene, packets_) {}

  std::string_view name() const override { return "native"; }
  using Backend::intersect;
  using Backend::occluded;

  bool intersect(const Ray& ray, Hit& hit) const override { return intersect(ray, 0.0f, hit); }
  bool occluded(const Ray& ray) const override { return occluded(ray, 0.0f); }

  bool intersect(const Ray& ray, float time, Hit& hit) const override {
    if (!gate_.admit(ray)) return false;
    Hit best;
    float best_t = ray.tfar;
    bvhs_.closest(ray, time, best, best_t);
    if (!best.valid()) return false;
    hit = best;
    hit.t = best_t;
    return true;
  }

  bool occluded(const Ray& ray, float time) const override {
    if (!gate_.admit(ray)) return false;
    return bvhs_.any(ray, time);
  }

  // Scattered rays in packets of eight through the top-level BVH: one node test for eight rays,
  // spheres four lanes at a time. The answers are the single-ray ones: every primitive a lane's
  // single traversal would test is tested (the box test is the same, lane by lane), and the
  // closest hit under the shared tie rule does not depend on the order of the tests.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence coherence) const override {
    if (!packets_) return Backend::intersect(rays, hits, coherence);
    closest_in_packets(rays, {}, hits);
  }

  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> result, RayCoherence coherence) const override {
    if (!packets_) return Backend::occluded(rays, result, coherence);
    any_in_packets(rays, {}, result);
  }

  // Rays with times in packets too, each lane where the scene is at its time.
  void intersect(std::span<const Ray> rays, std::span<const float> times, std::span<Hit> hits,
                 RayCoherence coherence) const override {
    if (!packets_ || times.empty()) return Backend::intersect(rays, times, hits, coherence);
    closest_in_packets(rays, times, hits);
  }

  void occluded(std::span<const Ray> rays, std::span<const float> times, std::span<std::uint8_t> result,
                RayCoherence coherence) const override {
    if (!packets_ || times.empty()) return Backend::occluded(rays, times, result, coherence);
    any_in_packets(rays, times, result);
  }

  BackendStats stats() const override {
    BackendStats s;
    s.build_seconds = bvhs_.build_seconds();
    s.acceleration_bytes = bvhs_.memory_bytes();
    s.rejected_rays = gate_.rejected();
    return s;
  }

 private:
  // Each lane's time from `times` (empty: none).
  static void set_times(RayPacket& packet, std::span<const float> times, const std::size_t (&slots)[kPacketSize],
                        unsigned count) {
    for (unsigned k = 0; k < count; ++k) packet.time[k] = times[slots[k]];
  }

  void closest_in_packets(std::span<const Ray> rays, std::span<const float> times, std::span<Hit> hits) const {
    RayPacket packet;
    Hit best[kPacketSize];
    std::size_t slots[kPacketSize];
    std::size_t i = 0;
    const bool timed = !times.empty();
    while (i < rays.size()) {
      const unsigned count = next_packet(rays, i, gate_, packet, slots, [&](std::size_t r) { hits[r] = Hit{}; });
      if (count == 0) continue;
      if (timed) set_times(packet, times, slots, count);
      for (Hit& lane_best : best) lane_best = Hit{};
      bvhs_.closest_in_packet(packet, timed, (1u << count) - 1u, best);
      // The record is copied first and its distance stored after: setting best[k].t and then
      // copying the record read the fresh 4-byte store back with a 16-byte load, a
      // store-forwarding stall per hit.
      for (unsigned k = 0; k < count; ++k) {
        if (!best[k].valid()) continue;
        Hit& hit = hits[slots[k]];
        hit = best[k];
        hit.t = packet.tmax[k];
      }
    }
  }

  void any_in_packets(std::span<const Ray> rays, std::span<const float> times, std::span<std::uint8_t> result) const {
    RayPacket packet;
    std::size_t slots[kPacketSize];
    std::size_t i = 0;
    const bool timed = !times.empty();
    while (i < rays.size()) {
      const unsigned count = next_packet(rays, i, gate_, packet, slots, [&](std::size_t r) { result[r] = 0; });
      if (count == 0) continue;
      if (timed) set_times(packet, times, slots, count);
      std::uint32_t blocked = bvhs_.any_in_packet(packet, timed, (1u << count) - 1u);
      for (; blocked != 0; blocked &= blocked - 1) result[slots[std::countr_zero(blocked)]] = 1;
    }
  }

  const bool packets_;  // the CPU has AVX2
  NativeTraversal bvhs_;
  RayGate gate_;
};

}  // namespace

std::unique_ptr<Backend> make_native_backend(const RenderScene& scene, const BackendOptions&) {
  return std::make_unique<NativeBackend>(scene);
}

}  // namespace rtpro
