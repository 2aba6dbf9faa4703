#pragma once
// Camera rays from the render scene's camera. Pixel coordinates are continuous, (0,0) at the
// image's top-left corner; the film point comes from the sampler's pixel dimensions and the lens
// point from its lens dimensions (sample_dimensions.h).
#include "rtpro/core/ray.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_camera.h"

namespace rtpro {

// Shirley and Chiu's concentric map of [0,1)² onto the unit disk: strata stay compact and the
// map is area-preserving, so stratified lens samples stay stratified.
Sample2D concentric_disk(Sample2D square);

// The ray through film point (px, py). With a lens (lens_radius > 0) it leaves the point of the
// lens disk that `lens` ([0,1)², stratified) maps to and passes through the film point's image on
// the plane in focus, so points on that plane stay sharp and others blur by the thin-lens circle
// of confusion. With lens_radius 0 `lens` is unused: the pinhole ray.
// Inline: one call per camera sample, and a ray returned through memory was copied into the batch
// with 16-byte loads over the callee's 4-byte stores (a store-forwarding stall per sample).
inline Ray camera_ray(const RenderCamera& camera, float px, float py, Sample2D lens) {
  const float x = (2.0f * px * camera.inv_width - 1.0f) * camera.half_width;
  const float y = (1.0f - 2.0f * py * camera.inv_height) * camera.half_height;
  // The film point's direction at distance 1 along `forward`.
  const Vec3 through = camera.forward + camera.right * x + camera.true_up * y;
  Ray ray;
  if (camera.lens_radius == 0.0f) {
    ray.org = camera.position;
    ray.dir = normalize(through);
    return ray;
  }
  const Sample2D disk = concentric_disk(lens);
  const Vec3 on_lens = (camera.right * disk.x + camera.true_up * disk.y) * camera.lens_radius;
  const Vec3 in_focus = through * camera.focus_distance;  // relative to the lens centre
  ray.org = camera.position + on_lens;
  ray.dir = normalize(in_focus - on_lens);
  return ray;
}

}  // namespace rtpro
