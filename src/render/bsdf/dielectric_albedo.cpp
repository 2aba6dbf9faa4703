#include "dielectric_albedo.h"

#include "dielectric.h"
#include "microfacet.h"
#include "table_coordinate.h"
#include "visible_normal_quadrature.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace rtpro {
namespace {

// The layout of microfacet.cpp's table: nodes evenly spaced in √μ and √α, where E changes
// fastest (grazing incidence, small α). Over the index, nodes evenly spaced in √t: from inside,
// the critical angle sweeps fastest through the lobes near η = 1 (24 nodes keep the
// interpolation within 3e-3 of the integral at 1/1.2; 16 in t left 1.6e-2).
constexpr int kGlassTableSize = 32;
constexpr int kGlassEtaNodes = 24;
constexpr int kGlassQuadrature = 32;
constexpr float kGlassGrazingMu = 1e-4f;  // μ = 0 itself is degenerate; the node holds the limit

using GlassTable = std::array<std::array<float, kGlassTableSize>, kGlassTableSize>;  // [√α node][√μ node]

struct GlassEtaNode {
  GlassTable entering;  // η' ≥ 1
  GlassTable leaving;   // 1/η'
};

constexpr int kGlassFresnelModels = 2;

float glass_node_coordinate(int i) { return static_cast<float>(i) / (kGlassTableSize - 1); }

// η' from √t; the last node, t = 1, is an infinite index, held at a large one.
float glass_eta_of_node(int k) {
  const float root_t = static_cast<float>(k) / (kGlassEtaNodes - 1);
  const float t = std::min(root_t * root_t, 0.999f);
  return (1.0f + t) / (1.0f - t);
}

// Rows in parallel, each a pure function of its node: the same table on every run. Isolated, so
// a thread waiting here for its rows never picks up a render task that asks for this very table.
GlassTable build_glass_table(float eta, GlassFresnel fresnel) {
  GlassTable table{};
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(tbb::blocked_range<int>(1, kGlassTableSize), [&](const tbb::blocked_range<int>& rows) {
      for (int a = rows.begin(); a != rows.end(); ++a) {
        const float alpha = glass_node_coordinate(a) * glass_node_coordinate(a);
        for (int m = 0; m < kGlassTableSize; ++m) {
          const float mu = std::max(kGlassGrazingMu, glass_node_coordinate(m) * glass_node_coordinate(m));
          table[a][m] = integrate_rough_dielectric_albedo(mu, alpha, eta, fresnel, kGlassQuadrature);
        }
      }
    });
  });
  table[0].fill(1.0f);  // α = 0: a smooth interface reflects R and refracts 1 − R
  return table;
}

// Built on first use, once per node, by whichever thread asks first: the values are a pure
// function of the node, so which thread builds them changes nothing.
const GlassEtaNode& glass_eta_node(int k, GlassFresnel fresnel) {
  static std::array<std::once_flag, kGlassEtaNodes * kGlassFresnelModels> built;
  static std::array<std::unique_ptr<const GlassEtaNode>, kGlassEtaNodes * kGlassFresnelModels> nodes;
  const int slot = k * kGlassFresnelModels + static_cast<int>(fresnel);
  std::call_once(built[slot], [slot, k, fresnel] {
    const float eta = glass_eta_of_node(k);
    nodes[slot] = std::make_unique<const GlassEtaNode>(
        GlassEtaNode{build_glass_table(eta, fresnel), build_glass_table(1.0f / eta, fresnel)});
  });
  return *nodes[slot];
}

float fresnel_of(GlassFresnel model, float cos_incident, float eta) {
  switch (model) {
    case GlassFresnel::kExact: return fresnel_dielectric(cos_incident, eta);
    case GlassFresnel::kSchlick: return schlick_glass_fresnel(cos_incident, eta);
  }
  return 1.0f;  // unreachable: the switch covers every model
}

float glass_bilinear(const GlassTable& table, const TableCoordinate& m, const TableCoordinate& a) {
  const float lower = table_lerp(m.fraction, table[a.index][m.index], table[a.index][m.index + 1]);
  const float upper = table_lerp(m.fraction, table[a.index + 1][m.index], table[a.index + 1][m.index + 1]);
  return table_lerp(a.fraction, lower, upper);
}

// Where index η' = max(η, 1/η) falls among the nodes: the lower node k and the position scaled to
// node units, whose fraction past k weighs node k + 1.
struct EtaCoordinate {
  int k;
  float scaled;
};
EtaCoordinate eta_coordinate(float index) {
  const float scaled = std::sqrt(std::clamp((index - 1.0f) / (index + 1.0f), 0.0f, 1.0f)) * (kGlassEtaNodes - 1);
  return {std::min(static_cast<int>(scaled), kGlassEtaNodes - 2), scaled};
}

}  // namespace

float schlick_glass_fresnel(float cos_incident, float eta) {
  const float f0 = ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f));
  float c = cos_incident;
  if (eta < 1.0f) {
    const float sin2_t = (1.0f - c * c) / (eta * eta);
    if (sin2_t >= 1.0f) return 1.0f;
    c = std::sqrt(1.0f - sin2_t);
  }
  return f0 + (1.0f - f0) * schlick_weight(c);
}

float integrate_rough_dielectric_albedo(float mu, float alpha, float eta, GlassFresnel fresnel, int quadrature) {
  const GgxDistribution ggx{alpha};
  const Vec3 wo{std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
  const float g1_wo = ggx.g1(wo);
  const double mean = visible_normal_quadrature(ggx, wo, quadrature, [&](const Vec3& wm) {
    const float r = fresnel_of(fresnel, dot(wo, wm), eta);
    float value = 0.0f;
    const Vec3 reflected = -reflect(wo, wm);
    if (reflected.z > 0.0f) value += r * ggx.g(wo, reflected);
    const std::optional<Vec3> refracted = refract(-wo, wm, eta);
    if (refracted && refracted->z < 0.0f) value += (1.0f - r) * ggx.g(wo, *refracted);
    return value;
  });
  return static_cast<float>(mean / g1_wo);
}

void prepare_rough_dielectric_albedo(std::span<const RoughInterface> interfaces) {
  std::vector<std::pair<int, GlassFresnel>> nodes;
  for (const RoughInterface& interface : interfaces) {
    const int k = eta_coordinate(interface.ior >= 1.0f ? interface.ior : 1.0f / interface.ior).k;
    for (const int node : {k, k + 1}) nodes.emplace_back(node, interface.fresnel);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  // Each node on a thread of its own, its rows spread further where threads are left (build_glass_table).
  tbb::parallel_for(std::size_t{0}, nodes.size(),
                    [&](std::size_t i) { glass_eta_node(nodes[i].first, nodes[i].second); });
}

float rough_dielectric_albedo(float mu, float alpha, float eta, GlassFresnel fresnel) {
  if (GgxDistribution{alpha}.effectively_smooth()) return 1.0f;
  const bool entering = eta >= 1.0f;
  const auto [k, scaled] = eta_coordinate(entering ? eta : 1.0f / eta);
  const TableCoordinate m = sqrt_spaced_coordinate(mu, kGlassTableSize);
  const TableCoordinate a = sqrt_spaced_coordinate(alpha, kGlassTableSize);
  const auto side = [&](int node) {
    const GlassEtaNode& n = glass_eta_node(node, fresnel);
    return glass_bilinear(entering ? n.entering : n.leaving, m, a);
  };
  return table_lerp(scaled - static_cast<float>(k), side(k), side(k + 1));
}

}  // namespace rtpro
