#include "mesh_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace rtpro {
namespace mesh_triangulation_test {

struct P2 {
  double x, y;
};

// Signed area of a polygon in the z = 0 plane (counter-clockwise positive).
double polygon_area(const std::vector<Vec3>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    twice += double(a.x) * b.y - double(b.x) * a.y;
  }
  return twice / 2.0;
}

double triangle_area(const std::vector<Vec3>& p, const LocalTriangle& t) {
  const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
  return ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x)) / 2.0;
}

// Even-odd point-in-polygon for a simple polygon.
bool inside_polygon(const std::vector<Vec3>& p, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    if ((p[i].y > y) != (p[j].y > y) && x < (p[j].x - p[i].x) * (y - p[i].y) / (double(p[j].y) - p[i].y) + p[i].x)
      in = !in;
  }
  return in;
}

bool covered(const std::vector<Vec3>& p, const std::vector<LocalTriangle>& triangles, double x, double y) {
  for (const LocalTriangle& t : triangles) {
    const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
    const auto side = [&](const Vec3& u, const Vec3& v) {
      return (double(v.x) - u.x) * (y - u.y) - (double(v.y) - u.y) * (x - u.x);
    };
    const double s0 = side(a, b), s1 = side(b, c), s2 = side(c, a);
    if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return true;
  }
  return false;
}

TEST(PolygonTriangulation, ConvexPolygonIsAFan) {
  const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<LocalTriangle> out;
  const PolygonTriangulation result = triangulate_polygon(square, out);
  EXPECT_FALSE(result.concave);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0], (LocalTriangle{0, 1, 2}));
  EXPECT_EQ(out[1], (LocalTriangle{0, 2, 3}));
}

TEST(PolygonTriangulation, ConcaveDartIsNotFanned) {
  // An arrowhead whose reflex corner is the fan's apex: a fan would cover area outside it.
  const std::vector<Vec3> dart = {{0.4f, 0.5f, 0}, {0, 0, 0}, {2, 0.5f, 0}, {0, 1, 0}};
  std::vector<LocalTriangle> out;
  const PolygonTriangulation result = triangulate_polygon(dart, out);
  EXPECT_TRUE(result.concave);
  EXPECT_FALSE(result.fan_fallback);
  double area = 0;
  for (const LocalTriangle& t : out) {
    EXPECT_GT(triangle_area(dart, t), 0.0);  // same winding as the polygon
    area += triangle_area(dart, t);
  }
  EXPECT_NEAR(area, polygon_area(dart), 1e-6);
}

// A square ring written as one keyhole polygon: the outer square counter-clockwise, a bridge to
// the hole, the hole clockwise, back along the bridge.
std::vector<Vec3> keyhole_ring(float z_tilt = 0.0f) {
  const std::vector<std::array<float, 2>> xy = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},
                                                {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
  std::vector<Vec3> p;
  for (const auto& [x, y] : xy) p.emplace_back(x, y, z_tilt * x);
  return p;
}

TEST(PolygonTriangulation, KeyholeRingKeepsItsHole) {
  const std::vector<Vec3> ring = keyhole_ring();
  std::vector<LocalTriangle> out;
  const PolygonTriangulation result = triangulate_polygon(ring, out);
  EXPECT_TRUE(result.concave);
  EXPECT_FALSE(result.fan_fallback);
  double area = 0;
  for (const LocalTriangle& t : out) {
    EXPECT_GE(triangle_area(ring, t), 0.0);
    area += triangle_area(ring, t);
  }
  EXPECT_NEAR(area, 16.0 - 4.0, 1e-9);
  // Coverage on a grid of sample points: the ring covered, the hole not.
  for (double y = 0.05; y < 4; y += 0.1) {
    for (double x = 0.05; x < 4; x += 0.1) {
      const bool in_hole = x > 1 && x < 3 && y > 1 && y < 3;
      EXPECT_EQ(covered(ring, out, x, y), !in_hole) << x << ", " << y;
    }
  }
}

