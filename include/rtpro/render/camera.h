#pragma once
// Camera rays from the render scene's camera. Pixel coordinates are continuous, (0,0) at the
// image's top-left corner; the film point comes from the sampler's pixel dimensions and the lens
// point from its lens dimensions (sample_dimensions.h).
#include "rtpro/core/ray.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_camera.h"

#include <emmintrin.h>

#include <limits>

namespace rtpro {

// Shirley and Chiu's concentric map of [0,1)² onto the unit disk: strata stay compact and the
// map is area-preserving, so stratified lens samples stay stratified.
Sample2D concentric_disk(Sample2D square);

// The ray through film point (px, py). With a lens (lens_radius > 0) it leaves the point of the
// lens disk that `lens` ([0,1)², stratified) maps to and passes through the film point's image on
// the plane in focus, so points on that plane stay sharp and others blur by the thin-lens circle
// of confusion. With lens_radius 0 `lens` is unused: the pinhole ray. An orthographic camera's ray
// leaves the film point's place on the plane through the camera, along `forward`.
// Inline: one call per camera sample, and a ray returned through memory was copied into the batch
// with 16-byte loads over the callee's 4-byte stores (a store-forwarding stall per sample).
inline Ray camera_ray(const RenderCamera& camera, float px, float py, Sample2D lens) {
  const float x = (2.0f * px * camera.inv_width - 1.0f) * camera.half_width;
  const float y = (1.0f - 2.0f * py * camera.inv_height) * camera.half_height;
  Ray ray;
  if (camera.orthographic) {
    ray.org = camera.position + camera.right * x + camera.true_up * y;
    ray.dir = camera.forward;
    return ray;
  }
  // The film point's direction at distance 1 along `forward`.
  const Vec3 through = camera.forward + camera.right * x + camera.true_up * y;
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

// Four pinhole rays (perspective, lens_radius 0) through film points (px[i], py[i]) into `rays[0..3]`: camera_ray's
// operations in its order, four lanes at a time in SSE2 registers (IEEE operations are exact per
// lane), so each ray is camera_ray's bit for bit. The square root and the three divisions of each
// direction's normalisation were a latency chain per sample; four lanes run one chain for four.
inline void pinhole_rays4(const RenderCamera& camera, const float* px, const float* py, Ray* rays) {
  const __m128 x =
      _mm_mul_ps(_mm_sub_ps(_mm_mul_ps(_mm_mul_ps(_mm_set1_ps(2.0f), _mm_loadu_ps(px)), _mm_set1_ps(camera.inv_width)),
                            _mm_set1_ps(1.0f)),
                 _mm_set1_ps(camera.half_width));
  const __m128 y = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(1.0f), _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(2.0f), _mm_loadu_ps(py)),
                                                                       _mm_set1_ps(camera.inv_height))),
                              _mm_set1_ps(camera.half_height));
  // forward + right·x + true_up·y, one coordinate at a time.
  auto through = [&](float forward, float right, float up) {
    return _mm_add_ps(_mm_add_ps(_mm_set1_ps(forward), _mm_mul_ps(_mm_set1_ps(right), x)),
                      _mm_mul_ps(_mm_set1_ps(up), y));
  };
  const __m128 tx = through(camera.forward.x, camera.right.x, camera.true_up.x);
  const __m128 ty = through(camera.forward.y, camera.right.y, camera.true_up.y);
  const __m128 tz = through(camera.forward.z, camera.right.z, camera.true_up.z);
  const __m128 len = _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(tx, tx), _mm_mul_ps(ty, ty)), _mm_mul_ps(tz, tz)));
  alignas(16) float dx[4], dy[4], dz[4];
  _mm_store_ps(dx, _mm_div_ps(tx, len));
  _mm_store_ps(dy, _mm_div_ps(ty, len));
  _mm_store_ps(dz, _mm_div_ps(tz, len));
  for (int i = 0; i < 4; ++i) {
    Ray& ray = rays[i];
    ray.org.x = camera.position.x;
    ray.org.y = camera.position.y;
    ray.org.z = camera.position.z;
    ray.tnear = 0.0f;
    ray.dir.x = dx[i];
    ray.dir.y = dy[i];
    ray.dir.z = dz[i];
    ray.tfar = std::numeric_limits<float>::infinity();
  }
}

}  // namespace rtpro
