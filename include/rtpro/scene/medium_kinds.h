#pragma once
// The kinds of participating medium, registered. Each kind's scene side is one header (its data:
// scene/homogeneous_medium.h, scene/grid_medium.h) and its render side another
// (render/media/homogeneous_medium.h, render/media/grid_medium.h, whose
// functions render/media/medium.h lists and checks). A new kind is its two headers, an alternative
// of Medium and its include here; the static_assert in render/media/medium.h then names each
// function its render side still lacks.
#include "rtpro/scene/grid_medium.h"
#include "rtpro/scene/homogeneous_medium.h"

#include <cstdint>
#include <variant>

namespace rtpro {

using Medium = std::variant<HomogeneousMedium, GridMedium>;

// A medium index (RenderScene::media) that names none: vacuum.
inline constexpr std::uint32_t kNoMedium = ~0u;

}  // namespace rtpro
