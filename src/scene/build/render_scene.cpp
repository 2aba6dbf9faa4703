#include "rtpro/scene/render_scene.h"

namespace rtpro {

BBox SphereSet::sphere_bounds(std::uint32_t i) const {
  const Sphere& s = spheres[i];
  return {s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
}

std::uint32_t Group::primitive_count(std::uint32_t g) const {
  const Geometry& geometry = geometries[g];
  switch (kind_of(geometry)) {
    case GeometryKind::kSpheres: return static_cast<std::uint32_t>(std::get<SphereSet>(geometry).spheres.size());
    case GeometryKind::kTriangles: return static_cast<std::uint32_t>(std::get<TriangleMesh>(geometry).triangles.size());
    case GeometryKind::kInstance: return 1;
  }
  return 0;
}

BBox Group::primitive_bounds(std::uint32_t g, std::uint32_t prim, std::span<const BBox> prototype_bounds) const {
  const Geometry& geometry = geometries[g];
  switch (kind_of(geometry)) {
    case GeometryKind::kSpheres: return std::get<SphereSet>(geometry).sphere_bounds(prim);
    case GeometryKind::kTriangles: return std::get<TriangleMesh>(geometry).triangle_bounds(prim);
    case GeometryKind::kInstance: {
      const Instance& instance = std::get<Instance>(geometry);
      return instance.object_to_world.apply(prototype_bounds[instance.prototype]);
    }
  }
  return {};
}

BBox Group::bounds(std::span<const BBox> prototype_bounds) const {
  BBox b;
  for (std::uint32_t g = 0; g < geometries.size(); ++g) {
    const Geometry& geometry = geometries[g];
    switch (kind_of(geometry)) {
      case GeometryKind::kSpheres:
        for (std::uint32_t i = 0; i < primitive_count(g); ++i) b.extend(std::get<SphereSet>(geometry).sphere_bounds(i));
        break;
      case GeometryKind::kTriangles: b.extend(std::get<TriangleMesh>(geometry).bounds()); break;
      case GeometryKind::kInstance: b.extend(primitive_bounds(g, 0, prototype_bounds)); break;
    }
  }
  return b;
}

std::vector<BBox> RenderScene::prototype_bounds() const {
  std::vector<BBox> result;
  result.reserve(prototypes.size());
  for (const Group& prototype : prototypes) result.push_back(prototype.bounds({}));  // prototypes hold no instances
  return result;
}

}  // namespace rtpro
