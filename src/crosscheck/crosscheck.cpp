#include "rtpro/crosscheck/crosscheck.h"

#include "curve_tolerance.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/core/random.h"
#include "rtpro/render/camera.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

namespace rtpro {

namespace {

// Tolerances, relative to the magnitude of the coordinates involved (origin, hit point, distance
// travelled): float rounding errors scale with those, not with t, which is tiny for an origin next
// to a surface, and barycentrics, which swing widely on small or grazed triangles.
constexpr double kPointTolerance = 1e-5;  // hit points of the same primitive
constexpr double kEdgeZone = 1e-5;        // "at an edge": that close to a triangle's edge
constexpr double kGrazing = 1e-5;         // |line distance − radius| of a tangential sphere hit
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Occlusion is asked on up to three segments: the whole ray, and (when the reference hits) just
// short of and just past the reference hit.
constexpr int kOcclusionSegments = 3;

struct TracedRay {
  Ray ray;
  float time = 0.0f;  // in the shutter (scene/motion.h), random while it is open
  bool reference_found = false, candidate_found = false;
  Hit reference, candidate;
  int segments = 0;
  std::array<bool, kOcclusionSegments> reference_occluded{}, candidate_occluded{};
};

float unit_random(std::uint64_t seed, std::uint64_t ray, std::uint64_t dimension) {
  return to_unit_float(hash_combine(hash_combine(seed, ray), dimension));
}

Ray random_camera_ray(const RenderCamera& camera, std::uint64_t seed, std::size_t i) {
  return camera_ray(camera, unit_random(seed, i, 0) * static_cast<float>(camera.width),
                    unit_random(seed, i, 1) * static_cast<float>(camera.height),
                    {unit_random(seed, i, 2), unit_random(seed, i, 3)});
}

double magnitude(const Vec3& v);

// Origin uniform in the scene's bounds, direction uniform on the sphere, starting the point
// tolerance of the origin's magnitude along. A flat scene's bounds put every origin in its
// surface's plane, and whether a ray hits the surface it starts on is rounding: Embree's triangles
// report t = ±0 there, which rtpro's interval (tnear, tfar] leaves out. That close the checker
// cannot tell two points apart anyway; beyond it both backends answer the same question.
Ray random_ray(const BBox& bounds, std::uint64_t seed, std::size_t i) {
  const Vec3 extent = bounds.extent();
  Ray ray;
  ray.org = bounds.lower + Vec3(extent.x * unit_random(seed, i, 0), extent.y * unit_random(seed, i, 1),
                                extent.z * unit_random(seed, i, 2));
  const double z = 1.0 - 2.0 * unit_random(seed, i, 3);
  const double phi = 2.0 * std::numbers::pi * unit_random(seed, i, 4);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  ray.dir = {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z)};
  ray.tnear = static_cast<float>(kPointTolerance * magnitude(ray.org));  // dir is unit length
  return ray;
}

double error_scale(const Ray& ray, float t);

// How far before and after the reference hit the occlusion segments end. It must clear the
// tolerance within which the two backends may place the same hit (kPointTolerance of the error
// scale), or an accepted difference in t flips the answer for a segment ending between the two
// hits — which happened for a ray 0.0014 from an instanced triangle, where 0.1% of t was 1.4e-6
// and the backends' hits 1.7e-6 apart.
float segment_margin(const Ray& ray, float t) {
  const double tolerance = 2.0 * kPointTolerance * error_scale(ray, t) / std::max(magnitude(ray.dir), 1e-30);
  return static_cast<float>(std::max(tolerance, 0.001 * double(t)));
}

void trace(const RenderScene& scene, const Backend& reference, const Backend& candidate, TracedRay& traced) {
  const Ray& ray = traced.ray;
  traced.reference_found = reference.intersect(ray, traced.time, traced.reference);
  traced.candidate_found = candidate.intersect(ray, traced.time, traced.candidate);
  std::array<float, kOcclusionSegments> ends{kInfinity};
  traced.segments = 1;
  if (traced.reference_found) {
    // Beyond where the other backend may put the same curve hit, too.
    const float margin = std::max(segment_margin(ray, traced.reference.t),
                                  float(2.0 * curve_allowance(scene, traced.reference) / magnitude(ray.dir)));
    const float before = traced.reference.t - margin;
    if (before > ray.tnear) ends[traced.segments++] = before;
    ends[traced.segments++] = traced.reference.t + margin;
  }
  for (int s = 0; s < traced.segments; ++s) {
    Ray segment = ray;
    segment.tfar = ends[s];
    traced.reference_occluded[s] = reference.occluded(segment, traced.time);
    traced.candidate_occluded[s] = candidate.occluded(segment, traced.time);
  }
}

// The geometry a hit names, or null when its ids do not exist in the scene.
const Geometry* geometry_of(const RenderScene& scene, const Hit& hit) {
  const Group* group = &scene.top;
  if (hit.inst_id != kInvalidId) {
    if (hit.inst_id >= scene.top.geometries.size()) return nullptr;
    const auto* instance = std::get_if<Instance>(&scene.top.geometries[hit.inst_id]);
    if (!instance || instance->prototype >= scene.prototypes.size()) return nullptr;
    group = &scene.prototypes[instance->prototype];
  }
  if (hit.geom_id >= group->geometries.size()) return nullptr;
  const Geometry* geometry = &group->geometries[hit.geom_id];
  return hit.prim_id < group->primitive_count(hit.geom_id) ? geometry : nullptr;
}

bool is_top_level_sphere(const RenderScene& scene, const Hit& hit) {
  const Geometry* geometry = geometry_of(scene, hit);
  return geometry && hit.inst_id == kInvalidId && kind_of(*geometry) == GeometryKind::kSpheres;
}

bool same_primitive(const Hit& a, const Hit& b) {
  return a.inst_id == b.inst_id && a.geom_id == b.geom_id && a.prim_id == b.prim_id;
}

bool bit_identical(const Hit& a, const Hit& b) {
  return same_primitive(a, b) && std::bit_cast<std::uint32_t>(a.t) == std::bit_cast<std::uint32_t>(b.t) &&
         std::bit_cast<std::uint32_t>(a.u) == std::bit_cast<std::uint32_t>(b.u) &&
         std::bit_cast<std::uint32_t>(a.v) == std::bit_cast<std::uint32_t>(b.v);
}

double magnitude(const Vec3& v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); }

