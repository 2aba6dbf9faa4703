#pragma once
// Many lights, each picked in proportion to an estimate of what it sends to the shading point
// (pbrt-v4's BVHLightSampler, after Conty Estevez & Kulla 2018): a bounding volume hierarchy over
// the lights that have a position, each node bounding its lights' positions, the cone of
// directions they face and their total power. A pick walks down from the root, choosing each
// child in proportion to its importance at the point; the probability of every light at a point
// is found again by walking the same path (each light keeps its path as bits), so multiple
// importance sampling sees the exact pmf. Deterministic: the tree depends only on the lights.
#include "rtpro/core/bbox.h"
#include "rtpro/core/vec3.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rtpro {

// Where a light (or a set of lights) is and which way it shines: light leaves points of `bounds`
// in directions within θ_e of a direction that is within θ_o of `w` (θ_o: the spread of the
// normals, θ_e: how far from its normal each point emits; a sphere of normals is cos θ_o = −1).
struct LightBounds {
  BBox bounds;
  Vec3 w{0.0f, 0.0f, 1.0f};
  float phi = 0.0f;  // power
  float cos_theta_o = 1.0f;
  float cos_theta_e = 0.0f;
  bool two_sided = false;

  // An estimate (an upper bound in direction and distance) of what these lights deliver at `p`.
  float importance(const Vec3& p) const;
};

LightBounds merge(const LightBounds& a, const LightBounds& b);

class LightTree {
 public:
  LightTree() = default;
  // One entry per light of a set: its bounds, or nothing for lights without a position
  // (directional, the environment), which the tree leaves out; so are lights of zero power.
  explicit LightTree(std::span<const std::optional<LightBounds>> lights);

  bool empty() const { return nodes_.empty(); }
  // The power of every light in the tree.
  float power() const { return nodes_.empty() ? 0.0f : nodes_[0].bounds.phi; }

  struct Pick {
    std::uint32_t light;  // index into the set the tree was built from
    float pmf;
  };
  // u in [0, 1). Nothing when no light of the tree can reach `p`.
  std::optional<Pick> sample(const Vec3& p, float u) const {
    Pick pick;
    return sample(p, u, pick) ? std::optional<Pick>(pick) : std::nullopt;
  }
  // The same into `out` (left as it was when there is none), for the path integrator's loop: an
  // optional returned from out of line is put together on the stack field by field and then loaded
  // whole, which stalls on store forwarding.
  bool sample(const Vec3& p, float u, Pick& out) const;
  // The probability sample() picks `light` at `p`; 0 for lights not in the tree.
  float pmf(const Vec3& p, std::uint32_t light) const;

  std::size_t node_count() const { return nodes_.size(); }
  // LightBounds::importance, as the tree's nodes compute it.
  static float importance_of(const LightBounds& bounds, const Vec3& p) { return Importance(bounds).at(p); }

 private:
  // A node's bounds as importance() reads them, the square roots taken once.
  struct Importance {
    Vec3 center, w;
    float half_diagonal;  // not closer than this: a point inside a cluster sees it finitely bright
    float radius2;        // of the bounding sphere
    float phi, cos_theta_o, sin_theta_o, cos_theta_e;
    bool two_sided;
    explicit Importance(const LightBounds& b);
    float at(const Vec3& p) const;
  };
  struct Node {
    LightBounds bounds;
    Importance importance;
    std::uint32_t index;  // a leaf: its light; an inner node: its second child (the first follows it)
    bool leaf;
  };
  struct Entry {
    std::uint32_t light;
    LightBounds bounds;
  };
  std::uint32_t build(std::span<Entry> entries, std::uint64_t trail, int depth);

  std::vector<Node> nodes_;
  // Per light of the set: the turns from the root to its leaf (bit d set: the second child at
  // depth d), and its depth; depth −1 for lights not in the tree.
  std::vector<std::uint64_t> trail_;
  std::vector<std::int8_t> depth_;
};

}  // namespace rtpro
