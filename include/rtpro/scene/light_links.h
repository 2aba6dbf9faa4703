#pragma once
// Light linking as the renderer reads it (scenes/FORMAT.md, "Light linking"): the world's objects
// in groups that agree on which of the scene's lights illuminate them and which lights' shadow
// rays they block. Group 0 is every object the file does not link: lit by every light, casting
// every light's shadows. Cycles' receiver and blocker sets, Arnold's light and shadow groups.
// Only the scene's `lights:` are linked; emissive surfaces and the environment reach everything.
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace rtpro {

struct LinkGroup {
  std::vector<std::uint8_t> illuminated_by;     // per scene light: 1 when it lights the group's objects
  std::vector<std::uint8_t> casts_shadow_from;  // per scene light: 1 when the objects block its shadow rays
  bool operator==(const LinkGroup&) const = default;
};

struct LightLinks {
  // Empty when nothing is linked (every lookup then answers group 0, lit and shadowing).
  std::vector<LinkGroup> groups;
  // Per top-level geometry: its group or, for a geometry whose primitives are entries of the scene
  // file of their own (the world's spheres are one geometry), kPerPrimitive plus where its
  // primitives' groups start in group_of_primitive.
  std::vector<std::uint32_t> group_of_object;
  std::vector<std::uint32_t> group_of_primitive;
  static constexpr std::uint32_t kPerPrimitive = 1u << 31;  // above any group or offset: both < kMaxSceneEntries

  bool linked() const { return !groups.empty(); }
  // The group of a hit on top-level geometry `object` (the instance, for an instanced hit),
  // primitive `primitive` of it.
  std::uint32_t group_of(std::uint32_t object, std::uint32_t primitive) const {
    if (groups.empty()) return 0;
    const std::uint32_t group = group_of_object[object];
    return group & kPerPrimitive ? group_of_primitive[(group & ~kPerPrimitive) + primitive] : group;
  }
  bool illuminates(std::uint32_t group, std::uint32_t light) const {
    return groups.empty() || groups[group].illuminated_by[light] != 0;
  }
  bool casts_shadow(std::uint32_t group, std::uint32_t light) const {
    return groups.empty() || groups[group].casts_shadow_from[light] != 0;
  }
  // Per scene light: 1 when some group lets its shadow rays through (they then need a closer look
  // than an occlusion query).
  std::vector<std::uint8_t> shadows_pass_some;
  bool shadow_linked(std::uint32_t light) const { return !groups.empty() && shadows_pass_some[light] != 0; }

  // The group with these flags, added unless one has them already (group 0 first: every light).
  // Found by hashing the flags: comparing each new group with every other made 3,000 groups of
  // 3,000 lights take seconds.
  std::uint32_t group_with(const LinkGroup& group);

 private:
  std::unordered_multimap<std::size_t, std::uint32_t> groups_by_hash_;
};

}  // namespace rtpro