double error_scale(const Ray& ray, float t) {
  return std::max({std::fabs(double(t)) * magnitude(ray.dir), magnitude(ray.org), magnitude(ray.at(t)), 1e-30});
}

// How far apart the two hit points lie along the ray, relative to the error scale.
double relative_t_error(const Ray& ray, float a, float b) {
  const float far_t = std::max(std::fabs(a), std::fabs(b));
  return std::fabs(double(a) - double(b)) * magnitude(ray.dir) / error_scale(ray, far_t);
}

struct WorldTriangle {
  Vec3 p0, p1, p2;
  Vec3 at(float u, float v) const { return p0 * (1.0f - u - v) + p1 * u + p2 * v; }
};

WorldTriangle world_triangle(const RenderScene& scene, const Hit& hit) {
  const auto& mesh = std::get<TriangleMesh>(*geometry_of(scene, hit));
  const TriangleIndices& tri = mesh.triangles[hit.prim_id];
  WorldTriangle world{mesh.vertex(tri.v0), mesh.vertex(tri.v1), mesh.vertex(tri.v2)};
  if (hit.inst_id != kInvalidId) {
    const Affine& placement = std::get<Instance>(scene.top.geometries[hit.inst_id]).object_to_world;
    world = {placement.apply_point(world.p0), placement.apply_point(world.p1), placement.apply_point(world.p2)};
  }
  return world;
}

