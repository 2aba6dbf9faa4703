#include "mesh_triangulation.h"

#include <cmath>

namespace rtpro {

namespace {

struct Point {
  double x, y;
};

bool operator==(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }

// Twice the signed area of (a, b, c): > 0 for a left turn. In double, so the projection of float
// corners and these products are exact far more often than in float.
double turn(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Inside or on the boundary of the counter-clockwise triangle (a, b, c).
bool in_triangle(const Point& a, const Point& b, const Point& c, const Point& p) {
  return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

// The corners projected onto the coordinate plane the polygon faces most, oriented so that the
// polygon runs counter-clockwise there (Newell's normal gives both the plane and the winding).
std::vector<Point> project(std::span<const Vec3> corners, bool& degenerate) {
  double normal[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % corners.size()];
    normal[0] += (double(a.y) - b.y) * (double(a.z) + b.z);
    normal[1] += (double(a.z) - b.z) * (double(a.x) + b.x);
    normal[2] += (double(a.x) - b.x) * (double(a.y) + b.y);
  }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(normal[k]) > std::fabs(normal[axis])) axis = k;
  degenerate = !(std::fabs(normal[axis]) > 0.0);
  // Dropping `axis` leaves the plane (u, v) = the next two axes in cyclic order, which sees the
  // polygon counter-clockwise when the normal points along +axis; otherwise swap them.
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  if (normal[axis] < 0.0) std::swap(u, v);
  std::vector<Point> points;
  points.reserve(corners.size());
  for (const Vec3& c : corners) {
    const float xyz[3] = {c.x, c.y, c.z};
    points.push_back({xyz[u], xyz[v]});
  }
  return points;
}

bool is_convex(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(p[(i + n - 1) % n], p[i], p[(i + 1) % n]) < 0.0) return false;
  return true;
}

void fan(const std::vector<Point>& p, std::uint32_t first, const std::vector<std::uint32_t>& order,
         std::vector<LocalTriangle>& out, PolygonTriangulation& result) {
  for (std::size_t k = 1; k + 1 < order.size(); ++k) {
    if (turn(p[first], p[order[k]], p[order[k + 1]]) == 0.0) ++result.dropped;
    else out.push_back({first, order[k], order[k + 1]});
  }
}

class EarClipper {
 public:
  EarClipper(const std::vector<Point>& points, std::vector<LocalTriangle>& out, PolygonTriangulation& result)
      : p_(points), out_(out), result_(result), next_(points.size()), prev_(points.size()) {
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
      next_[i] = std::uint32_t((i + 1) % n);
      prev_[i] = std::uint32_t((i + n - 1) % n);
    }
  }

  void run() {
    std::size_t remaining = p_.size();
    std::uint32_t current = 0;
    // A full lap without clipping anything means no ear exists (self-intersecting input).
    std::size_t since_last_clip = 0;
    const std::size_t budget = 16 * remaining * remaining + 64;
    while (remaining > 3) {
      const std::uint32_t a = prev_[current], c = next_[current];
      const double area = turn(p_[a], p_[current], p_[c]);
      if (area == 0.0) {  // collinear or a zero-width spike: no area to cover, no triangle
        ++result_.dropped;
      } else if (area < 0.0 || !is_ear(a, current, c)) {
        current = c;
        if (++since_last_clip > remaining || tests_ > budget) return give_up(current, remaining);
        continue;
      } else {
        out_.push_back({a, current, c});
      }
      unlink(current);
      --remaining;
      since_last_clip = 0;
      current = c;
    }
    const std::uint32_t a = prev_[current], c = next_[current];
    if (turn(p_[a], p_[current], p_[c]) == 0.0) ++result_.dropped;
    else out_.push_back({a, current, c});
  }

 private:
  // No other corner inside or on the triangle, except corners at the triangle's own points
  // (a keyhole's bridge visits its two ends twice).
  bool is_ear(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    for (std::uint32_t v = next_[c]; v != a; v = next_[v]) {
      ++tests_;
      const Point& q = p_[v];
      if (q == p_[a] || q == p_[b] || q == p_[c]) continue;
      if (in_triangle(p_[a], p_[b], p_[c], q)) return false;
    }
    return true;
  }

  void unlink(std::uint32_t v) {
    next_[prev_[v]] = next_[v];
    prev_[next_[v]] = prev_[v];
  }

  void give_up(std::uint32_t start, std::size_t remaining) {
    result_.fan_fallback = true;
    std::vector<std::uint32_t> order;
    order.reserve(remaining);
    std::uint32_t v = start;
    for (std::size_t k = 0; k < remaining; ++k, v = next_[v]) order.push_back(v);
    fan(p_, start, order, out_, result_);
  }

  const std::vector<Point>& p_;
  std::vector<LocalTriangle>& out_;
  PolygonTriangulation& result_;
  std::vector<std::uint32_t> next_, prev_;
  std::size_t tests_ = 0;
};

}  // namespace

PolygonTriangulation triangulate_polygon(std::span<const Vec3> corners, std::vector<LocalTriangle>& out) {
  PolygonTriangulation result;
  const std::size_t n = corners.size();
  if (n < 3) return result;
  bool degenerate = false;
  const std::vector<Point> points = project(corners, degenerate);
  if (degenerate) {  // no area at all (every corner on one line or point)
    result.dropped = n - 2;
    return result;
  }
  if (n == 3 || is_convex(points)) {
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
    fan(points, 0, order, out, result);
    return result;
  }
  result.concave = true;
  if (n > kMaxEarClippedCorners) {
    result.fan_fallback = true;
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
    fan(points, 0, order, out, result);
    return result;
  }
  EarClipper(points, out, result).run();
  return result;
}

}  // namespace rtpro
