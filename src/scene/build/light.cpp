#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/light.h"

#include <variant>

namespace rtpro {

// Each kind's light_from is in its own file (scene/point_light.h and its neighbours).
Light make_light(const LightDesc& desc) {
  return std::visit([](const auto& d) -> Light { return light_from(d); }, desc);
}

}  // namespace rtpro