// Distance from the hit point to the triangle's nearest edge: each barycentric times the height
// over its opposite edge.
double edge_distance(const WorldTriangle& tri, float u, float v) {
  const double twice_area = magnitude(cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
  const auto height = [&](const Vec3& a, const Vec3& b) {
    const double base = magnitude(b - a);
    return base > 0.0 ? twice_area / base : 0.0;
  };
  return std::min(
      {(1.0 - u - v) * height(tri.p1, tri.p2), double(u) * height(tri.p2, tri.p0), double(v) * height(tri.p0, tri.p1)});
}

// Whether the ray passes an instanced sphere so nearly tangentially that the two backends'
// different object-space rays may disagree about hitting it at all.
bool grazes(const Instance& instance, const Sphere& sphere, const Ray& ray) {
  const Vec3 org = instance.world_to_object.apply_point(ray.org);
  const Vec3 dir = instance.world_to_object.apply_vector(ray.dir);
  const double f[3] = {double(org.x) - sphere.center.x, double(org.y) - sphere.center.y,
                       double(org.z) - sphere.center.z};
  const double d[3] = {dir.x, dir.y, dir.z};
  const double s = (f[0] * d[0] + f[1] * d[1] + f[2] * d[2]) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  double line2 = 0.0, f2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    line2 += (f[a] - s * d[a]) * (f[a] - s * d[a]);
    f2 += f[a] * f[a];
  }
  return std::fabs(std::sqrt(line2) - sphere.radius) <= kGrazing * (sphere.radius + std::sqrt(f2));
}

// A hit the other backend may legitimately have missed by rounding. Top-level spheres are
// bit-identical in both backends, so never borderline; a hit names the geometry inside an
// instance, never the instance itself.
bool is_borderline(const RenderScene& scene, const Ray& ray, const Hit& hit) {
  const Geometry& geometry = *geometry_of(scene, hit);
  switch (kind_of(geometry)) {
    case GeometryKind::kTriangles:
      return edge_distance(world_triangle(scene, hit), hit.u, hit.v) <= kEdgeZone * error_scale(ray, hit.t);
    case GeometryKind::kSpheres: {
      if (hit.inst_id == kInvalidId) return false;
      const auto& instance = std::get<Instance>(scene.top.geometries[hit.inst_id]);
      return grazes(instance, std::get<SphereSet>(geometry).spheres[hit.prim_id], ray);
    }
    case GeometryKind::kCurves:
      return grazes_curve(std::get<CurveSet>(geometry), hit.prim_id, object_ray(scene, hit, ray));
    case GeometryKind::kInstance: return false;
  }
  return false;
}

// How far apart the two backends' points on the same primitive lie, relative to the error scale:
// a triangle's barycentric points; a sphere hit carries no surface coordinates to compare.
double surface_error(const RenderScene& scene, const TracedRay& traced) {
  const Hit& a = traced.reference;
  const Hit& b = traced.candidate;
  switch (kind_of(*geometry_of(scene, a))) {
    case GeometryKind::kTriangles: {
      const WorldTriangle tri = world_triangle(scene, a);
      return magnitude(tri.at(a.u, a.v) - tri.at(b.u, b.v)) / error_scale(traced.ray, a.t);
    }
    case GeometryKind::kSpheres:
    case GeometryKind::kCurves:  // no surface coordinates to compare: the backends' u differ by design
    case GeometryKind::kInstance: return 0.0;
  }
  return 0.0;
}

// The allowance for surface_error. Both backends find the point where the ray meets the
// triangle's plane; an error ε across the plane moves that point ε / |cos θ| along it, so a ray
// grazing a triangle (a mesh's silhouette) may put the two barycentric points far further apart
// than the distances differ. The cosine is floored at 0.01: a hundredfold allowance at most.
double surface_tolerance(const RenderScene& scene, const TracedRay& traced) {
  const Hit& a = traced.reference;
  switch (kind_of(*geometry_of(scene, a))) {
    case GeometryKind::kTriangles: {
      const WorldTriangle tri = world_triangle(scene, a);
      const Vec3 normal = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
      const double normal_length = magnitude(normal), dir_length = magnitude(traced.ray.dir);
      if (!(normal_length > 0.0) || !(dir_length > 0.0)) return kPointTolerance;
      const double cosine = std::fabs(double(dot(normal, traced.ray.dir))) / (normal_length * dir_length);
      return kPointTolerance / std::max(cosine, 0.01);
    }
    case GeometryKind::kSpheres:
    case GeometryKind::kCurves:
    case GeometryKind::kInstance: return kPointTolerance;
  }
  return kPointTolerance;
}

