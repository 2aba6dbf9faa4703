#include "light_tree.h"

#include "rtpro/core/math_constants.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtpro {

namespace {

float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

// cos(max(0, a − b)) and sin(max(0, a − b)) from the sines and cosines of a and b.
float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 1.0f;
  return cos_a * cos_b + sin_a * sin_b;
}
float sin_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  if (cos_a > cos_b) return 0.0f;
  return sin_a * cos_b - cos_a * sin_b;
}

// A direction cone (w, cos θ): the union of two (pbrt-v4's DirectionCone::Union).
struct Cone {
  Vec3 w;
  float cos_theta;
};

Vec3 rotate_about(const Vec3& v, const Vec3& axis, float angle) {
  // Rodrigues, axis unit.
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0f - c));
}

Cone cone_union(const Cone& a, const Cone& b) {
  const float theta_a = std::acos(std::clamp(a.cos_theta, -1.0f, 1.0f));
  const float theta_b = std::acos(std::clamp(b.cos_theta, -1.0f, 1.0f));
  const float theta_d = std::acos(std::clamp(dot(a.w, b.w), -1.0f, 1.0f));
  if (std::min(theta_d + theta_b, kPi) <= theta_a) return a;
  if (std::min(theta_d + theta_a, kPi) <= theta_b) return b;
  const float theta_o = 0.5f * (theta_a + theta_d + theta_b);
  if (theta_o >= kPi) return {a.w, -1.0f};
  const Vec3 axis = cross(a.w, b.w);
  if (!(dot(axis, axis) > 0.0f)) return {a.w, -1.0f};
  const Vec3 w = rotate_about(a.w, normalize(axis), theta_o - theta_a);
  return {normalize(w), std::cos(theta_o)};
}

// pbrt-v4's cost of a split's side: its power × the solid angle its cone of emission reaches ×
// its surface area, stretched by how thin the box is along the split axis.
float split_cost(const LightBounds& b, const BBox& centroid_bounds, int axis) {
  const float theta_o = std::acos(std::clamp(b.cos_theta_o, -1.0f, 1.0f));
  const float theta_e = std::acos(std::clamp(b.cos_theta_e, -1.0f, 1.0f));
  const float theta_w = std::min(theta_o + theta_e, kPi);
  const float sin_theta_o = safe_sqrt(1.0f - b.cos_theta_o * b.cos_theta_o);
  const float m_omega =
      2.0f * kPi * (1.0f - b.cos_theta_o) + 0.5f * kPi *
                                                (2.0f * theta_w * sin_theta_o - std::cos(theta_o - 2.0f * theta_w) -
                                                 2.0f * theta_o * sin_theta_o + b.cos_theta_o);
  const Vec3 extent = centroid_bounds.extent();
  const float largest = std::max({extent.x, extent.y, extent.z});
  const float kr = extent[axis] > 0.0f ? largest / extent[axis] : 1.0f;
  return b.phi * m_omega * kr * b.bounds.surface_area();
}

constexpr int kBuckets = 12;
constexpr int kMaxDepth = 63;

}  // namespace

LightTree::Importance::Importance(const LightBounds& b)
    : center(b.bounds.center()), w(b.w), half_diagonal(0.5f * length(b.bounds.extent())),
      radius2(0.25f * dot(b.bounds.extent(), b.bounds.extent())), phi(b.phi), cos_theta_o(b.cos_theta_o),
      sin_theta_o(safe_sqrt(1.0f - b.cos_theta_o * b.cos_theta_o)), cos_theta_e(b.cos_theta_e), two_sided(b.two_sided) {
}

float LightTree::Importance::at(const Vec3& p) const {
  const Vec3 to_p = p - center;
  const float distance2 = dot(to_p, to_p);
  const float d2 = std::max(distance2, half_diagonal);
  if (!(d2 > 0.0f)) return phi;
  float cos_theta_w = distance2 > 0.0f ? dot(w, to_p) / std::sqrt(distance2) : 1.0f;  // at the centre: any way
  if (two_sided) cos_theta_w = std::fabs(cos_theta_w);
  const float sin_theta_w = safe_sqrt(1.0f - cos_theta_w * cos_theta_w);
  // The half-angle of the cone of directions the bounding sphere fills from p (everything inside it).
  const float cos_theta_b = distance2 < radius2 ? -1.0f : safe_sqrt(1.0f - radius2 / distance2);
  const float sin_theta_b = safe_sqrt(1.0f - cos_theta_b * cos_theta_b);
  // The smallest angle between p's direction and any direction the lights may emit in.
  const float cos_theta_x = cos_sub_clamped(sin_theta_w, cos_theta_w, sin_theta_o, cos_theta_o);
  const float sin_theta_x = sin_sub_clamped(sin_theta_w, cos_theta_w, sin_theta_o, cos_theta_o);
  const float cos_theta_p = cos_sub_clamped(sin_theta_x, cos_theta_x, sin_theta_b, cos_theta_b);
  if (cos_theta_p <= cos_theta_e) return 0.0f;
  return phi * cos_theta_p / d2;
}

LightBounds merge(const LightBounds& a, const LightBounds& b) {
  if (a.phi == 0.0f) return b;
  if (b.phi == 0.0f) return a;
  const Cone cone = cone_union({a.w, a.cos_theta_o}, {b.w, b.cos_theta_o});
  return {
      rtpro::merge(a.bounds, b.bounds), cone.w, a.phi + b.phi, cone.cos_theta, std::min(a.cos_theta_e, b.cos_theta_e),
      a.two_sided || b.two_sided};
}

