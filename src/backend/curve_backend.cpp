#include "curve_backend.h"

#include <cmath>
#include <cstring>
#include <string>

namespace rtpro {

std::optional<std::string> embree_refusal(const CurveSet& curves) {
  for (std::size_t i = 0; i < curves.points.size(); ++i) {
    const CurvePoint& p = curves.points[i];
    if (!within_traceable_range(p.position) || !std::isfinite(p.radius))
      return "has curve control point " + std::to_string(i) + " outside Embree's range or with a bad radius";
  }
  const std::size_t span = control_points_per_segment(curves.basis);
  for (const std::uint32_t first : curves.segments)
    if (first + span > curves.points.size())
      return "has a curve segment past its " + std::to_string(curves.points.size()) + " control points";
  // A control point's radius may be negative (a B-spline's phantom end, scene/curve_geometry.h), a
  // segment's may not: Embree's rule. Its Bézier radii bound it; a blend of radii that should come
  // to 0 may round to a hair below.
  for (std::uint32_t prim = 0; prim < curves.segments.size(); ++prim) {
    const BezierSegment segment = bezier_segment(curves, prim);
    const float floor = -1e-5f * std::fabs(segment.largest_radius());
    for (const CurvePoint& c : segment.c)
      if (!(c.radius >= floor)) return "has curve segment " + std::to_string(prim) + " with a negative radius";
  }
  return std::nullopt;
}

namespace {

RTCGeometryType embree_curve_type(CurveBasis basis, CurveShape shape) {
  const bool round = shape == CurveShape::kRound;
  switch (basis) {
    case CurveBasis::kLinear: return round ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE : RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE;
    case CurveBasis::kBezier: return round ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE : RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE;
    case CurveBasis::kBSpline:
      return round ? RTC_GEOMETRY_TYPE_ROUND_BSPLINE_CURVE : RTC_GEOMETRY_TYPE_FLAT_BSPLINE_CURVE;
    case CurveBasis::kCatmullRom:
      return round ? RTC_GEOMETRY_TYPE_ROUND_CATMULL_ROM_CURVE : RTC_GEOMETRY_TYPE_FLAT_CATMULL_ROM_CURVE;
  }
  return RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE;
}

}  // namespace

// The control points are copied into a buffer of Embree's own, which it pads for its reads past the
// last vertex (a shared vector need not have that room); the segments are shared.
EmbreeGeometry new_embree_geometry(RTCDevice device, const CurveSet& curves, RTCBuildQuality quality) {
  EmbreeGeometry geometry(rtcNewGeometry(device, embree_curve_type(curves.basis, curves.shape)));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  void* points = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(CurvePoint),
                                         curves.points.size());
  if (!points) return EmbreeGeometry();
  if (!curves.points.empty()) std::memcpy(points, curves.points.data(), curves.points.size() * sizeof(CurvePoint));
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, curves.segments.data(), 0,
                             sizeof(std::uint32_t), curves.segments.size());
  // Flat curves are this many ray-facing quads per segment, as the native intersector's ribbons.
  if (curves.shape == CurveShape::kFlat) rtcSetGeometryTessellationRate(g, float(kFlatCurvePieces));
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

}  // namespace rtpro
