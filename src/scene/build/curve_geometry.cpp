#include "rtpro/scene/curve_geometry.h"

#include "hair_file.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/scene/curve_basis.h"
#include "rtpro/scene/scene_summary.h"

#include <cmath>
#include <string>
#include <system_error>

namespace rtpro {

std::size_t CurveSet::memory_bytes() const {
  return points.capacity() * sizeof(CurvePoint) + segments.capacity() * sizeof(std::uint32_t) +
         colors.capacity() * sizeof(Color);
}

namespace {

// The points a cubic strand gets before its first and after its last so the curve runs from the
// one to the other: a copy of the end for Catmull–Rom (which passes through its inner two control
// points, with the tangent (p1 − p0) / 2 there), and for a B-spline the end reflected through its
// neighbour, 2·p0 − p1 (a phantom point: the segment then starts at p0 with the tangent p1 − p0
// and no bend). A B-spline end repeated three times instead starts the curve at p0 with a zero
// tangent, where Embree's sweep of a circle along the curve has no direction and reports hits a
// radius off the tube. The phantom's radius, 2·r0 − r1, may be negative (Embree allows that); the
// segment's radius, a blend of the strand's own, is not.
bool has_end_points(CurveBasis basis) { return basis == CurveBasis::kCatmullRom || basis == CurveBasis::kBSpline; }

CurvePoint end_point(CurveBasis basis, const CurvePoint& end, const CurvePoint& neighbour) {
  if (basis != CurveBasis::kBSpline) return end;
  return {end.position * 2.0f - neighbour.position, end.radius * 2.0f - neighbour.radius};
}

}  // namespace

CurveSet curves_from_strands(std::vector<CurvePoint> points, const std::vector<std::uint32_t>& strand_points,
                             CurveBasis basis) {
  CurveSet curves;
  curves.basis = basis;
  const bool ends = has_end_points(basis);
  const std::uint32_t step = basis == CurveBasis::kBezier ? 3 : 1;
  const std::uint32_t span = control_points_per_segment(basis) - 1;
  curves.points.reserve(points.size() + (ends ? 2 : 0) * strand_points.size());
  std::size_t first = 0;
  for (std::size_t s = 0; s < strand_points.size(); ++s) {
    const std::uint32_t n = strand_points[s];
    if (n > points.size() - first)
      throw InputError("strand " + std::to_string(s) + " has " + std::to_string(n) + " points, past the " +
                       std::to_string(points.size()) + " given");
    if (n < 2) {  // a single point has no segment
      first += n;
      continue;
    }
    if (basis == CurveBasis::kBezier && (n - 1) % 3 != 0)
      throw InputError("strand " + std::to_string(s) + " has " + std::to_string(n) +
                       " points; a Bezier strand needs 3k + 1 (4, 7, 10, ...)");
    const auto start = static_cast<std::uint32_t>(curves.points.size());
    const std::size_t last = first + n - 1;
    if (ends) curves.points.push_back(end_point(basis, points[first], points[first + 1]));
    curves.points.insert(curves.points.end(), points.begin() + static_cast<std::ptrdiff_t>(first),
                         points.begin() + static_cast<std::ptrdiff_t>(last + 1));
    if (ends) curves.points.push_back(end_point(basis, points[last], points[last - 1]));
    const auto stored = static_cast<std::uint32_t>(curves.points.size()) - start;
    for (std::uint32_t i = 0; i + span < stored; i += step) curves.segments.push_back(start + i);
    first += n;
  }
  return curves;
}

namespace {

// The per-point colours follow the points through the end points curves_from_strands adds (a
// B-spline's phantom colour, extrapolated like its position, kept at or above 0).
std::vector<Color> colors_of_strands(const std::vector<Color>& colors, const std::vector<std::uint32_t>& strands,
                                     CurveBasis basis) {
  std::vector<CurvePoint> carried;
  carried.reserve(colors.size());
  for (const Color& c : colors) carried.push_back({c, 0.0f});
  std::vector<Color> out;
  for (const CurvePoint& p : curves_from_strands(std::move(carried), strands, basis).points)
    out.push_back(max(p.position, Vec3(0.0f)));
  return out;
}

// The cube root of the transform's volume scale: what a radius becomes under it.
float radius_scale_of(const Affine& transform) { return std::cbrt(std::fabs(transform.determinant())); }

}  // namespace

CurveSet load_curves(const CurvesDesc& desc) {
  const CurveBasis basis = desc.basis.value_or(CurveBasis::kCatmullRom);
  std::vector<CurvePoint> points = desc.points;
  std::vector<std::uint32_t> strands = desc.strands;
  std::vector<Color> colors;
  if (!desc.file.empty()) {
    HairFile hair = read_hair_file(desc.file);
    points = std::move(hair.points);
    strands = std::move(hair.strand_points);
    colors = std::move(hair.colors);
  } else if (strands.empty()) {
    strands.push_back(static_cast<std::uint32_t>(points.size()));
  }
  const float radius_scale = desc.radius_scale * (desc.transform ? radius_scale_of(*desc.transform) : 1.0f);
  for (CurvePoint& p : points) {
    if (desc.transform) p.position = desc.transform->apply_point(p.position);
    p.radius *= radius_scale;
  }
  CurveSet curves;
  try {
    curves = curves_from_strands(std::move(points), strands, basis);
    if (!colors.empty()) curves.colors = colors_of_strands(colors, strands, basis);
  } catch (const InputError& e) {
    throw InputError(desc.where, (desc.file.empty() ? "curves: " : desc.file.string() + ": ") + e.message());
  }
  curves.shape = desc.shape;
  curves.material = desc.material;
  return curves;
}

std::uint32_t primitive_count_of(const CurveSet& curves) { return static_cast<std::uint32_t>(curves.segments.size()); }

BBox primitive_bounds_of(const CurveSet& curves, std::uint32_t prim) {
  const BezierSegment segment = bezier_segment(curves, prim);
  BBox box;
  for (const CurvePoint& c : segment.c) box.extend(c.position);
  const float r = std::max(segment.largest_radius(), 0.0f);
  return {box.lower - Vec3(r), box.upper + Vec3(r)};
}

BBox bounds_of(const CurveSet& curves) {
  BBox b;
  for (std::uint32_t i = 0; i < primitive_count_of(curves); ++i) b.extend(primitive_bounds_of(curves, i));
  return b;
}

void tally_shapes(const CurveSet& curves, ShapeTally& tally, SceneSummary& summary) {
  tally.curve_segments += curves.segments.size();
  summary.geometry_bytes += curves.memory_bytes();
  tally.primitives += curves.segments.size();
}

// A .hair file's points take 12 to 32 bytes of it and become 16 (plus repeats, a segment index and
// the BVH's share): kMeshBytesPerFileByte's 4 per byte covers them as it does a mesh's.
std::uint64_t estimated_bytes(const CurvesDesc& curves) {
  if (curves.file.empty()) return saturating_multiply(curves.points.size(), 4 * sizeof(CurvePoint));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(curves.file, error);
  return error ? 0 : saturating_multiply(size, 4);
}

}  // namespace rtpro
