#pragma once
// The kinds of participating medium, registered. Each kind's scene side is one header (its data:
// scene/homogeneous_medium.h) and its render side another (render/media/homogeneous_medium.h, whose
// functions render/media/medium.h lists and checks). A new kind is its two headers, an alternative
// of Medium and its include here; the static_assert in render/media/medium.h then names each
// function its render side still lacks.
#include "rtpro/scene/absorbing_medium.h"
#include "rtpro/scene/homogeneous_medium.h"

#include <cstdint>
#include <variant>

namespace rtpro {

using Medium = std::variant<HomogeneousMedium, AbsorbingMedium>;

// An index into RenderScene::media. Sixteen bits keep a path's stack of them small
// (render/media/medium_stack.h): a scene holds at most kNoMedium media.
using MediumIndex = std::uint16_t;
// The medium index that names none: vacuum.
inline constexpr MediumIndex kNoMedium = 0xFFFF;

}  // namespace rtpro
