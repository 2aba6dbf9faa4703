#pragma once
// The backend interface: the only thing that differs between `native` and `embree`. A backend
// is built once from an immutable render scene and answers "closest hit" and "any hit".
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace rtpro {

struct BackendStats {
  double build_seconds = 0.0;
  std::size_t acceleration_bytes = 0;  // BVH and backend-side copies; not the shared mesh arrays
  std::size_t build_peak_bytes = 0;    // the most the build held at once, its temporaries too (embree)
  std::uint64_t rejected_rays = 0;     // rays refused by is_traceable()
};

enum class BackendKind { kNative, kEmbree };

// A hint for batches: camera rays of a tile travel together; secondary rays scatter.
enum class RayCoherence { kCoherent, kIncoherent };

// Embree's BVH build quality (RTC_BUILD_QUALITY_*): faster builds or faster traversal.
enum class EmbreeBuildQuality { kLow, kMedium, kHigh };

struct BackendOptions {
  int threads = 0;  // 0: all cores
  EmbreeBuildQuality embree_quality = EmbreeBuildQuality::kMedium;
  bool embree_robust = true;         // RTC_SCENE_FLAG_ROBUST
  bool embree_compact = false;       // smaller, slower BVH
  std::size_t max_memory_bytes = 0;  // 0: no limit
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string_view name() const = 0;

  // Closest hit in (ray.tnear, ray.tfar]; false when nothing is hit. Untraceable rays miss and
  // are counted as rejected.
  virtual bool intersect(const Ray& ray, Hit& hit) const = 0;
  // Whether anything lies in (ray.tnear, ray.tfar).
  virtual bool occluded(const Ray& ray) const = 0;

  // Batches: the renderer traces every ray kind in batches (a batch of camera rays, then all their
  // shadow rays, then all reflection rays, ...), so a backend can trace a batch as it measures
  // fastest (packets, streams, SIMD). The answers are exactly those of the single-ray calls.
  // hits[i] is invalid (Hit::valid() false) on a miss; occluded[i] is 1 or 0.
  virtual void intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence coherence) const;
  virtual void occluded(std::span<const Ray> rays, std::span<std::uint8_t> occluded, RayCoherence coherence) const;

  // Rays at a time of the shutter (scene/motion.h: 0 at open, 1 at close), where the scene's
  // moving shapes are interpolated. `times` empty: every ray at the frame's time, the calls above.
  // By default the time is ignored (a backend of a scene where nothing moves).
  virtual bool intersect(const Ray& ray, float /*time*/, Hit& hit) const { return intersect(ray, hit); }
  virtual bool occluded(const Ray& ray, float /*time*/) const { return occluded(ray); }
  // By default one by one through the calls above.
  virtual void intersect(std::span<const Ray> rays, std::span<const float> times, std::span<Hit> hits,
                         RayCoherence coherence) const;
  virtual void occluded(std::span<const Ray> rays, std::span<const float> times, std::span<std::uint8_t> occluded,
                        RayCoherence coherence) const;

  virtual BackendStats stats() const = 0;
};

// Builds the chosen backend for `scene`, which must outlive it.
std::unique_ptr<Backend> make_backend(BackendKind kind, const RenderScene& scene, const BackendOptions& options);
BackendKind parse_backend_kind(std::string_view name);  // throws InputError
std::string_view backend_name(BackendKind kind);

}  // namespace rtpro