void classify_same_primitive(const RenderScene& scene, const TracedRay& traced, CrosscheckCase& c) {
  const Hit& a = traced.reference;
  const Hit& b = traced.candidate;
  c.t_error = relative_t_error(traced.ray, a.t, b.t);
  c.surface_error = surface_error(scene, traced);
  const double t_tolerance = kPointTolerance + curve_allowance(scene, a) / error_scale(traced.ray, a.t);
  if (bit_identical(a, b)) {
    c.agreement = Agreement::kIdentical;
  } else if (is_top_level_sphere(scene, a)) {
    c.agreement = Agreement::kMismatch;
    c.note = "top-level sphere hit is not bit-identical";
  } else if (c.t_error <= t_tolerance && c.surface_error <= surface_tolerance(scene, traced)) {
    c.agreement = Agreement::kWithinTolerance;
  } else if (curve_allowance(scene, a) > 0.0 && is_borderline(scene, traced.ray, a)) {
    c.agreement = Agreement::kAmbiguous;  // a fibre's silhouette or open end: the surfaces differ there
    c.note = "the same curve segment hit at its silhouette, an end or from inside";
  } else {
    c.agreement = Agreement::kMismatch;
    c.note = c.t_error > t_tolerance ? "distance differs beyond tolerance" : "barycentrics differ beyond tolerance";
  }
}

void classify_different_primitives(const RenderScene& scene, const TracedRay& traced, CrosscheckCase& c) {
  const bool both = traced.reference_found && traced.candidate_found;
  const bool reference_closer =
      traced.reference_found && (!traced.candidate_found || traced.reference.t <= traced.candidate.t);
  const Hit& closer = reference_closer ? traced.reference : traced.candidate;
  const char* closer_side = reference_closer         ? traced.candidate_found ? "reference" : "only the reference"
                            : traced.reference_found ? "candidate"
                                                     : "only the candidate";
  const bool both_top_spheres =
      both && is_top_level_sphere(scene, traced.reference) && is_top_level_sphere(scene, traced.candidate);
  if (both) c.t_error = relative_t_error(traced.ray, traced.reference.t, traced.candidate.t);
  const double allowance =
      both ? std::max(curve_allowance(scene, traced.reference), curve_allowance(scene, traced.candidate)) : 0.0;

  if (both && !both_top_spheres && c.t_error <= kPointTolerance + allowance / error_scale(traced.ray, closer.t)) {
    c.agreement = Agreement::kAmbiguous;
    c.note = "different primitives at the same distance (shared edge or touching surfaces)";
  } else if (!both_top_spheres && is_borderline(scene, traced.ray, closer)) {
    c.agreement = Agreement::kAmbiguous;
    c.note = std::string(closer_side) + " hits a primitive at its edge or tangentially";
  } else {
    c.agreement = Agreement::kMismatch;
    c.note = std::string(closer_side) + " hits a primitive the other backend misses";
  }
}

CrosscheckCase classify(const RenderScene& scene, const TracedRay& traced, std::size_t index, bool camera) {
  CrosscheckCase c;
  c.index = index;
  c.camera_ray = camera;
  c.ray = traced.ray;
  c.reference_found = traced.reference_found;
  c.candidate_found = traced.candidate_found;
  c.reference = traced.reference;
  c.candidate = traced.candidate;

  const bool unknown_ids = (traced.reference_found && !geometry_of(scene, traced.reference)) ||
                           (traced.candidate_found && !geometry_of(scene, traced.candidate));
  if (unknown_ids) {
    c.agreement = Agreement::kMismatch;
    c.note = "a hit names a primitive that does not exist";
  } else if (!traced.reference_found && !traced.candidate_found) {
    c.agreement = Agreement::kIdentical;
  } else if (traced.reference_found && traced.candidate_found && same_primitive(traced.reference, traced.candidate)) {
    classify_same_primitive(scene, traced, c);
  } else {
    classify_different_primitives(scene, traced, c);
  }

  for (int s = 0; s < traced.segments; ++s)
    c.occlusion_differs |= traced.reference_occluded[s] != traced.candidate_occluded[s];
  return c;
}

