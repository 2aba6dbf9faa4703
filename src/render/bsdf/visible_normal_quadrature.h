#pragma once
// The deterministic integral the microfacet albedo tables are made by: a midpoint rule over the
// visible-normal sampler's square, with u.x = 1 − v² (du.x = 2v dv), so that at v → 0 the disk's
// rim, which maps to the steep facets that send light back into the surface, is sampled densely.
// Returns (1/n²) Σ_facets per_normal(wm) · 2v: the mean of per_normal over visible normals.
#include "microfacet.h"

namespace rtpro {

template <class PerNormal>
double visible_normal_quadrature(const GgxDistribution& ggx, const Vec3& wo, int n, PerNormal&& per_normal) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = (i + 0.5) / n;
    double row = 0.0;
    for (int j = 0; j < n; ++j) {
      const Sample2D u{static_cast<float>(1.0 - v * v), (static_cast<float>(j) + 0.5f) / n};
      row += per_normal(ggx.sample_visible_normal(wo, u));
    }
    sum += 2.0 * v * row;
  }
  return sum / (static_cast<double>(n) * n);
}

}  // namespace rtpro