LightTree::LightTree(std::span<const std::optional<LightBounds>> lights)
    : trail_(lights.size(), 0), depth_(lights.size(), -1) {
  std::vector<Entry> entries;
  for (std::uint32_t i = 0; i < lights.size(); ++i)
    if (lights[i] && lights[i]->phi > 0.0f && std::isfinite(lights[i]->phi)) entries.push_back({i, *lights[i]});
  if (entries.empty()) return;
  nodes_.reserve(2 * entries.size());
  build(entries, 0, 0);
}

std::uint32_t LightTree::build(std::span<Entry> entries, std::uint64_t trail, int depth) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  if (entries.size() == 1) {
    nodes_.push_back({entries[0].bounds, Importance(entries[0].bounds), entries[0].light, true});
    trail_[entries[0].light] = trail;
    depth_[entries[0].light] = static_cast<std::int8_t>(depth);
    return index;
  }
  BBox centroids;
  for (const Entry& e : entries) centroids.extend(e.bounds.bounds.center());

  // The cheapest of kBuckets − 1 planes along each axis, or, where the centroids coincide (or the
  // tree grows too deep), halves by count.
  std::size_t split = entries.size() / 2;
  float best_cost = std::numeric_limits<float>::infinity();
  int best_axis = -1, best_bucket = -1;
  if (depth < kMaxDepth - 8) {
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centroids.lower[axis], hi = centroids.upper[axis];
      if (!(hi > lo)) continue;
      std::array<LightBounds, kBuckets> buckets{};
      const auto bucket_of = [&](const Entry& e) {
        const int b = static_cast<int>(kBuckets * ((e.bounds.bounds.center()[axis] - lo) / (hi - lo)));
        return std::clamp(b, 0, kBuckets - 1);
      };
      for (const Entry& e : entries) {
        LightBounds& b = buckets[static_cast<std::size_t>(bucket_of(e))];
        b = merge(b, e.bounds);
      }
      for (int plane = 0; plane < kBuckets - 1; ++plane) {
        LightBounds below, above;
        for (int b = 0; b <= plane; ++b) below = merge(below, buckets[static_cast<std::size_t>(b)]);
        for (int b = plane + 1; b < kBuckets; ++b) above = merge(above, buckets[static_cast<std::size_t>(b)]);
        const float cost = split_cost(below, centroids, axis) + split_cost(above, centroids, axis);
        if (below.phi > 0.0f && above.phi > 0.0f && cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bucket = plane;
        }
      }
    }
  }
  if (best_axis >= 0) {
    const float lo = centroids.lower[best_axis], hi = centroids.upper[best_axis];
    const auto middle = std::partition(entries.begin(), entries.end(), [&](const Entry& e) {
      const int b = static_cast<int>(kBuckets * ((e.bounds.bounds.center()[best_axis] - lo) / (hi - lo)));
      return std::clamp(b, 0, kBuckets - 1) <= best_bucket;
    });
    split = static_cast<std::size_t>(middle - entries.begin());
  } else {
    // Ordered by light index, so the halves do not depend on the partition's earlier moves.
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.light < b.light; });
  }
  if (split == 0 || split == entries.size()) split = entries.size() / 2;

  nodes_.push_back({LightBounds{}, Importance(LightBounds{}), 0, false});  // filled once both children are built
  build(entries.subspan(0, split), trail, depth + 1);
  const std::uint32_t second = build(entries.subspan(split), trail | (std::uint64_t{1} << depth), depth + 1);
  const LightBounds bounds = merge(nodes_[index + 1].bounds, nodes_[second].bounds);
  nodes_[index] = {bounds, Importance(bounds), second, false};
  return index;
}

bool LightTree::sample(const Vec3& p, float u, Pick& out) const {
  if (nodes_.empty()) return false;
  std::uint32_t node = 0;
  float pmf = 1.0f;
  while (!nodes_[node].leaf) {
    const std::uint32_t first = node + 1, second = nodes_[node].index;
    const float a = nodes_[first].importance.at(p), b = nodes_[second].importance.at(p);
    if (!(a + b > 0.0f)) return false;
    const float p_first = a / (a + b);
    if (u < p_first) {
      u = std::min(u / p_first, 0x1.fffffep-1f);
      pmf *= p_first;
      node = first;
    } else {
      const float p_second = 1.0f - p_first;
      u = std::min((u - p_first) / p_second, 0x1.fffffep-1f);
      pmf *= p_second;
      node = second;
    }
  }
  if (!(pmf > 0.0f)) return false;
  out = Pick{nodes_[node].index, pmf};
  return true;
}

float LightTree::pmf(const Vec3& p, std::uint32_t light) const {
  if (light >= depth_.size() || depth_[light] < 0) return 0.0f;
  std::uint32_t node = 0;
  float pmf = 1.0f;
  for (int d = 0; d < depth_[light]; ++d) {
    const std::uint32_t first = node + 1, second = nodes_[node].index;
    const float a = nodes_[first].importance.at(p), b = nodes_[second].importance.at(p);
    if (!(a + b > 0.0f)) return 0.0f;
    const float p_first = a / (a + b);
    if ((trail_[light] >> d) & 1u) {
      pmf *= 1.0f - p_first;
      node = second;
    } else {
      pmf *= p_first;
      node = first;
    }
  }
  return pmf;
}

}  // namespace rtpro

namespace rtpro {

float LightBounds::importance(const Vec3& p) const { return LightTree::importance_of(*this, p); }

}  // namespace rtpro
