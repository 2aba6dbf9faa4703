#pragma once
// How far a render may differ from its reference (always a native render) before the regression
// test fails. The numbers, what was measured and why they are what they are:
// tests/references/README.md. Keep the two in step.
#include "rtpro/backend/backend.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/scene/render_scene.h"

#include <string>
#include <variant>

namespace rtpro::regression {

struct Tolerance {
  std::string rule;  // which row of the README's table applies
  CompareThresholds thresholds;
};

// Whether every primitive is a sphere in the top-level group: then both backends call the same
// intersect_sphere with the same floats and their images are bit-identical by design.
inline bool top_level_spheres_only(const RenderScene& scene) {
  for (const Geometry& geometry : scene.top.geometries)
    if (!std::holds_alternative<SphereSet>(geometry)) return false;
  return true;
}

inline bool has_curves(const RenderScene& scene) {
  const auto in = [](const Group& group) {
    for (const Geometry& geometry : group.geometries)
      if (std::holds_alternative<CurveSet>(geometry)) return true;
    return false;
  };
  if (in(scene.top)) return true;
  for (const Group& prototype : scene.prototypes)
    if (in(prototype)) return true;
  return false;
}

inline Tolerance tolerance_for(BackendKind backend, const RenderScene& scene) {
  // Bit-identical on one machine; 1e-5 (about 170 float steps at 1.0) absorbs last-bit
  // differences of libm variants on other CPUs without hiding any change a person could see.
  // Every pixel must stay within it: a regression may touch only a few pixels.
  CompareThresholds exact;
  exact.fail = exact.warn = 1e-5f;
  exact.fail_percent = 0.0;
  if (backend == BackendKind::kNative) return {"native", exact};
  if (top_level_spheres_only(scene)) return {"embree, top-level spheres only", exact};

  // Embree rounds triangle and instance hits differently: shading moves by rounding noise (up to
  // 6e-4 measured) and now and then one sample of an edge pixel hits the other primitive (a jump
  // of 1e-3 and more). The threshold separates the two; the pixel share bounds the edge flips and
  // the mean error catches a shift of the whole image that stays under the threshold everywhere.
  // Curves differ by construction, within a stated share of their radius (docs/backends.md): every
  // fibre's silhouette and ends move a little, so a few percent of a furry image's pixels differ, and
  // under the path integrator a path that meets another fibre goes on elsewhere.
  if (has_curves(scene)) {
    CompareThresholds curves;
    curves.fail = curves.warn = 1e-3f;
    curves.fail_percent = 10.0;
    curves.max_mean_error = 8e-4;
    return {"embree, curves", curves};
  }
  CompareThresholds meshes;
  meshes.fail = meshes.warn = 1e-3f;
  meshes.fail_percent = 0.1;
  meshes.max_mean_error = 5e-5;
  return {"embree, meshes or instances", meshes};
}

}  // namespace rtpro::regression