// Mismatches first, then the largest distance errors; ties by ray number for a stable report.
bool worse(const CrosscheckCase& a, const CrosscheckCase& b) {
  const auto rank = [](const CrosscheckCase& c) {
    if (c.agreement == Agreement::kMismatch) return 0;
    return c.occlusion_differs && c.agreement != Agreement::kAmbiguous ? 1 : 2;
  };
  if (rank(a) != rank(b)) return rank(a) < rank(b);
  if (a.t_error != b.t_error) return a.t_error > b.t_error;
  return a.index < b.index;
}

void tally(const RenderScene& scene, CrosscheckCase c, int occlusion_queries, std::size_t worst_cases,
           CrosscheckReport& report, std::vector<CrosscheckCase>& notable) {
  switch (c.agreement) {
    case Agreement::kIdentical: ++report.identical; break;
    case Agreement::kWithinTolerance: ++report.within_tolerance; break;
    case Agreement::kAmbiguous: ++report.ambiguous; break;
    case Agreement::kMismatch: ++report.mismatches; break;
  }
  report.occlusion_queries += static_cast<std::size_t>(occlusion_queries);
  // An ambiguous closest hit makes the occlusion answers just as ambiguous.
  if (c.occlusion_differs && c.agreement != Agreement::kAmbiguous) ++report.occlusion_mismatches;
  if (c.reference_found && is_top_level_sphere(scene, c.reference)) ++report.top_level_sphere_hits;
  if (c.agreement == Agreement::kIdentical || c.agreement == Agreement::kWithinTolerance) {
    report.max_t_error = std::max(report.max_t_error, c.t_error);
    report.max_surface_error = std::max(report.max_surface_error, c.surface_error);
  }
  if (c.agreement == Agreement::kIdentical && !c.occlusion_differs) return;
  notable.push_back(std::move(c));
  if (notable.size() >= 4 * worst_cases + 64) {  // keep memory bounded on bad runs
    std::sort(notable.begin(), notable.end(), worse);
    notable.resize(worst_cases);
  }
}

}  // namespace

CrosscheckReport crosscheck(const RenderScene& scene, const Backend& reference, const Backend& candidate,
                            const CrosscheckOptions& options) {
  const std::size_t camera_rays = options.rays / 2;
  BBox bounds = scene.bounds();
  if (bounds.empty()) bounds = {Vec3(-1.0f), Vec3(1.0f)};

  CrosscheckReport report;
  report.reference_name = reference.name();
  report.candidate_name = candidate.name();
  report.rays = options.rays;
  std::vector<CrosscheckCase> notable;

  // Traced in parallel a block at a time, classified in ray order: memory stays bounded and the
  // report does not depend on scheduling.
  constexpr std::size_t kBlock = 1 << 16;
  std::vector<TracedRay> traced(std::min(options.rays, kBlock));
  for (std::size_t first = 0; first < options.rays; first += kBlock) {
    const std::size_t count = std::min(kBlock, options.rays - first);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 256), [&](const auto& range) {
      set_tracing_fp_mode();
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const std::size_t i = first + k;
        traced[k] = TracedRay{};
        traced[k].ray =
            i < camera_rays ? random_camera_ray(scene.camera, options.seed, i) : random_ray(bounds, options.seed, i);
        // Moving shapes are compared where each ray's time puts them.
        if (scene.camera.shutter.is_open()) traced[k].time = unit_random(options.seed, i, 8);
        trace(scene, reference, candidate, traced[k]);
      }
    });
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = first + k;
      tally(scene, classify(scene, traced[k], i, i < camera_rays), traced[k].segments, options.worst_cases, report,
            notable);
    }
  }
  std::sort(notable.begin(), notable.end(), worse);
  if (notable.size() > options.worst_cases) notable.resize(options.worst_cases);
  report.worst = std::move(notable);
  return report;
}

}  // namespace rtpro
