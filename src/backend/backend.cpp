#include "rtpro/backend/backend.h"

#include "embree_backend.h"
#include "native_backend.h"
#include "rtpro/core/error.h"

namespace rtpro {

void Backend::intersect(std::span<const Ray> rays, std::span<Hit> hits, RayCoherence) const {
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (!intersect(rays[i], hits[i])) hits[i] = Hit{};
}

void Backend::occluded(std::span<const Ray> rays, std::span<std::uint8_t> result, RayCoherence) const {
  for (std::size_t i = 0; i < rays.size(); ++i) result[i] = occluded(rays[i]) ? 1 : 0;
}

// Rays with times go one by one: only scenes with an open shutter have them, and a ray's answer
// then never depends on which rays share its batch.
void Backend::intersect(std::span<const Ray> rays, std::span<const float> times, std::span<Hit> hits,
                        RayCoherence coherence) const {
  if (times.empty()) return intersect(rays, hits, coherence);
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (!intersect(rays[i], times[i], hits[i])) hits[i] = Hit{};
}

void Backend::occluded(std::span<const Ray> rays, std::span<const float> times, std::span<std::uint8_t> result,
                       RayCoherence coherence) const {
  if (times.empty()) return occluded(rays, result, coherence);
  for (std::size_t i = 0; i < rays.size(); ++i) result[i] = occluded(rays[i], times[i]) ? 1 : 0;
}

std::unique_ptr<Backend> make_backend(BackendKind kind, const RenderScene& scene, const BackendOptions& options) {
  switch (kind) {
    case BackendKind::kNative: return make_native_backend(scene, options);
    case BackendKind::kEmbree: return make_embree_backend(scene, options);
  }
  throw RuntimeError("unknown backend");
}

BackendKind parse_backend_kind(std::string_view name) {
  if (name == "native") return BackendKind::kNative;
  if (name == "embree") return BackendKind::kEmbree;
  throw InputError("unknown backend '" + std::string(name) + "': expected 'embree' or 'native'");
}

std::string_view backend_name(BackendKind kind) {
  switch (kind) {
    case BackendKind::kNative: return "native";
    case BackendKind::kEmbree: return "embree";
  }
  return "unknown";  // unreachable: the switch covers every backend
}

}  // namespace rtpro
