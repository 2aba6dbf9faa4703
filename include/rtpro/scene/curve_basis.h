#pragma once
// A curve segment's shape: its control points in any basis (scene/curve_geometry.h) turned into the
// cubic Bézier form that every other step uses (bounds, the native intersector, the surface at a
// hit). Positions and radii go through the same basis, as in Embree.
#include "rtpro/scene/curve_geometry.h"

#include <algorithm>
#include <array>

namespace rtpro {

// Both backends render a flat cubic segment as this many straight ribbons facing the ray
// (Embree's tessellation rate; the native backend's src/backend/curve_intersect.h).
inline constexpr int kFlatCurvePieces = 8;

// A segment as four Bézier control points (position and radius each): p(u) = Σ Bᵢ(u)·cᵢ, u in [0, 1].
struct BezierSegment {
  std::array<CurvePoint, 4> c;

  CurvePoint at(float u) const {
    const float s = 1.0f - u;
    const float b0 = s * s * s, b1 = 3.0f * s * s * u, b2 = 3.0f * s * u * u, b3 = u * u * u;
    return {c[0].position * b0 + c[1].position * b1 + c[2].position * b2 + c[3].position * b3,
            c[0].radius * b0 + c[1].radius * b1 + c[2].radius * b2 + c[3].radius * b3};
  }
  // dp/du (not unit).
  Vec3 derivative(float u) const {
    const float s = 1.0f - u;
    return (c[1].position - c[0].position) * (3.0f * s * s) + (c[2].position - c[1].position) * (6.0f * s * u) +
           (c[3].position - c[2].position) * (3.0f * u * u);
  }
  float largest_radius() const {
    return std::max(std::max(c[0].radius, c[1].radius), std::max(c[2].radius, c[3].radius));
  }
  // A bound on |d²p/du²| over the segment: 6 × the largest second difference of the control points.
  float curvature_bound() const {
    const Vec3 a = c[0].position - c[1].position * 2.0f + c[2].position;
    const Vec3 b = c[1].position - c[2].position * 2.0f + c[3].position;
    return 6.0f * std::max(length(a), length(b));
  }
};

namespace curve_basis_detail {

inline CurvePoint mix(const CurvePoint& a, float wa, const CurvePoint& b, float wb, const CurvePoint& c, float wc,
                      const CurvePoint& d, float wd) {
  return {a.position * wa + b.position * wb + c.position * wc + d.position * wd,
          a.radius * wa + b.radius * wb + c.radius * wc + d.radius * wd};
}

}  // namespace curve_basis_detail

// Segment `prim` of `curves` in Bézier form. Linear segments are degree-elevated (their thirds),
// B-spline and Catmull–Rom segments converted by their basis matrices.
inline BezierSegment bezier_segment(const CurveSet& curves, std::uint32_t prim) {
  using curve_basis_detail::mix;
  const CurvePoint* p = curves.points.data() + curves.segments[prim];
  constexpr float third = 1.0f / 3.0f, sixth = 1.0f / 6.0f;
  switch (curves.basis) {
    case CurveBasis::kLinear:
      return {{p[0], mix(p[0], 2.0f * third, p[1], third, p[1], 0.0f, p[1], 0.0f),
               mix(p[0], third, p[1], 2.0f * third, p[1], 0.0f, p[1], 0.0f), p[1]}};
    case CurveBasis::kBezier: return {{p[0], p[1], p[2], p[3]}};
    case CurveBasis::kBSpline:
      return {{mix(p[0], sixth, p[1], 4.0f * sixth, p[2], sixth, p[3], 0.0f),
               mix(p[0], 0.0f, p[1], 2.0f * third, p[2], third, p[3], 0.0f),
               mix(p[0], 0.0f, p[1], third, p[2], 2.0f * third, p[3], 0.0f),
               mix(p[0], 0.0f, p[1], sixth, p[2], 4.0f * sixth, p[3], sixth)}};
    case CurveBasis::kCatmullRom:
      return {{p[1], mix(p[0], -sixth, p[1], 1.0f, p[2], sixth, p[3], 0.0f),
               mix(p[0], 0.0f, p[1], sixth, p[2], 1.0f, p[3], -sixth), p[2]}};
  }
  return {{p[0], p[0], p[0], p[0]}};
}

}  // namespace rtpro
