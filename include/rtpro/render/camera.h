#pragma once
// Camera rays from the render scene's camera. Pixel coordinates are continuous, (0,0) at the
// image's top-left corner; the film point comes from the sampler's pixel dimensions and the lens
// point from its lens dimensions (sample_dimensions.h).
#include "rtpro/core/ray.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_camera.h"

namespace rtpro {

// The ray through film point (px, py). With a lens (lens_radius > 0) it leaves the point of the
// lens disk that `lens` ([0,1)², stratified) maps to and passes through the film point's image on
// the plane in focus, so points on that plane stay sharp and others blur by the thin-lens circle
// of confusion. With lens_radius 0 `lens` is unused: the pinhole ray.
Ray camera_ray(const RenderCamera& camera, float px, float py, Sample2D lens);

// Shirley and Chiu's concentric map of [0,1)² onto the unit disk: strata stay compact and the
// map is area-preserving, so stratified lens samples stay stratified.
Sample2D concentric_disk(Sample2D square);

}  // namespace rtpro
