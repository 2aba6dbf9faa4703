#include "sheen.h"

#include "rtpro/core/math_constants.h"
#include "energy_tables.h"
#include "table_coordinate.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtpro {
namespace {

constexpr float kMinRoughness = 0.07f;

// The paper's fit of the exponent of Λ, interpolated between its fits at α = 0 and α = 1.
float lambda_exponent(float x, float alpha) {
  const float t = (1.0f - alpha) * (1.0f - alpha);
  const float a = (1.0f - t) * 21.5473f + t * 25.3245f;
  const float b = (1.0f - t) * 3.82987f + t * 3.32435f;
  const float c = (1.0f - t) * 0.19823f + t * 0.16801f;
  const float d = (1.0f - t) * -1.97760f + t * -1.27393f;
  const float e = (1.0f - t) * -4.32054f + t * -4.85967f;
  return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}

// The tables: E and Ē at kMuNodes nodes evenly spaced in √μ (E rises steeply at grazing
// incidence) by kRoughnessNodes evenly spaced in roughness. Node values by a fixed midpoint rule
// over (x, φ) with μi = x², which puts the nodes near the horizon where the lobe lives; the
// integrand is mirror-symmetric in φ about wo's plane, so half the circle is integrated and
// doubled. The lookups agree with a fine integration to 3e-3 between the nodes (sheen_test.cpp).
constexpr int kMuNodes = kSheenMuNodes;
constexpr int kRoughnessNodes = kSheenRoughnessNodes;
constexpr int kSheenQuadrature = 64;
constexpr float kSheenGrazingMu = 1e-4f;

float mu_node(int m) {
  const float x = static_cast<float>(m) / (kMuNodes - 1);
  return std::max(kSheenGrazingMu, x * x);
}

float quadrature_mu(int i) {
  const double x = (i + 0.5) / kSheenQuadrature;
  return static_cast<float>(x * x);
}

// ∫ eval · μi dφ over the row of quadrature points at μi = x², times dμi/dx = 2x, per row.
std::array<double, kSheenQuadrature> row_integrals(const CharlieSheen& sheen, float mu) {
  const Vec3 wo{std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
  std::array<double, kSheenQuadrature> rows{};
  for (int i = 0; i < kSheenQuadrature; ++i) {
    const float mu_i = quadrature_mu(i);
    const float sin_i = std::sqrt(std::max(0.0f, 1.0f - mu_i * mu_i));
    double row = 0.0;
    for (int j = 0; j < kSheenQuadrature; ++j) {
      const float phi = kPi * (static_cast<float>(j) + 0.5f) / kSheenQuadrature;
      row += sheen.eval(wo, Vec3{sin_i * std::cos(phi), sin_i * std::sin(phi), mu_i});
    }
    // dx = 1/n, dφ = π/n, twice for the other half of the circle.
    rows[i] = row * mu_i * 2.0 * std::sqrt(static_cast<double>(mu_i)) * 2.0 * kPi /
              (static_cast<double>(kSheenQuadrature) * kSheenQuadrature);
  }
  return rows;
}

TableCoordinate mu_coordinate(float mu) { return sqrt_spaced_coordinate(mu, kMuNodes); }

// Below kMinRoughness the lobe is the one at kMinRoughness, so the nodes start there.
float roughness_node(int r) {
  return kMinRoughness + (1.0f - kMinRoughness) * static_cast<float>(r) / (kRoughnessNodes - 1);
}

TableCoordinate roughness_coordinate(float roughness) {
  const float scaled =
      (std::clamp(roughness, kMinRoughness, 1.0f) - kMinRoughness) / (1.0f - kMinRoughness) * (kRoughnessNodes - 1);
  const int index = std::min(static_cast<int>(scaled), kRoughnessNodes - 2);
  return {index, scaled - static_cast<float>(index)};
}

float along_mu(const std::array<float, kMuNodes>& row, float mu) {
  const TableCoordinate m = mu_coordinate(mu);
  return table_lerp(m.fraction, row[m.index], row[m.index + 1]);
}

// What the bounded lobe divides by. The margin covers the tables' interpolation, which can
// underestimate E by a few percent where it peaks (grazing, smoothest sheens).
constexpr float kBoundMargin = 1.05f;
float albedo_bound(float e_o, float e_i) { return std::max(1.0f, kBoundMargin * std::max(e_o, e_i)); }

float lookup(const std::array<std::array<float, kMuNodes>, kRoughnessNodes>& table, float mu, float roughness) {
  const TableCoordinate r = roughness_coordinate(roughness);
  return table_lerp(r.fraction, along_mu(table[r.index], mu), along_mu(table[r.index + 1], mu));
}

}  // namespace

// Per roughness node: E from the rows, then Ē from the same rows divided by the bound, which
// needs E at every quadrature μi of this roughness, i.e. the node row just made.
SheenAlbedoTables integrate_sheen_albedo_tables() {
  SheenAlbedoTables tables;
  for (int r = 0; r < kRoughnessNodes; ++r) {
    const CharlieSheen sheen{sheen_roughness_to_alpha(roughness_node(r))};
    std::array<std::array<double, kSheenQuadrature>, kMuNodes> rows;
    for (int m = 0; m < kMuNodes; ++m) {
      rows[m] = row_integrals(sheen, mu_node(m));
      double sum = 0.0;
      for (double row : rows[m]) sum += row;
      tables.raw[r][m] = static_cast<float>(sum);
    }
    for (int m = 0; m < kMuNodes; ++m) {
      double sum = 0.0;
      for (int i = 0; i < kSheenQuadrature; ++i)
        sum += rows[m][i] / albedo_bound(tables.raw[r][m], along_mu(tables.raw[r], quadrature_mu(i)));
      tables.bounded[r][m] = static_cast<float>(sum);
    }
  }
  return tables;
}

float sheen_roughness_to_alpha(float roughness) {
  const float r = std::clamp(roughness, kMinRoughness, 1.0f);
  return r * r;
}

float CharlieSheen::d(const Vec3& wm) const {
  const float sin2 = std::max(0.0f, 1.0f - wm.z * wm.z);
  const float inv_alpha = 1.0f / alpha;
  return (2.0f + inv_alpha) * std::pow(sin2, 0.5f * inv_alpha) / (2.0f * kPi);
}

float CharlieSheen::lambda(float abs_cos_theta) const {
  const float mu = std::clamp(abs_cos_theta, 0.0f, 1.0f);
  if (mu < 0.5f) return std::exp(lambda_exponent(mu, alpha));
  return std::exp(2.0f * lambda_exponent(0.5f, alpha) - lambda_exponent(1.0f - mu, alpha));
}

float CharlieSheen::eval(const Vec3& wo, const Vec3& wi) const {
  const float cos_o = std::fabs(wo.z), cos_i = std::fabs(wi.z);
  if (wo.z * wi.z <= 0.0f) return 0.0f;
  const Vec3 half = wo + wi;
  const float half_length2 = dot(half, half);
  if (half_length2 == 0.0f) return 0.0f;
  const Vec3 wm = half / std::sqrt(half_length2);
  const float g = 1.0f / (1.0f + lambda(cos_o) + lambda(cos_i));
  return d(wm) * g / (4.0f * cos_o * cos_i);
}

float sheen_directional_albedo(float mu, float roughness) { return lookup(sheen_albedo_tables().raw, mu, roughness); }

SheenLobe::SheenLobe(float roughness)
    : roughness_(std::clamp(roughness, 0.0f, 1.0f)), charlie_{sheen_roughness_to_alpha(roughness)} {}

float SheenLobe::eval(const Vec3& wo, const Vec3& wi) const {
  const float f = charlie_.eval(wo, wi);
  if (f == 0.0f) return 0.0f;
  return f / albedo_bound(sheen_directional_albedo(std::fabs(wo.z), roughness_),
                          sheen_directional_albedo(std::fabs(wi.z), roughness_));
}

float SheenLobe::albedo(float mu) const { return lookup(sheen_albedo_tables().bounded, mu, roughness_); }

}  // namespace rtpro
