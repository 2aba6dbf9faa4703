#include "microfacet.h"

#include "bsdf_sample.h"
#include "energy_tables.h"

#include "rtpro/core/math_constants.h"
#include "table_coordinate.h"
#include "visible_normal_quadrature.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtpro {
namespace {

float tan2_theta(const Vec3& w) {
  const float cos2 = w.z * w.z;
  return std::max(0.0f, 1.0f - cos2) / cos2;
}

// The table: E at kTableSize × kTableSize nodes, evenly spaced in √μ and √α (α above 1 clamped),
// because E changes fastest at grazing incidence and at small α: near μ ≈ α the facets' heights
// decide whether a reflection escapes. Node values come from a fixed midpoint rule over the
// visible-normal sampler's unit square, where E's integrand G(wo,wi)/G1(wo) is bounded and
// continuous (it fades to 0 at the horizon): no random numbers, the same table on every run, and
// about 5e-4 from the exact integral. u.x = 1 − v² with v uniform puts the nodes where they are
// needed: at v → 0 the disk's rim maps to the steep facets that send light into the surface.
constexpr int kTableSize = kGgxAlbedoNodes;
constexpr int kQuadrature = 48;
// μ = 0 itself is degenerate (Λ of a grazing direction is taken as 0); the node holds the limit.
constexpr float kGrazingMu = 1e-4f;

float node_coordinate(int i) { return static_cast<float>(i) / (kTableSize - 1); }

float single_scattering_albedo(float mu, float alpha) {
  const GgxDistribution ggx{alpha};
  const Vec3 wo{std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
  const float g1_wo = ggx.g1(wo);
  return static_cast<float>(visible_normal_quadrature(ggx, wo, kQuadrature, [&](const Vec3& wm) -> float {
    const Vec3 wi = -reflect(wo, wm);
    return wi.z > 0.0f ? ggx.g(wo, wi) / g1_wo : 0.0f;
  }));
}

// 2∫E(μ)μ dμ = 4∫E(x)x³ dx (x = √μ) of the interpolant, linear in x on each segment: three-point
// Gauss-Legendre per segment integrates the degree-4 polynomial exactly.
float average_of_interpolant(const std::array<float, kTableSize>& e) {
  constexpr double kNode = 0.7745966692414834;  // √(3/5)
  constexpr std::array<double, 3> kNodes{-kNode, 0.0, kNode};
  constexpr std::array<double, 3> kWeights{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double h = 1.0 / (kTableSize - 1);
  double integral = 0.0;
  for (int m = 0; m + 1 < kTableSize; ++m)
    for (int q = 0; q < 3; ++q) {
      const double t = 0.5 * (1.0 + kNodes[q]);
      const double x = (m + t) * h;
      integral += kWeights[q] * 0.5 * h * ((1.0 - t) * e[m] + t * e[m + 1]) * x * x * x;
    }
  return static_cast<float>(4.0 * integral);
}

TableCoordinate albedo_table_coordinate(float x) { return sqrt_spaced_coordinate(x, kTableSize); }

}  // namespace

GgxAlbedoTable integrate_ggx_albedo_table() {
  GgxAlbedoTable table;
  for (int a = 0; a < kTableSize; ++a) {
    const float alpha = node_coordinate(a) * node_coordinate(a);
    for (int m = 0; m < kTableSize; ++m) {
      const float mu = std::max(kGrazingMu, node_coordinate(m) * node_coordinate(m));
      table.e[a][m] = a == 0 ? 1.0f : single_scattering_albedo(mu, alpha);  // α = 0: a mirror
    }
    table.e_average[a] = average_of_interpolant(table.e[a]);
  }
  return table;
}

float roughness_to_alpha(float roughness) { return roughness * roughness; }

float GgxDistribution::d(const Vec3& wm) const {
  const float tan2 = tan2_theta(wm);
  if (std::isinf(tan2)) return 0.0f;
  const float cos4 = wm.z * wm.z * wm.z * wm.z;
  if (cos4 < 1e-16f) return 0.0f;
  const float alpha2 = alpha * alpha;
  const float e = 1.0f + tan2 / alpha2;
  return 1.0f / (kPi * alpha2 * cos4 * e * e);
}

float GgxDistribution::lambda(const Vec3& w) const {
  const float tan2 = tan2_theta(w);
  if (std::isinf(tan2)) return 0.0f;
  return (std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f) / 2.0f;
}

float GgxDistribution::visible_normal_pdf(const Vec3& w, const Vec3& wm) const {
  const float cos_w = std::fabs(w.z);
  const float facing = w.z < 0.0f ? -dot(w, wm) : dot(w, wm);
  if (cos_w == 0.0f || wm.z <= 0.0f || facing <= 0.0f) return 0.0f;
  return g1(w) / cos_w * d(wm) * facing;
}

Vec3 GgxDistribution::sample_visible_normal(const Vec3& w, Sample2D u) const {
  // Stretch to the configuration where the facets form a unit hemisphere, whose visible normals
  // are uniform over the projected half disk seen from wh.
  Vec3 wh = normalize(Vec3{alpha * w.x, alpha * w.y, w.z});
  if (wh.z < 0.0f) wh = -wh;
  const Vec3 t1 = wh.z < 0.99999f ? normalize(cross(Vec3{0.0f, 0.0f, 1.0f}, wh)) : Vec3{1.0f, 0.0f, 0.0f};
  const Vec3 t2 = cross(wh, t1);
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  float px = r * std::cos(phi);
  float py = r * std::sin(phi);
  // Squeeze the disk onto the visible part: the half disk plus the projected ellipse of the rest.
  const float h = std::sqrt(std::max(0.0f, 1.0f - px * px));
  py = table_lerp((1.0f + wh.z) / 2.0f, h, py);
  const float pz = std::sqrt(std::max(0.0f, 1.0f - px * px - py * py));
  const Vec3 nh = t1 * px + t2 * py + wh * pz;
  return normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)});
}

