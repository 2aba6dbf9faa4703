#pragma once
// The native backend's curve intersector (Embree intersects curves with its own kernels). A
// segment is cut into straight pieces at equal steps of u:
// - a round segment into round cones (the hull of the spheres at a piece's two ends), as many as
//   keep the pieces within kCurveChordTolerance of the segment's largest radius from the curve
//   (the chord error of a cubic, |p''|/8 per piece squared), at most kMaxRoundPieces. A round
//   linear segment is one piece: Embree's ROUND_LINEAR_CURVE surface exactly.
// - a flat segment into kFlatCurvePieces ribbons facing the ray, as Embree's flat curves are
//   (rtcSetGeometryTessellationRate, set to the same count in curve_backend.cpp). Where a bend
//   turns one piece from the next, Embree's quads turn about the curve's direction at the corner
//   and the native ribbons about each chord: a thin wedge on the bend's outside is Embree's alone.
//   A flat linear segment is one ribbon with ends rounded across the ray, as in Embree.
// docs/backends.md states the resulting tolerance against Embree's surfaces; the cross-check test
// (tests/crosscheck/curve_crosscheck_test.cpp) holds both backends to it.
#include "rtpro/scene/curve_basis.h"

#include <cmath>
#include <cstdint>

namespace rtpro {

inline constexpr float kCurveChordTolerance = 0.01f;
inline constexpr int kMaxRoundPieces = 64;
inline constexpr double kSelfIntersectionAvoidance = 2.0;

// How many pieces the segment is cut into (see above).
inline int curve_pieces(const BezierSegment& segment, CurveShape shape, CurveBasis basis) {
  if (basis == CurveBasis::kLinear) return 1;
  if (shape == CurveShape::kFlat) return kFlatCurvePieces;
  const float tolerance = kCurveChordTolerance * segment.largest_radius();
  const float curvature = segment.curvature_bound();
  if (!(curvature > 0.0f)) return 1;
  if (!(tolerance > 0.0f)) return kMaxRoundPieces;
  const float pieces = std::ceil(std::sqrt(curvature / (8.0f * tolerance)));
  return pieces >= float(kMaxRoundPieces) ? kMaxRoundPieces : std::max(1, static_cast<int>(pieces));
}

struct CurveHit {
  float t, u, v;
};

namespace curve_intersect_detail {

struct Line {
  double o[3], d[3];  // origin; unit direction
  double scale;       // |dir| of the caller's ray: a distance along d over it is the caller's t
};

inline double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Where the line first meets, and last leaves, the hull of the spheres (a, ra) and (b, rb): the
// least and greatest of the roots of both spheres and of the cone tangent to both between its
// circles of contact (the hull is convex, so the line crosses it in one interval; Quilez's rounded
// cone). False when it misses.
inline bool round_cone_interval(const Line& line, const Vec3& a, float ra, const Vec3& b, float rb, double& t_in,
                                double& t_out) {
  const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z};
  double ba[3], oa[3], ob[3];
  for (int i = 0; i < 3; ++i) {
    ba[i] = pb[i] - pa[i];
    oa[i] = line.o[i] - pa[i];
    ob[i] = line.o[i] - pb[i];
  }
  t_in = INFINITY;
  t_out = -INFINITY;
  const auto take = [&](double t) {
    t_in = std::min(t_in, t);
    t_out = std::max(t_out, t);
  };
  const auto sphere = [&](const double f[3], double r) {
    const double b_half = dot3(f, line.d);
    const double disc = b_half * b_half - (dot3(f, f) - r * r);
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    take(-b_half - root);
    take(-b_half + root);
  };
  sphere(oa, ra);
  sphere(ob, rb);
  const double rr = double(ra) - double(rb);
  const double m0 = dot3(ba, ba), m1 = dot3(ba, oa), m2 = dot3(ba, line.d), m3 = dot3(line.d, oa), m5 = dot3(oa, oa);
  const double d2 = m0 - rr * rr;
  if (d2 > 0.0) {  // otherwise one sphere holds the other: the spheres are the hull
    const double k2 = d2 - m2 * m2;
    const double k1 = d2 * m3 - m1 * m2 + m2 * rr * ra;
    const double k0 = d2 * m5 - m1 * m1 + m1 * rr * ra * 2.0 - m0 * double(ra) * ra;
    const double h = k1 * k1 - k0 * k2;
    if (h >= 0.0 && k2 != 0.0) {
      const double root = std::sqrt(h);
      for (const double t : {(-k1 - root) / k2, (-k1 + root) / k2}) {
        const double y = m1 - ra * rr + t * m2;
        if (y > 0.0 && y < d2) take(t);
      }
    }
  }
  return t_in <= t_out;
}

}  // namespace curve_intersect_detail

