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
                                 BBox box = instance.object_to_world.apply(prototype_bounds[instance.prototype]);
                                 // Linear in time between steps: the steps' boxes hold the motion.
                                 for (const Affine& step : instance.object_to_world_steps)
                                   box.extend(step.apply(prototype_bounds[instance.prototype]));
                                 return box;
                               },
                               [&](const auto& shapes) { return primitive_bounds_of(shapes, prim); }},
                    geometries[g]);
}

std::uint32_t Group::motion_step_count(std::uint32_t g) const {
  return std::visit(Overloaded{[](const Instance& instance) {
                                 return static_cast<std::uint32_t>(instance.object_to_world_steps.size());
                               },
                               [](const auto& shapes) { return motion_step_count_of(shapes); }},
                    geometries[g]);
}

BBox Group::primitive_bounds_at_step(std::uint32_t g, std::uint32_t prim, std::uint32_t step,
                                     std::span<const BBox> prototype_bounds) const {
  return std::visit(
      Overloaded{[&](const Instance& instance) {
                   // A point of the prototype moves linearly between the matrices'
                   // steps, so its placed box does too.
                   return instance.object_to_world_steps[step].apply(prototype_bounds[instance.prototype]);
                 },
                 [&](const auto& shapes) { return rtpro::primitive_bounds_at_step(shapes, prim, step); }},
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

std::optional<InstancePlacement> placement_at(const Instance& instance, float time) {
  const Affine to_world = value_at_time<Affine>(instance.object_to_world_steps, time);
  const std::optional<Affine> to_object = inverse(to_world);
  if (!to_object) return std::nullopt;
  return InstancePlacement{to_world, *to_object};
}

std::vector<BBox> RenderScene::prototype_bounds() const {
  std::vector<BBox> result;
  result.reserve(prototypes.size());
  for (const Group& prototype : prototypes) result.push_back(prototype.bounds({}));  // prototypes hold no instances
  return result;
}

}  // namespace rtpro
