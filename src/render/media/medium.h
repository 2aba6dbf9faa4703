#pragma once
// The closed set of medium kinds (scene/medium_kinds.h) with their render sides registered: each
// kind's include below, and the static_assert names any function of render/media/medium_interface.h
// that a kind lacks.
#include "absorbing_medium.h"
#include "homogeneous_medium.h"
#include "medium_interface.h"
#include "rtpro/scene/medium_kinds.h"

#include <cstddef>
#include <utility>
#include <variant>

namespace rtpro {

template <std::size_t... Kind>
constexpr bool every_medium_has_render_side(std::index_sequence<Kind...>) {
  return (has_render_side<std::variant_alternative_t<Kind, Medium>>() && ...);
}
static_assert(every_medium_has_render_side(std::make_index_sequence<std::variant_size_v<Medium>>{}));

inline bool only_absorbs(const Medium& medium) {
  return std::visit([](const auto& kind) { return only_absorbs(kind); }, medium);
}

}  // namespace rtpro
