#pragma once
// What the backend tests that compare two ways of answering the same rays share: the rays, and
// the assertion that two answers are the same hit bit for bit.
#include "rtpro/backend/backend.h"
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace rtpro::test {

// `count` rays from random_ray (extent 6) drawn with `seed`; every third from the second on a
// segment ending at `segment_tfar`, as shadow rays to a point light are.
inline std::vector<Ray> scattered_rays(unsigned seed, int count, float segment_tfar) {
  std::mt19937 rng(seed);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray ray = random_ray(rng, 6.0f);
    if (i % 3 == 1) ray.tfar = segment_tfar;
    rays.push_back(ray);
  }
  return rays;
}

// The same hit bit for bit: distance, barycentrics and ids (misses alike).
inline void expect_same_hit(const Hit& a, const Hit& b, std::size_t i) {
  ASSERT_EQ(a.valid(), b.valid()) << "ray " << i;
  if (!a.valid()) return;
  const std::string ray =
      std::to_string(i) + " (geometry " + std::to_string(b.geom_id) + ", instance " + std::to_string(b.inst_id) + ")";
  EXPECT_EQ(a.t, b.t) << "ray " << ray;
  EXPECT_EQ(a.u, b.u) << "ray " << ray;
  EXPECT_EQ(a.v, b.v) << "ray " << ray;
  EXPECT_EQ(a.inst_id, b.inst_id) << "ray " << ray;
  EXPECT_EQ(a.geom_id, b.geom_id) << "ray " << ray;
  EXPECT_EQ(a.prim_id, b.prim_id) << "ray " << ray;
}

// Both backends' batched answers to `rays`, coherent and incoherent alike: the same hits bit for
// bit and the same occlusion.
inline void expect_same_batch_answers(const Backend& a, const Backend& b, const std::vector<Ray>& rays) {
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent}) {
    std::vector<Hit> hits_a(rays.size()), hits_b(rays.size());
    a.intersect(rays, hits_a, coherence);
    b.intersect(rays, hits_b, coherence);
    for (std::size_t i = 0; i < rays.size(); ++i) expect_same_hit(hits_a[i], hits_b[i], i);
    std::vector<std::uint8_t> occluded_a(rays.size()), occluded_b(rays.size());
    a.occluded(rays, occluded_a, coherence);
    b.occluded(rays, occluded_b, coherence);
    EXPECT_EQ(occluded_a, occluded_b);
  }
}

}  // namespace rtpro::test