float ggx_directional_albedo(float mu, float alpha) {
  const GgxAlbedoTable& table = ggx_albedo_table();
  const TableCoordinate m = albedo_table_coordinate(mu);
  const TableCoordinate a = albedo_table_coordinate(alpha);
  const float lower = table_lerp(m.fraction, table.e[a.index][m.index], table.e[a.index][m.index + 1]);
  const float upper = table_lerp(m.fraction, table.e[a.index + 1][m.index], table.e[a.index + 1][m.index + 1]);
  return table_lerp(a.fraction, lower, upper);
}

float ggx_average_albedo(float alpha) {
  const GgxAlbedoTable& table = ggx_albedo_table();
  const TableCoordinate a = albedo_table_coordinate(alpha);
  return table_lerp(a.fraction, table.e_average[a.index], table.e_average[a.index + 1]);
}

std::optional<Vec3> reflection_normal(const Vec3& wo, const Vec3& wi) {
  const Vec3 half = wo + wi;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return std::nullopt;
  const Vec3 wm = half / std::sqrt(half_length2);
  return wm.z < 0.0f ? -wm : wm;
}

float microfacet_reflection(const GgxDistribution& ggx, const Vec3& wo, const Vec3& wi, const Vec3& wm) {
  return ggx.d(wm) * ggx.g(wo, wi) / (4.0f * abs_cos_theta(wo) * abs_cos_theta(wi));
}

float reflection_density(const GgxDistribution& ggx, const Vec3& wo, const Vec3& wm) {
  const float wo_dot_wm = std::fabs(dot(wo, wm));
  return wo_dot_wm == 0.0f ? 0.0f : ggx.visible_normal_pdf(wo, wm) / (4.0f * wo_dot_wm);
}

std::optional<Vec3> sample_reflection(const GgxDistribution& ggx, const Vec3& wo, Sample2D u) {
  const Vec3 wi = -reflect(wo, ggx.sample_visible_normal(wo, u));
  // Facets near the horizon reflect some directions into the surface: that light is lost to
  // single scattering (the albedo scaling hands it to the layers below).
  if (!same_hemisphere(wo, wi)) return std::nullopt;
  return wi;
}

}  // namespace rtpro
