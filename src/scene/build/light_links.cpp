#include "rtpro/scene/light_links.h"

#include "rtpro/scene/build_render_scene.h"

#include <functional>
#include <string_view>

namespace rtpro {

namespace {

std::size_t hash_of(const LinkGroup& group) {
  const auto bytes = [](const std::vector<std::uint8_t>& flags) {
    return std::string_view(reinterpret_cast<const char*>(flags.data()), flags.size());
  };
  const std::hash<std::string_view> hash;
  return hash(bytes(group.illuminated_by)) * 31 + hash(bytes(group.casts_shadow_from));
}

}  // namespace

std::uint32_t LightLinks::group_with(const LinkGroup& group) {
  if (groups.empty()) {
    const std::size_t lights = group.illuminated_by.size();
    groups.push_back(LinkGroup{std::vector<std::uint8_t>(lights, 1), std::vector<std::uint8_t>(lights, 1)});
    shadows_pass_some.assign(lights, 0);
    groups_by_hash_.emplace(hash_of(groups.front()), 0);
  }
  const std::size_t hash = hash_of(group);
  const auto [first, last] = groups_by_hash_.equal_range(hash);
  for (auto it = first; it != last; ++it)
    if (groups[it->second] == group) return it->second;
  groups_by_hash_.emplace(hash, static_cast<std::uint32_t>(groups.size()));
  groups.push_back(group);
  for (std::size_t light = 0; light < shadows_pass_some.size(); ++light)
    if (!group.casts_shadow_from[light]) shadows_pass_some[light] = 1;
  return static_cast<std::uint32_t>(groups.size() - 1);
}

namespace {

// Per light: 1 for the lights an include list names or an exclude list does not; all 1 without a list.
std::vector<std::uint8_t> light_flags(const std::optional<LightListDesc>& list, std::size_t light_count) {
  if (!list) return std::vector<std::uint8_t>(light_count, 1);
  std::vector<std::uint8_t> flags(light_count, list->include ? 0 : 1);
  for (const std::uint32_t light : list->lights) flags.at(light) = list->include ? 1 : 0;
  return flags;
}

}  // namespace

LinkGroup make_link_group(const LightLinkingDesc& desc, std::size_t light_count) {
  return LinkGroup{light_flags(desc.illumination, light_count), light_flags(desc.shadows, light_count)};
}

}  // namespace rtpro
