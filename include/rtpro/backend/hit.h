#pragma once
// The compact hit record every backend returns. Everything after the hit (surface point,
// normals, material) is computed by shared code from these ids and barycentrics.
#include <cstdint>

namespace rtpro {

inline constexpr std::uint32_t kInvalidId = ~0u;

struct Hit {
  float t = 0.0f;
  float u = 0.0f, v = 0.0f;            // triangle barycentrics; 0 for spheres
  std::uint32_t geom_id = kInvalidId;  // geometry in the top group, or in the prototype if instanced
  std::uint32_t prim_id = kInvalidId;  // sphere or triangle within that geometry
  std::uint32_t inst_id = kInvalidId;  // top-group geometry id of the instance, or kInvalidId

  bool valid() const { return geom_id != kInvalidId; }
};

// The tie rule both backends apply when two primitives report exactly the same distance: the
// lower (instance, geometry, primitive) triple wins, so the answer never depends on traversal order.
inline bool is_closer(float t, std::uint32_t inst, std::uint32_t geom, std::uint32_t prim, const Hit& best,
                      float best_t) {
  if (t != best_t) return t < best_t;
  if (inst != best.inst_id) return inst < best.inst_id;
  if (geom != best.geom_id) return geom < best.geom_id;
  return prim < best.prim_id;
}

}  // namespace rtpro
