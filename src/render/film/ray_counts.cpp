#include "rtpro/render/ray_counts.h"

#include <stdexcept>

namespace rtpro {

const char* ray_kind_name(RayKind kind) {
  switch (kind) {
    case RayKind::kCamera: return "camera";
    case RayKind::kShadow: return "shadow";
    case RayKind::kReflection: return "reflection";
    case RayKind::kRefraction: return "refraction";
  }
  throw std::logic_error("ray_kind_name: not a RayKind");
}

}  // namespace rtpro
