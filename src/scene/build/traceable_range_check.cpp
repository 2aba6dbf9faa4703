#include "traceable_range_check.h"

#include "rtpro/core/overloaded.h"
#include "rtpro/core/ray.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <variant>

namespace rtpro {

double largest_magnitude(const Vec3& v) {
  if (!is_finite(v)) return INFINITY;
  return std::max({std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z))});
}

namespace {

double largest_magnitude(const BBox& box) {
  return box.empty() ? 0.0 : std::max(largest_magnitude(box.lower), largest_magnitude(box.upper));
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

// Within range as within_traceable_range() has it (strictly below the limit), which is what
// the Embree scene builder and the ray gate enforce.
bool in_range(double magnitude) { return magnitude < double(kMaxTraceableMagnitude); }

// How far an instance's world-to-object transform can carry a ray: the largest row sum of its
// linear part scales directions and origins, the translation adds to origins.
struct Stretch {
  double linear = 0.0;
  double translation = 0.0;
};

Stretch stretch_of(const Affine& world_to_object) {
  Stretch s;
  for (const auto& row : world_to_object.m) {
    s.linear = std::max(s.linear, std::fabs(double(row[0])) + std::fabs(double(row[1])) + std::fabs(double(row[2])));
    s.translation = std::max(s.translation, std::fabs(double(row[3])));
  }
  return s;
}

BBox geometry_bounds(const Group& group, std::uint32_t g, std::span<const BBox> prototype_bounds) {
  return std::visit(Overloaded{[&](const Instance&) { return group.primitive_bounds(g, 0, prototype_bounds); },
                               [](const auto& shapes) { return bounds_of(shapes); }},
                    group.geometries[g]);
}

}  // namespace

void check_traceable_range(const RenderScene& scene, std::span<const GeometryOrigin> origins, const CameraDesc& camera,
                           const std::vector<LightDesc>& lights) {
  const std::vector<BBox> prototype_bounds = scene.prototype_bounds();
  const std::string limit = number(kMaxTraceableMagnitude);

  // Where rays can start (the camera, any surface) and what they can aim at (a point or spot light).
  double extent = largest_magnitude(camera.position);
  for (const LightDesc& light : lights)
    extent = std::max(extent, std::visit([](const auto& l) { return reach_from_origin(l); }, light));

  for (std::uint32_t g = 0; g < scene.top.geometries.size(); ++g) {
    const Geometry& geometry = scene.top.geometries[g];
    const double reach = largest_magnitude(geometry_bounds(scene.top, g, prototype_bounds));
    if (!in_range(reach)) {
      const bool instance = kind_of(geometry) == GeometryKind::kInstance;
      throw geometry_error(
          origins[g], std::string(instance ? "this instance places geometry" : "this geometry reaches") +
                          " as far as " + number(reach) + " from the origin; coordinates must stay within ±" + limit +
                          " (after all transforms) for the ray tracing backends");
    }
    extent = std::max(extent, reach);
  }

  // Directions: unit for camera and mirror rays, up to twice the extent for a shadow ray.
  const double direction = std::max(1.0, 2.0 * extent);
  for (std::uint32_t g = 0; g < scene.top.geometries.size(); ++g) {
    const auto* instance = std::get_if<Instance>(&scene.top.geometries[g]);
    if (!instance) continue;
    const Stretch s = stretch_of(instance->world_to_object);
    const double origin_reach = s.linear * extent + s.translation;
    const double direction_reach = s.linear * direction;
    if (!in_range(origin_reach) || !in_range(direction_reach) || !std::isfinite(s.linear)) {
      throw geometry_error(origins[g],
                           "this instance's transform (combined with its parents) shrinks its object so far "
                           "that rays entering it reach " +
                               number(std::max(origin_reach, direction_reach)) + " in object space, beyond the ±" +
                               limit +
                               " the ray tracing backends support; use a larger scale (the largest inverse "
                               "scale factor is " +
                               number(s.linear) + ")");
    }
  }
}

}  // namespace rtpro
