#pragma once
// Curves (hair, fur, grass), the scene's side of the geometry kind in one place (as
// scene/sphere_geometry.h has it for spheres): the entries a scene file writes (read in
// src/scene/yaml/yaml_curves_entry.cpp), the curves a render scene stores, laid out as Embree
// takes them (a float4 point per control point, the first control point of each segment), and what
// the scene needs of them, defined in src/scene/build/curve_geometry.cpp. Their shape along a
// segment is scene/curve_basis.h; the native intersector is src/backend/curve_intersect.h.
#include "rtpro/core/bbox.h"
#include "rtpro/core/error.h"
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace rtpro {

struct ShapeTally;  // scene/scene_summary.h
struct SceneSummary;
struct YamlNode;
class ShapeEntryReader;  // src/scene/yaml/yaml_shape_entry.h

// How control points make a segment: linear (2 points), cubic Bézier, uniform cubic B-spline or
// Catmull–Rom (4 points each), as Embree's curve types of those names.
enum class CurveBasis : std::uint8_t { kLinear, kBezier, kBSpline, kCatmullRom };
// A round tube (the sweep of a sphere along the curve) or a flat ribbon that faces every ray.
enum class CurveShape : std::uint8_t { kRound, kFlat };

// A control point: position and radius, Embree's RTC_FORMAT_FLOAT4 vertex (x, y, z, r).
struct CurvePoint {
  Vec3 position;
  float radius;
};
static_assert(sizeof(CurvePoint) == 16);

struct CurveSet {
  std::vector<CurvePoint> points;
  std::vector<std::uint32_t> segments;  // each segment's first control point
  std::vector<Color> colors;            // one per control point, or none (the file had none)
  CurveBasis basis = CurveBasis::kCatmullRom;
  CurveShape shape = CurveShape::kRound;
  std::uint32_t material = 0;

  std::size_t memory_bytes() const;
};

inline std::uint32_t control_points_per_segment(CurveBasis basis) { return basis == CurveBasis::kLinear ? 2 : 4; }

// Strands of consecutive control points (`points` laid out strand after strand, strand s having
// `strand_points[s]` of them) as segments of `basis`. Cubic strands get a point past each end so the
// curve starts and ends there along the strand (Catmull–Rom: the end again; B-spline: the end
// reflected through its neighbour); a Bézier strand needs 3k + 1 points. The error names the strand.
CurveSet curves_from_strands(std::vector<CurvePoint> points, const std::vector<std::uint32_t>& strand_points,
                             CurveBasis basis);

// A `type: curves` entry: the curves of a .hair file, or control points written in the scene file.
struct CurvesDesc {
  std::filesystem::path file;          // a .hair file; empty for inline points
  std::vector<CurvePoint> points;      // inline: every strand's control points, strand after strand
  std::vector<std::uint32_t> strands;  // inline: points per strand (one strand of them all when empty)
  std::optional<CurveBasis> basis;     // unset: Catmull–Rom, through every point
  CurveShape shape = CurveShape::kRound;
  float radius_scale = 1.0f;
  std::optional<Affine> transform;
  std::uint32_t material = 0;
  std::uint32_t linking = ~0u;  // kNoLinking (scene/description.h)
  SourceLocation where;
};

inline const char* entry_type_name(const std::vector<CurvesDesc>&) { return "curves"; }
void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<CurvesDesc>& curves);

// The entry's curves, its file read (src/scene/mesh/hair_file.h) and placed; load errors name the entry.
CurveSet load_curves(const CurvesDesc& desc);

std::uint32_t primitive_count_of(const CurveSet& curves);
// A segment's bounds: its Bézier control points' hull, widened by the largest radius.
BBox primitive_bounds_of(const CurveSet& curves, std::uint32_t prim);
// Curves keep still: no motion steps.
inline std::uint32_t motion_step_count_of(const CurveSet&) { return 0; }
inline BBox primitive_bounds_at_step(const CurveSet& curves, std::uint32_t prim, std::uint32_t) {
  return primitive_bounds_of(curves, prim);
}
BBox bounds_of(const CurveSet& curves);
void tally_shapes(const CurveSet& curves, ShapeTally& tally, SceneSummary& summary);
// Memory the entry adds to a render (scene/render_cost.h): its points and segments, and the BVH.
std::uint64_t estimated_bytes(const CurvesDesc& curves);

}  // namespace rtpro
