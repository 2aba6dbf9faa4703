#include "curve_tolerance.h"

#include "rtpro/scene/curve_basis.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

double curve_surface_tolerance(const CurveSet& curves, std::uint32_t prim) {
  const double fraction = curves.shape == CurveShape::kRound ? kRoundCurveTolerance : kFlatCurveTolerance;
  return fraction * std::max(0.0f, bezier_segment(curves, prim).largest_radius());
}

namespace {

// Whether the segment's start (`end` 0) or end (1) is a strand's: no neighbouring segment shares it.
bool ends_a_strand(const CurveSet& curves, std::uint32_t prim, int end) {
  const std::uint32_t step = curves.basis == CurveBasis::kBezier ? 3 : 1;
  if (end == 0) return prim == 0 || curves.segments[prim - 1] + step != curves.segments[prim];
  return prim + 1 == curves.segments.size() || curves.segments[prim] + step != curves.segments[prim + 1];
}

double line_distance(const Ray& ray, const Vec3& p, double dd) {
  const Vec3 f = p - ray.org;
  const double along = double(dot(f, ray.dir)) / dd;
  const double fx = f.x - along * ray.dir.x, fy = f.y - along * ray.dir.y, fz = f.z - along * ray.dir.z;
  return std::sqrt(fx * fx + fy * fy + fz * fz);
}

}  // namespace

bool grazes_curve(const CurveSet& curves, std::uint32_t prim, const Ray& ray) {
  const BezierSegment segment = bezier_segment(curves, prim);
  const double tolerance = curve_surface_tolerance(curves, prim);
  const double dd = double(dot(ray.dir, ray.dir));
  if (!(dd > 0.0)) return false;
  // The ray's clearance from the tube at u: its distance from the axis point, across the ray, less
  // the radius there; sampled finely enough that its least value is known to well within the
  // tolerance for the smooth segments the cross-check meets. An origin inside the tube or within
  // two radii of it counts too: from inside, the native pieces' inner ends and Embree's sweep
  // differ, and both ignore hits within two radii of the origin, each measuring the radius at its
  // own hit (secondary rays start four radii away, see render/surface/surface.cpp).
  constexpr int kSamples = 256;
  double least = INFINITY;
  for (int i = 0; i <= kSamples; ++i) {
    const CurvePoint c = segment.at(float(i) / float(kSamples));
    least = std::min(least, line_distance(ray, c.position, dd) - c.radius);
    if (double(length(c.position - ray.org)) <= 3.0 * c.radius + tolerance) return true;
  }
  if (std::fabs(least) <= tolerance) return true;
  // Where flat pieces meet, the bend's outside is covered by Embree's quads alone.
  if (curves.shape == CurveShape::kFlat && curves.basis != CurveBasis::kLinear)
    for (int k = 0; k <= kFlatCurvePieces; ++k) {
      const CurvePoint c = segment.at(float(k) / float(kFlatCurvePieces));
      if (line_distance(ray, c.position, dd) <= c.radius + tolerance) return true;
    }
  // Embree leaves a cubic strand's ends open where the native pieces close them with a sphere.
  for (int end = 0; end < 2; ++end) {
    const CurvePoint c = segment.c[end == 0 ? 0 : 3];
    if (ends_a_strand(curves, prim, end) && line_distance(ray, c.position, dd) <= c.radius + tolerance) return true;
  }
  return false;
}

Ray object_ray(const RenderScene& scene, const Hit& hit, const Ray& ray, double* stretch) {
  if (stretch) *stretch = 1.0;
  if (hit.inst_id == kInvalidId) return ray;
  const auto& instance = std::get<Instance>(scene.top.geometries[hit.inst_id]);
  if (stretch)
    for (const Vec3& axis : {Vec3(1.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)})
      *stretch = std::max(*stretch, double(length(instance.object_to_world.apply_vector(axis))));
  return {instance.world_to_object.apply_point(ray.org), ray.tnear, instance.world_to_object.apply_vector(ray.dir),
          ray.tfar};
}

double curve_allowance(const RenderScene& scene, const Hit& hit) {
  const Group* group = &scene.top;
  if (hit.inst_id != kInvalidId) {
    const Instance* instance =
        hit.inst_id < scene.top.geometries.size() ? std::get_if<Instance>(&scene.top.geometries[hit.inst_id]) : nullptr;
    if (!instance || instance->prototype >= scene.prototypes.size()) return 0.0;
    group = &scene.prototypes[instance->prototype];
  }
  if (hit.geom_id >= group->geometries.size()) return 0.0;
  const auto* curves = std::get_if<CurveSet>(&group->geometries[hit.geom_id]);
  if (!curves || hit.prim_id >= curves->segments.size()) return 0.0;
  double stretch = 1.0;
  object_ray(scene, hit, Ray{}, &stretch);
  return curve_surface_tolerance(*curves, hit.prim_id) * stretch;
}

}  // namespace rtpro
