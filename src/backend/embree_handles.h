#pragma once
// Owning handles for Embree objects, so every early exit (a thrown RuntimeError mid-build)
// still releases what was created.
#include <embree3/rtcore.h>

#include <memory>

namespace rtpro {

struct EmbreeSceneRelease {
  void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
struct EmbreeGeometryRelease {
  void operator()(RTCGeometry geometry) const { rtcReleaseGeometry(geometry); }
};

using EmbreeScene = std::unique_ptr<RTCSceneTy, EmbreeSceneRelease>;
using EmbreeGeometry = std::unique_ptr<RTCGeometryTy, EmbreeGeometryRelease>;

}  // namespace rtpro
