#include "specular_albedo.h"

#include "energy_tables.h"
#include "table_coordinate.h"

#include "microfacet.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtpro {
namespace {

// The same layout and quadrature as microfacet.cpp's E table, for the same reasons: nodes evenly
// spaced in √μ and √α, where E changes fastest; node values from a fixed midpoint rule over the
// visible-normal sampler's unit square (no random numbers, the same table on every run). The
// (1 − c)⁵ weight is smooth on that square too, so E₅ converges as E₁ does.
constexpr int kSpecularTableSize = kSpecularAlbedoNodes;
constexpr int kSpecularQuadrature = 48;
constexpr float kSpecularGrazingMu = 1e-4f;

using Node = SpecularAlbedoNode;

float specular_node_coordinate(int i) { return static_cast<float>(i) / (kSpecularTableSize - 1); }

// E₁ and E₅ as expectations over visible normals: the integrand G(wo,wi)/G1(wo) times 1 or (1 − c)⁵.
Node integrate_node(float mu, float alpha) {
  const GgxDistribution ggx{alpha};
  const Vec3 wo{std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
  const float g1_wo = ggx.g1(wo);
  double e1 = 0.0, e5 = 0.0;
  for (int i = 0; i < kSpecularQuadrature; ++i) {
    const double v = (i + 0.5) / kSpecularQuadrature;
    double row1 = 0.0, row5 = 0.0;
    for (int j = 0; j < kSpecularQuadrature; ++j) {
      const Sample2D u{static_cast<float>(1.0 - v * v), (static_cast<float>(j) + 0.5f) / kSpecularQuadrature};
      const Vec3 wm = ggx.sample_visible_normal(wo, u);
      const Vec3 wi = -reflect(wo, wm);
      if (wi.z <= 0.0f) continue;
      const double shadowing = ggx.g(wo, wi) / g1_wo;
      row1 += shadowing;
      row5 += shadowing * schlick_weight(dot(wo, wm));
    }
    e1 += 2.0 * v * row1;  // du.x = 2v dv
    e5 += 2.0 * v * row5;
  }
  constexpr double kCells = static_cast<double>(kSpecularQuadrature) * kSpecularQuadrature;
  return {static_cast<float>(e1 / kCells), static_cast<float>(e5 / kCells)};
}

// 2∫E(μ)μ dμ = 4∫E(x)x³ dx (x = √μ) of the interpolant, linear in x on each segment: three-point
// Gauss-Legendre per segment integrates the degree-4 polynomial exactly.
Node average_of_interpolant(const std::array<Node, kSpecularTableSize>& e) {
  constexpr double kNode = 0.7745966692414834;  // √(3/5)
  constexpr std::array<double, 3> kNodes{-kNode, 0.0, kNode};
  constexpr std::array<double, 3> kWeights{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double h = 1.0 / (kSpecularTableSize - 1);
  double e1 = 0.0, e5 = 0.0;
  for (int m = 0; m + 1 < kSpecularTableSize; ++m)
    for (int q = 0; q < 3; ++q) {
      const double t = 0.5 * (1.0 + kNodes[q]);
      const double x = (m + t) * h;
      const double weight = kWeights[q] * 0.5 * h * x * x * x;
      e1 += weight * ((1.0 - t) * e[m].e1 + t * e[m + 1].e1);
      e5 += weight * ((1.0 - t) * e[m].e5 + t * e[m + 1].e5);
    }
  return {static_cast<float>(4.0 * e1), static_cast<float>(4.0 * e5)};
}

TableCoordinate specular_table_coordinate(float x) { return sqrt_spaced_coordinate(x, kSpecularTableSize); }

Node table_lerp(float t, const Node& a, const Node& b) {
  return {(1.0f - t) * a.e1 + t * b.e1, (1.0f - t) * a.e5 + t * b.e5};
}

SchlickAlbedo to_albedo(const Node& n) { return {std::max(0.0f, n.e1 - n.e5), n.e5}; }

}  // namespace

SpecularAlbedoTable integrate_specular_albedo_table() {
  SpecularAlbedoTable tables;
  for (int a = 0; a < kSpecularTableSize; ++a) {
    const float alpha = specular_node_coordinate(a) * specular_node_coordinate(a);
    for (int m = 0; m < kSpecularTableSize; ++m) {
      const float mu = std::max(kSpecularGrazingMu, specular_node_coordinate(m) * specular_node_coordinate(m));
      // α = 0: a mirror, where the facet normal is the macro normal.
      tables.e[a][m] = a == 0 ? Node{1.0f, schlick_weight(mu)} : integrate_node(mu, alpha);
    }
    tables.average[a] = average_of_interpolant(tables.e[a]);
  }
  return tables;
}

SchlickAlbedo ggx_schlick_albedo(float mu, float alpha) {
  if (GgxDistribution{alpha}.effectively_smooth()) {
    const float edge = schlick_weight(mu);
    return {1.0f - edge, edge};
  }
  const SpecularAlbedoTable& t = specular_albedo_table();
  const TableCoordinate m = specular_table_coordinate(mu);
  const TableCoordinate a = specular_table_coordinate(alpha);
  const Node lower = table_lerp(m.fraction, t.e[a.index][m.index], t.e[a.index][m.index + 1]);
  const Node upper = table_lerp(m.fraction, t.e[a.index + 1][m.index], t.e[a.index + 1][m.index + 1]);
  return to_albedo(table_lerp(a.fraction, lower, upper));
}

SchlickAlbedo ggx_schlick_average_albedo(float alpha) {
  // A mirror's average of (1 − μ)⁵ in closed form: 2∫(1 − μ)⁵ μ dμ = 1/21.
  if (GgxDistribution{alpha}.effectively_smooth()) return {20.0f / 21.0f, 1.0f / 21.0f};
  const SpecularAlbedoTable& t = specular_albedo_table();
  const TableCoordinate a = specular_table_coordinate(alpha);
  return to_albedo(table_lerp(a.fraction, t.average[a.index], t.average[a.index + 1]));
}

}  // namespace rtpro
