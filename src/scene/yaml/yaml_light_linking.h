#pragma once
// Reads a world entry's `light_linking:` ({illuminated_by: [light names]} or {not_illuminated_by:
// [...]}) and `shadow_linking:` ({shadows_from: [...]} or {no_shadows_from: [...]}), each name one
// of the scene's lights (scenes/FORMAT.md, "Light linking").
#include "rtpro/scene/description.h"
#include "yaml_reader.h"

#include <optional>
#include <string>
#include <vector>

namespace rtpro {

// The keys an entry that may be linked accepts besides its own.
inline constexpr std::string_view kLightLinkingKey = "light_linking";
inline constexpr std::string_view kShadowLinkingKey = "shadow_linking";

// The entry's linking, or nothing when it has neither key. `light_names`: one per light of the
// scene (empty for a light without a name); an unknown name fails at its node, with a suggestion.
std::optional<LightLinkingDesc> read_light_linking(const MappingReader& entry,
                                                   const std::vector<std::string>& light_names);

}  // namespace rtpro