TEST(PolygonTriangulation, WorksInTheTiltedPlaneOfThePolygonAndEitherWinding) {
  std::vector<Vec3> ring = keyhole_ring(0.5f);
  std::reverse(ring.begin(), ring.end());
  std::vector<LocalTriangle> out;
  triangulate_polygon(ring, out);
  // Area measured in the plane: projected onto z = 0 it is 12, of the same sign as the polygon's.
  double area = 0;
  for (const LocalTriangle& t : out) area += triangle_area(ring, t);
  EXPECT_NEAR(area, polygon_area(ring), 1e-6);
  EXPECT_NEAR(std::fabs(area), 12.0, 1e-6);
}

TEST(PolygonTriangulation, RandomSimplePolygonsKeepTheirAreaAndStayInside) {
  std::mt19937 random(1234);
  std::uniform_real_distribution<double> radius(0.2, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    // Star-shaped around the origin (angles increasing), hence simple; often very concave.
    const int n = 4 + trial % 40;
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * M_PI * (i + 0.5 * std::uniform_real_distribution<double>(0, 1)(random)) / n;
      const double r = radius(random);
      p.emplace_back(float(r * std::cos(angle)), float(r * std::sin(angle)), 0.0f);
    }
    if (trial % 2) std::reverse(p.begin(), p.end());
    std::vector<LocalTriangle> out;
    const PolygonTriangulation result = triangulate_polygon(p, out);
    SCOPED_TRACE(trial);
    EXPECT_FALSE(result.fan_fallback);
    EXPECT_EQ(out.size() + result.dropped, std::size_t(n - 2));
    double area = 0;
    for (const LocalTriangle& t : out) {
      const double a = triangle_area(p, t);
      EXPECT_GT(a * polygon_area(p), 0.0) << "a triangle wound against the polygon";
      area += a;
      // Inside: the centroid of every triangle lies in the polygon.
      const double cx = (double(p[t[0]].x) + p[t[1]].x + p[t[2]].x) / 3,
                   cy = (double(p[t[0]].y) + p[t[1]].y + p[t[2]].y) / 3;
      EXPECT_TRUE(inside_polygon(p, cx, cy));
    }
    EXPECT_NEAR(area, polygon_area(p), 1e-5);
  }
}

TEST(PolygonTriangulation, CollinearAndDegeneratePolygonsEmitNoZeroAreaTriangles) {
  // A square with a corner on one edge: 5 corners, 3 triangles of which one would be empty.
  const std::vector<Vec3> square = {{0, 0, 0}, {0.5f, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<LocalTriangle> out;
  const PolygonTriangulation result = triangulate_polygon(square, out);
  for (const LocalTriangle& t : out) EXPECT_NE(triangle_area(square, t), 0.0);
  EXPECT_EQ(out.size() + result.dropped, 3u);
  out.clear();
  const std::vector<Vec3> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_EQ(triangulate_polygon(line, out).dropped, 2u);
  EXPECT_TRUE(out.empty());
}

TEST(PolygonTriangulation, HugeConcavePolygonsAreFannedInsteadOfTakingMinutes) {
  std::vector<Vec3> comb;  // teeth up along the bottom, then back along the top
  const int teeth = int(kMaxEarClippedCorners);
  for (int i = 0; i < teeth; ++i) {
    comb.emplace_back(float(i), 0.0f, 0.0f);
    comb.emplace_back(float(i) + 0.5f, 1.0f, 0.0f);
  }
  comb.emplace_back(float(teeth), 2.0f, 0.0f);
  comb.emplace_back(0.0f, 2.0f, 0.0f);
  std::vector<LocalTriangle> out;
  const PolygonTriangulation result = triangulate_polygon(comb, out);
  EXPECT_TRUE(result.concave);
  EXPECT_TRUE(result.fan_fallback);
  EXPECT_EQ(out.size() + result.dropped, comb.size() - 2);
}

}  // namespace mesh_triangulation_test
}  // namespace rtpro
