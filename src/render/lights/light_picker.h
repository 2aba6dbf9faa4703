#pragma once
// Chooses which light of a LightSet a shading point samples (render.light_sampler): `power` picks
// every light in proportion to its power; `tree` picks the lights with a position through a light
// tree (importance at the point) and those without (directional lights, the environment) by their
// power against the tree's. A picker may hold only some of the set's lights (light linking: the
// lights that illuminate one group of objects); it then picks exactly as a picker over a set that
// held only those lights, in the same order, would, so a light left out by linking changes nothing.
#include "rtpro/core/vec3.h"
#include "alias_table.h"
#include "light_tree.h"
#include "rtpro/scene/render_settings.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace rtpro {

class LightPicker {
 public:
  LightPicker() = default;
  // `members`: the set's indices of the lights it picks from, ascending; `power` and `bounds`: per
  // light of the set (bounds empty for lights without a position).
  LightPicker(LightSamplerKind kind, std::span<const std::uint32_t> members, std::span<const float> power,
              std::span<const std::optional<LightBounds>> bounds);

  // No light to pick (none, or none with power).
  bool empty() const { return pick_.empty(); }

  struct Pick {
    std::uint32_t light;  // the set's index
    float pmf;
  };
  // u in [0, 1). Nothing when no light can reach `point`.
  std::optional<Pick> pick(const Vec3& point, float u) const {
    Pick p;
    return pick(point, u, p) ? std::optional<Pick>(p) : std::nullopt;
  }
  // The same into `out` (left as it was when there is none), for the path integrator's loop
  // (LightTree::sample says why).
  bool pick(const Vec3& point, float u, Pick& out) const {
    if (single_) {
      out = single_pick_;
      return true;
    }
    return pick_among(point, u, out);
  }
  // Whether pick() reads its `u`: not for one member (nor none).
  bool picks_by_number() const { return !single_ && !members_.empty(); }
  // The probability pick() chooses light `light` (the set's index) at `point`; 0 for lights it
  // does not hold.
  float probability(std::uint32_t light, const Vec3& point) const;
  bool holds(std::uint32_t light) const { return light < member_of_.size() && member_of_[light] != kNone; }

 private:
  static constexpr std::uint32_t kNone = ~0u;
  bool pick_among(const Vec3& point, float u, Pick& out) const;
  LightSamplerKind kind_ = LightSamplerKind::kTree;
  std::vector<std::uint32_t> members_;    // the set's index of each member
  std::vector<std::uint32_t> member_of_;  // per light of the set: its member index, or kNone
  AliasTable pick_;                       // power: every member by its power
  // tree: the members with a position in the tree, those without by their power; which of the
  // two by the power of each side.
  LightTree tree_;
  std::vector<std::uint32_t> infinite_;       // their member indices
  std::vector<std::uint32_t> infinite_slot_;  // per member: its place in infinite_, or kNone
  AliasTable infinite_pick_;
  float infinite_probability_ = 0.0f;
  // One member: the pick depends on neither the point nor u (the tree is one leaf, the tables
  // one entry, the split 0 or 1), so it is made once, and a scene lit by one light pays nothing
  // per vertex to pick it.
  bool single_ = false;
  Pick single_pick_{};
};

}  // namespace rtpro
