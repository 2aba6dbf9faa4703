// The Embree backend: the same answers as the native backend (bit-identical for top-level
// spheres, within float tolerance for triangles and instances), from Embree 3's BVHs.
#include "embree_backend.h"
#include "backend_shapes.h"

#include "embree_device.h"
#include "embree_ray_batches.h"
#include "embree_scene_builder.h"
#include "embree_user_geometry.h"
#include "ray_gate.h"
#include "sphere_lanes.h"
#include "rtpro/core/overloaded.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <chrono>
#include <variant>

namespace rtpro {

namespace {

// Every field Embree reads, set explicitly: a zero mask would hit nothing (Debian's Embree is
// built with ray masks).
void to_embree(const Ray& ray, float tfar, unsigned id, RTCRay& r, float time = 0.0f) {
  set_ray_fields(ray, tfar, r);
  r.time = time;
  r.mask = 0xFFFFFFFFu;
  r.id = id;
  r.flags = 0;
}

// The invalid ids tell a miss apart after the query.
void to_embree(const Ray& ray, unsigned id, RTCRayHit& out, float time = 0.0f) {
  to_embree(ray, ray.tfar, id, out.ray, time);
  out.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  out.hit.primID = RTC_INVALID_GEOMETRY_ID;
  out.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

// Shapes whose hits Embree's own kernels decide (triangles); an instance's prototype is asked itself.
bool has_triangles(const Group& group) {
  for (const Geometry& geometry : group.geometries) {
    const bool by_embree = std::visit(Overloaded{[](const Instance&) { return false; },
                                                 [](const auto& shapes) { return !hits_decided_by_rtpro(shapes); }},
                                      geometry);
    if (by_embree) return true;
  }
  return false;
}

// Where rtpro's own callbacks decide every hit, every batch goes in packets, camera rays too.
// Elsewhere a packet's answers are known to be each ray's alone only under
// packet_lanes_answer_alone: Embree's hybrid traversal chooses between packet and single-ray
// kernels by how many lanes are active, and through instances its packets answered a glTF
// scene's rays 2e-5 away from single rays, so a hit could depend on which rays share its packet
// (tiles, threads, ranks).
bool rays_decided_by_callbacks(const RenderScene& scene) {
  if (has_triangles(scene.top)) return false;
  for (const Group& prototype : scene.prototypes)
    if (has_triangles(prototype)) return false;
  return true;
}

// Whether Embree answers every lane of a packet of eight as it answers the ray alone: where the
// top scene holds every shape itself (no instance geometry: none in the scene, or every one
// inlined; no mesh in pieces, which are instances too) and each kind's packet kernels compute
// what its single-ray kernels do (packet_lanes_answer_alone: spheres, whose hits rtpro's
// callbacks decide lane by lane, and triangles stored in the leaves). With instances in packets
// a pixel of scenes/dragon_field.yaml moved by 3e-7 against single rays, its cause not found, so
// they keep single rays.
bool packet_lanes_answer_alone(const RenderScene& scene, const EmbreeScenes& built, bool compact) {
  if (!built.pieces.empty()) return false;
  for (const EmbreeScene& prototype : built.prototypes)
    if (prototype.get() != nullptr) return false;
  const auto answer_alone = [&](const Group& group) {
    for (const Geometry& geometry : group.geometries) {
      const bool alone =
          std::visit(Overloaded{[](const Instance&) { return true; },  // checked as its prototype
                                [&](const auto& shapes) { return packet_lanes_answer_alone(shapes, compact); }},
                     geometry);
      if (!alone) return false;
    }
    return true;
  };
  if (!answer_alone(scene.top)) return false;
  for (const Group& prototype : scene.prototypes)  // inlined into the top scene
    if (!answer_alone(prototype)) return false;
  return true;
}

// Embree traces a coherent stream that meets a moving instance (its motion BVH over instances)
// as packets through the prototype, whose triangle kernels round differently from a single ray's:
// the hits in a moving instance moved by an ulp against single rays (tests/backend/
// motion_traversal_test.cpp), while moving triangles and spheres answered as single rays. Rays
// with a time in such a scene go one by one.
bool has_moving_instance(const RenderScene& scene) {
  for (const Geometry& geometry : scene.top.geometries)
    if (const auto* instance = std::get_if<Instance>(&geometry); instance != nullptr && instance->moving()) return true;
  return false;
}

class EmbreeBackend final : public Backend {
 public:
  EmbreeBackend(const RenderScene& scene, const BackendOptions& options)
      : scene_(scene), device_(EmbreeDevice::get(options.threads)), packets_(rays_decided_by_callbacks(scene)),
        wide_loads_(sphere_lanes_vectorised()), timed_streams_(!has_moving_instance(scene)) {
    const EmbreeBuildSettings settings = embree_build_settings(options);
    EmbreeDevice::Session session(*device_, options.max_memory_bytes);
    const auto start = std::chrono::steady_clock::now();
    scenes_ = build_embree_scenes(session, scene, settings);
    stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_.acceleration_bytes = static_cast<std::size_t>(std::max<std::int64_t>(0, session.allocated_bytes()));
    stats_.build_peak_bytes = static_cast<std::size_t>(std::max<std::int64_t>(0, session.peak_bytes()));
    scattered_packets_ = packet_lanes_answer_alone(scene, scenes_, options.embree_compact);
  }

  // Releasing frees Embree memory; inside a session so another thread's build does not count it.
  ~EmbreeBackend() override {
    EmbreeDevice::Session session(*device_, 0);
    scenes_ = {};
  }

  std::string_view name() const override { return "embree"; }

  bool intersect(const Ray& ray, Hit& hit) const override { return intersect(ray, 0.0f, hit); }
  bool occluded(const Ray& ray) const override { return occluded(ray, 0.0f); }

  bool intersect(const Ray& ray, float time, Hit& hit) const override {
    if (!gate_.admit(ray)) return false;
    Hit closest_user_hit = no_user_hit_yet(ray);
    EmbreeIntersectContext context;
    rtcInitIntersectContext(&context.base);
    context.closest_user_hits = &closest_user_hit;
    alignas(16) RTCRayHit query;
    to_embree(ray, 0, query, time);
    rtcIntersect1(scenes_.top.get(), &context.base, &query);
    return from_embree(query, scenes_.hit_ids, hit);
  }

  // Where only spheres can be hit (packets_), every batch goes in packets of eight, camera rays
  // too: 7% faster on the demo than the coherent stream, whose regrouping costs more than it
  // gains for a handful of user-geometry primitives. Elsewhere camera rays go to Embree as a
  // stream with the coherent flag: Embree regroups them into packets, which traced camera tiles
  // 1.3–2.4× faster than one rtcIntersect1 per ray (third_party_notes/embree.md), and scattered
  // rays in packets of eight where Embree answers each lane as the ray alone
  // (packet_lanes_answer_alone), else one by one: streams of them were 1.3–2.6× slower than
  // single rays, packets 1.1–1.6× faster on the path integrator's Cornell box shadow rays
  // (benchmarks/path_bounce_benchmark.sh). Rays with a time go the same ways, each with its own
  // time.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence coherence) const override {
    intersect(rays, {}, hits, coherence);
  }

  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> result, RayCoherence coherence) const override {
    occluded(rays, {}, result, coherence);
  }

