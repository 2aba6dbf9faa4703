#pragma once
// The energy tables that the GGX and sheen lobes look up: the GGX albedo behind the conductor's
// multiple-scattering compensation (microfacet.cpp), its Schlick split (specular_albedo.cpp) and
// the sheen lobe's albedos (sheen.cpp). Each module integrates its table (integrate_*), but renders
// read the values shipped in energy_table_data.cpp: integrating them took 0.4–0.7 s of one core
// before a principled material's first sample, in every process, while the other threads waited.
// energy_tables_test.cpp integrates them again and checks the shipped values; after a change to an
// integrand, `cmake --build build --target update-energy-tables` writes the data anew.
#include <array>

namespace rtpro {

// E(μ, α) at nodes evenly spaced in √α (rows) and √μ (columns), and E_avg(α) per row.
inline constexpr int kGgxAlbedoNodes = 32;
struct GgxAlbedoTable {
  std::array<std::array<float, kGgxAlbedoNodes>, kGgxAlbedoNodes> e{};
  std::array<float, kGgxAlbedoNodes> e_average{};
};

// E₁ and E₅, the albedo weighted by 1 and by Schlick's (1 − c)⁵, on the same nodes.
inline constexpr int kSpecularAlbedoNodes = 32;
struct SpecularAlbedoNode {
  float e1 = 0.0f, e5 = 0.0f;
};
struct SpecularAlbedoTable {
  std::array<std::array<SpecularAlbedoNode, kSpecularAlbedoNodes>, kSpecularAlbedoNodes> e{};
  std::array<SpecularAlbedoNode, kSpecularAlbedoNodes> average{};
};

// The sheen lobe's E (raw) and Ē (bounded) at roughness nodes (rows) by nodes evenly spaced in √μ.
inline constexpr int kSheenMuNodes = 32;
inline constexpr int kSheenRoughnessNodes = 32;
struct SheenAlbedoTables {
  std::array<std::array<float, kSheenMuNodes>, kSheenRoughnessNodes> raw{};
  std::array<std::array<float, kSheenMuNodes>, kSheenRoughnessNodes> bounded{};
};

// The shipped tables (energy_table_data.cpp).
const GgxAlbedoTable& ggx_albedo_table();
const SpecularAlbedoTable& specular_albedo_table();
const SheenAlbedoTables& sheen_albedo_tables();

// The same tables integrated now, by a fixed quadrature (no random numbers): what the shipped ones
// were made from.
GgxAlbedoTable integrate_ggx_albedo_table();
SpecularAlbedoTable integrate_specular_albedo_table();
SheenAlbedoTables integrate_sheen_albedo_tables();

}  // namespace rtpro
