#pragma once
#include "rtpro/backend/backend.h"

#include <memory>

namespace rtpro {

std::unique_ptr<Backend> make_embree_backend(const RenderScene& scene, const BackendOptions& options);

}  // namespace rtpro
