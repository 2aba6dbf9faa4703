#pragma once
// Light linking as both integrators apply it (scene/light_links.h): the link group of the object
// a hit is on, and shadow rays that pass the objects that do not cast their light's shadows.
#include "rtpro/backend/backend.h"
#include "rtpro/backend/hit.h"
#include "rtpro/scene/light_links.h"

#include <cstdint>
#include <span>

namespace rtpro {

inline std::uint32_t link_group_of(const LightLinks& links, const Hit& hit) {
  return links.group_of(hit.inst_id != kInvalidId ? hit.inst_id : hit.geom_id, hit.prim_id);
}

// occluded[i]: whether rays[i] is blocked before its end by an object that casts the shadows of
// light light_of_ray[i] (a scene light's index; kInvalidId for light every object blocks: emissive
// surfaces, the environment). An object that does not cast that light's shadows is transparent to
// the ray, and only to it. Rays of lights nothing lets through take the backend's occlusion query
// alone; the others, where that query finds something, are followed hit by hit.
// `times`: each ray's time in the shutter (scene/motion.h), or empty.
void occluded_with_shadow_linking(const Backend& backend, const LightLinks& links, std::span<const Ray> rays,
                                  std::span<const float> times, std::span<const std::uint32_t> light_of_ray,
                                  std::span<std::uint8_t> occluded, RayCoherence coherence);

}  // namespace rtpro
