#pragma once
// Cross-checking two backends on the same scene — the point of having two. Rays (camera rays
// through the scene camera, plus random rays from inside the scene bounds, starting just past
// their origin) go to both; their closest hits and occlusion answers are compared under rules that
// say how far they may differ:
//
// - Top-level spheres: both backends call the same intersect_sphere with the same floats, so
//   the distance bits and ids must be identical.
// - Triangles and anything instanced: each backend rounds differently (Embree's own triangle
//   kernels and its own inverse of the instance transform), so the hit points — along the ray,
//   and where the barycentrics put them on the triangle — may lie apart by 1e-5 of the magnitude
//   of the coordinates involved (origin, hit point, distance travelled). Relative to t instead,
//   an origin next to a surface would fail on rounding noise.
// - Different primitives are allowed only where the choice is genuinely ambiguous: hits at equal
//   distance within that tolerance (a shared edge, a sphere touching a plane), or a closer hit
//   the other backend could have missed by rounding (a triangle hit within 1e-5 of the same
//   scale from its edge, an instanced sphere hit tangentially). Anything else is a mismatch.
#include "rtpro/backend/backend.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

struct CrosscheckOptions {
  std::size_t rays = 100000;  // half camera rays, half random rays
  std::uint64_t seed = 1;
  std::size_t worst_cases = 10;
};

enum class Agreement {
  kIdentical,        // same ids and bit-identical t, u, v (or both miss)
  kWithinTolerance,  // same primitive, t and barycentrics within tolerance
  kAmbiguous,        // different primitive where the rules allow it
  kMismatch,
};

struct CrosscheckCase {
  std::size_t index = 0;  // ray number; camera rays come first
  bool camera_ray = false;
  Ray ray;
  bool reference_found = false, candidate_found = false;
  Hit reference, candidate;
  bool occlusion_differs = false;
  Agreement agreement = Agreement::kIdentical;
  double t_error = 0.0;        // hit-point distance relative to the coordinates' magnitude
  double surface_error = 0.0;  // distance between the barycentric points, relative likewise
  std::string note;            // why the case was classified as it was
};

struct CrosscheckReport {
  std::string reference_name, candidate_name;
  std::size_t rays = 0;
  std::size_t identical = 0, within_tolerance = 0, ambiguous = 0, mismatches = 0;
  std::size_t top_level_sphere_hits = 0;  // closest hits on top-level spheres (reference side)
  std::size_t occlusion_queries = 0, occlusion_mismatches = 0;
  double max_t_error = 0.0, max_surface_error = 0.0;  // over same-primitive hits
  std::vector<CrosscheckCase> worst;                  // mismatches first, then the largest errors

  bool passed() const { return mismatches == 0 && occlusion_mismatches == 0; }
};

// Traces the same rays through both backends (built over `scene`) and classifies every ray.
// Deterministic for a given seed, whatever the thread count.
CrosscheckReport crosscheck(const RenderScene& scene, const Backend& reference, const Backend& candidate,
                            const CrosscheckOptions& options);

}  // namespace rtpro
