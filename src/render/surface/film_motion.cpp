#include "film_motion.h"

#include <optional>
#include <variant>

namespace rtpro {

namespace {

// Object-space point `p` of the hit's primitive at ray time `from`, carried to ray time `to`: with
// its sphere's centre, or at the same barycentrics of its deforming triangle; still otherwise.
Vec3 carried_point(const Group& group, const Hit& hit, const Vec3& p, float from, float to) {
  const Geometry& geometry = group.geometries[hit.geom_id];
  if (const auto* set = std::get_if<SphereSet>(&geometry); set && set->moving())
    return p + (set->center_at(hit.prim_id, to) - set->center_at(hit.prim_id, from));
  if (const auto* mesh = std::get_if<TriangleMesh>(&geometry); mesh && mesh->moving()) {
    const TriangleIndices& tri = mesh->triangles[hit.prim_id];
    const float w = 1.0f - hit.u - hit.v;
    const auto at = [&](float time) {
      return mesh->vertex_at(tri.v0, time) * w + mesh->vertex_at(tri.v1, time) * hit.u +
             mesh->vertex_at(tri.v2, time) * hit.v;
    };
    return p + (at(to) - at(from));
  }
  return p;
}

}  // namespace

FilmMotion film_motion(const RenderScene& scene, const Hit& hit, float time, const Vec3& position) {
  const Shutter& shutter = scene.camera.shutter;
  if (!shutter.is_open()) return {};
  const bool instanced = hit.inst_id != kInvalidId;
  const Instance* instance = instanced ? &std::get<Instance>(scene.top.geometries[hit.inst_id]) : nullptr;
  const Group& group = instanced ? scene.prototypes[instance->prototype] : scene.top;
  const auto placement = [&](float at) -> std::optional<InstancePlacement> {
    if (!instance->moving()) return InstancePlacement{instance->object_to_world, instance->world_to_object};
    return placement_at(*instance, at);
  };
  std::optional<InstancePlacement> seen;
  if (instanced && !(seen = placement(time))) return {};
  const Vec3 object_point = instanced ? seen->world_to_object.apply_point(position) : position;
  const auto film_at = [&](float at) -> std::optional<FilmPoint> {
    Vec3 p = carried_point(group, hit, object_point, time, at);
    if (instanced) {
      const std::optional<InstancePlacement> then = placement(at);
      if (!then) return std::nullopt;
      p = then->object_to_world.apply_point(p);
    }
    return film_point(scene.camera, camera_pose_at(scene.camera, at), p);
  };
  const std::optional<FilmPoint> open = film_at(0.0f), centre = film_at(0.5f), close = film_at(1.0f);
  if (!open || !centre || !close) return {};
  const float per_frame = 2.0f / (shutter.close - shutter.open);  // each half of the shutter, in frames
  return {(close->x - centre->x) * per_frame, (close->y - centre->y) * per_frame, (centre->x - open->x) * per_frame,
          (centre->y - open->y) * per_frame};
}

}  // namespace rtpro
