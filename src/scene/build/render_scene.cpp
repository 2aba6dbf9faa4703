#include "rtpro/scene/render_scene.h"

#include "rtpro/core/overloaded.h"

#include <variant>

namespace rtpro {

// Each kind of shape counts and bounds itself (scene/sphere_geometry.h and its neighbours); an
// instance is one primitive, bounded by its placed prototype.
std::uint32_t Group::primitive_count(std::uint32_t g) const {
  return std::visit(Overloaded{[](const Instance&) { return std::uint32_t{1}; },
                               [](const auto& shapes) { return primitive_count_of(shapes); }},
                    geometries[g]);
}

BBox Group::primitive_bounds(std::uint32_t g, std::uint32_t prim, std::span<const BBox> prototype_bounds) const {
  return std::visit(Overloaded{[&](const Instance& instance) {
                                 return instance.object_to_world.apply(prototype_bounds[instance.prototype]);
                               },
                               [&](const auto& shapes) { return primitive_bounds_of(shapes, prim); }},
                    geometries[g]);
}

BBox Group::bounds(std::span<const BBox> prototype_bounds) const {
  BBox b;
  for (std::uint32_t g = 0; g < geometries.size(); ++g) {
    std::visit(Overloaded{[&](const Instance&) { b.extend(primitive_bounds(g, 0, prototype_bounds)); },
                          [&](const auto& shapes) { b.extend(bounds_of(shapes)); }},
               geometries[g]);
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