// The nearest hit of the ray (org + t·dir, tnear < t <= tfar) on the segment, with u along it and
// v across as Embree has it (0 on round and flat linear curves; −1 to 1 across a flat cubic one).
inline bool intersect_curve_segment(const BezierSegment& segment, CurveShape shape, CurveBasis basis, const Vec3& org,
                                    const Vec3& dir, float tnear, float tfar, CurveHit& hit) {
  using namespace curve_intersect_detail;
  const double scale = std::sqrt(double(dir.x) * dir.x + double(dir.y) * dir.y + double(dir.z) * dir.z);
  if (!(scale > 0.0)) return false;
  const Line line{{org.x, org.y, org.z}, {dir.x / scale, dir.y / scale, dir.z / scale}, scale};
  const int pieces = curve_pieces(segment, shape, basis);
  const bool linear = basis == CurveBasis::kLinear;
  const double lo = double(tnear) * scale;
  double best = INFINITY;
  // Nearer than the best so far, within (tnear, tfar] once rounded to the caller's float t, and
  // farther from the origin than twice the radius there: Embree ignores curve hits closer than that
  // (its EMBREE_CURVE_SELF_INTERSECTION_AVOIDANCE_FACTOR, 2 in Debian's build).
  const auto accepted = [&](double t, double radius) {
    const float tf = static_cast<float>(t / scale);
    return t < best && tf > tnear && tf <= tfar && t > kSelfIntersectionAvoidance * radius;
  };
  CurvePoint a = segment.at(0.0f);
  for (int k = 0; k < pieces; ++k) {
    const CurvePoint b = segment.at(float(k + 1) / float(pieces));
    if (shape == CurveShape::kRound) {
      double t_in, t_out;
      if (round_cone_interval(line, a.position, a.radius, b.position, b.radius, t_in, t_out)) {
        const double t = t_in > lo ? t_in : t_out;  // from inside the tube: where it leaves
        const Vec3 p(float(line.o[0] + line.d[0] * t), float(line.o[1] + line.d[1] * t),
                     float(line.o[2] + line.d[2] * t));
        const Vec3 axis = b.position - a.position;
        const float along =
            std::clamp(dot(axis, axis) > 0.0f ? dot(p - a.position, axis) / dot(axis, axis) : 0.0f, 0.0f, 1.0f);
        if (accepted(t, a.radius + (b.radius - a.radius) * along)) {
          best = t;
          hit = {static_cast<float>(t / scale), (float(k) + along) / float(pieces), 0.0f};
        }
      }
    } else {
      // In the plane across the ray: the piece's nearest point to the ray, and its width there.
      double pa[3], pb[3];
      const double ra[3] = {a.position.x - line.o[0], a.position.y - line.o[1], a.position.z - line.o[2]};
      const double rb[3] = {b.position.x - line.o[0], b.position.y - line.o[1], b.position.z - line.o[2]};
      const double along_a = dot3(ra, line.d), along_b = dot3(rb, line.d);
      for (int i = 0; i < 3; ++i) {
        pa[i] = ra[i] - line.d[i] * along_a;
        pb[i] = rb[i] - line.d[i] * along_b;
      }
      const double e[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
      const double ee = dot3(e, e);
      const double nearest = ee > 0.0 ? -dot3(pa, e) / ee : 0.0;
      // Embree rounds a flat linear segment's ends across the ray (its nearest point is clamped to
      // the segment) and cuts a cubic one's square.
      const double s = linear ? std::clamp(nearest, 0.0, 1.0) : nearest;
      if (s >= 0.0 && s <= 1.0) {
        const double q[3] = {pa[0] + e[0] * s, pa[1] + e[1] * s, pa[2] + e[2] * s};
        const double width = double(a.radius) + (double(b.radius) - double(a.radius)) * s;
        const double distance = std::sqrt(dot3(q, q));
        const double t = along_a + (along_b - along_a) * s;
        if (distance <= width && width > 0.0 && accepted(t, width)) {
          best = t;
          // Embree's v: 0 on a linear segment; across a cubic one from −1 to 1, positive where
          // (e × q)·d, q pointing from the ray to the piece, is negative.
          const double side = (e[1] * q[2] - e[2] * q[1]) * line.d[0] + (e[2] * q[0] - e[0] * q[2]) * line.d[1] +
                              (e[0] * q[1] - e[1] * q[0]) * line.d[2];
          const double across = linear ? 0.0 : (side >= 0.0 ? -distance : distance) / width;
          hit = {static_cast<float>(t / scale), float((double(k) + s) / pieces), float(across)};
        }
      }
    }
    a = b;
  }
  return best < INFINITY;
}

}  // namespace rtpro