  void intersect(std::span<const Ray> rays, std::span<const float> times, std::span<Hit> hits,
                 RayCoherence coherence) const override {
    if (packets_ || (coherence == RayCoherence::kIncoherent && scattered_packets_)) {
      intersect_packets(target(), rays, times, hits);
      return;
    }
    if (coherence == RayCoherence::kIncoherent || (!times.empty() && !timed_streams_)) {
      intersect_one_by_one(target(), rays, times, hits);
      return;
    }
    intersect_stream(target(), rays, times, hits);
  }

  void occluded(std::span<const Ray> rays, std::span<const float> times, std::span<std::uint8_t> result,
                RayCoherence coherence) const override {
    if (packets_ || (coherence == RayCoherence::kIncoherent && scattered_packets_)) {
      occluded_packets(target(), rays, times, result);
      return;
    }
    if (coherence == RayCoherence::kIncoherent || (!times.empty() && !timed_streams_)) {
      occluded_one_by_one(target(), rays, times, result);
      return;
    }
    occluded_stream(target(), rays, times, result);
  }

  // Embree's triangles accept t == tfar; asking for (tnear, previous float below tfar] instead
  // gives exactly the open interval (tnear, tfar) the interface promises, for every geometry.
  bool occluded(const Ray& ray, float time) const override {
    if (!gate_.admit(ray)) return false;
    const float tfar = one_step_towards_zero(ray.tfar);
    if (!(tfar > ray.tnear)) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(16) RTCRay query;
    to_embree(ray, tfar, 0, query, time);
    rtcOccluded1(scenes_.top.get(), &context, &query);
    return query.tfar < 0.0f;
  }

  BackendStats stats() const override {
    BackendStats s = stats_;
    s.rejected_rays = gate_.rejected();
    return s;
  }

 private:
  EmbreeRayTarget target() const { return {scenes_.top.get(), gate_, wide_loads_, scenes_.hit_ids, scene_}; }

  const RenderScene& scene_;  // outlives the backend: Embree shares its arrays
  std::shared_ptr<EmbreeDevice> device_;
  // Rays go to Embree in packets of eight (rtcIntersect8, rtcOccluded8): one traversal
  // and one callback per sphere for up to eight rays, 1.18x faster on the demo than one
  // rtcIntersect1 per ray. Only for scenes without triangles (rays_decided_by_callbacks).
  bool packets_;
  bool scattered_packets_ = false;  // incoherent rays in packets too (packet_lanes_answer_alone)
  bool wide_loads_;                 // eight rays loaded at once (load_traceable_lanes needs AVX2)
  bool timed_streams_;              // coherent rays with a time go as streams too (has_moving_instance)
  EmbreeScenes scenes_;
  BackendStats stats_;
  RayGate gate_;
};

}  // namespace

std::unique_ptr<Backend> make_embree_backend(const RenderScene& scene, const BackendOptions& options) {
  return std::make_unique<EmbreeBackend>(scene, options);
}

}  // namespace rtpro
