#include "scene_materials.h"

#include "rtpro/core/error.h"
#include "rtpro/core/overloaded.h"
#include "material_textures.h"

#include <cmath>
#include <variant>

namespace rtpro {

namespace {

// The surface model and the Whitted approximation of a material, each its kind's own
// (scene/phong_material.h and its neighbours; scene/material_kinds.h asks each kind for them).
SurfaceModel surface_model(const MaterialDesc& m, std::vector<TextureImage>& textures) {
  return std::visit([&](const auto& params) -> SurfaceModel { return surface_model_from(params, m, textures); },
                    m.params);
}

WhittedMaterial whitted_material(const MaterialDesc& m, const ColorTexture& base_color) {
  return std::visit([&](const auto& params) { return whitted_approximation_of(params, m, base_color); }, m.params);
}

// What the Whitted integrator shows of a medium inside glass or an interface: absorption only, by
// its extinction (what it scatters away counts as lost), as the glass's transmittance over a
// distance; a grid's at its mean density over its box.
void show_to_whitted(const Medium& medium, Dielectric& glass) {
  const auto beer_lambert = [&](const Color& sigma_t) {
    glass.transmittance = {std::exp(-sigma_t.x), std::exp(-sigma_t.y), std::exp(-sigma_t.z)};
    glass.transmittance_distance = 1.0f;
  };
  std::visit(Overloaded{[&](const HomogeneousMedium& m) { beer_lambert(m.sigma_a + m.sigma_s); },
                        [&](const AbsorbingMedium& m) {
                          glass.transmittance = m.transmittance;
                          glass.transmittance_distance = m.distance;
                        },
                        [&](const GridMedium& m) { beer_lambert((m.sigma_a + m.sigma_s) * m.grid->mean_density); }},
             medium);
}

}  // namespace

std::uint32_t SceneMaterials::add(const MaterialDesc& m, const std::string& name) {
  Material material;
  material.base_color = color_texture(m, m.color, scene_.textures);
  material.model = surface_model(m, scene_.textures);
  material.emission =
      Emission{m.emission, m.emission_two_sided, slot_texture(m.emission_texture, Color(1.0f), scene_.textures)};
  material.whitted = whitted_material(m, material.base_color);
  material.index_matched = std::holds_alternative<InterfaceSurface>(material.model);
  material.interior = interior_medium(m, material);
  if (m.interior && material.whitted.glass) show_to_whitted(*m.interior, *material.whitted.glass);
  scene_.materials.push_back(std::move(material));
  scene_.material_names.push_back(name);
  return static_cast<std::uint32_t>(scene_.materials.size() - 1);
}

MediumIndex SceneMaterials::add_medium(const Medium& medium) {
  if (scene_.media.size() == kNoMedium)
    throw InputError("the scene has more than " + std::to_string(kNoMedium) +
                     " media (interiors, tinted glass and the world's medium together): the most a scene holds");
  scene_.media.push_back(medium);
  return static_cast<MediumIndex>(scene_.media.size() - 1);
}

std::uint32_t SceneMaterials::add_volume_boundary(std::size_t v) {
  MaterialDesc boundary;
  boundary.name = "volume " + std::to_string(v);
  boundary.params = InterfaceParams{};
  const std::uint32_t index = add(boundary, boundary.name);
  Material& material = scene_.materials[index];
  material.interior = scene_.volumes[v];
  if (material.whitted.glass) show_to_whitted(scene_.media[scene_.volumes[v]], *material.whitted.glass);
  return index;
}

// The medium a material's surface bounds: its `interior:`; else a glass's absorption (vacuum
// when clear) and an interface's vacuum; else none.
std::optional<MediumIndex> SceneMaterials::interior_medium(const MaterialDesc& m, const Material& material) {
  if (m.interior) return add_medium(*m.interior);
  if (const Dielectric* glass = interior_of(material)) {
    const std::optional<AbsorbingMedium> absorbing = glass_absorption(*glass);
    return absorbing ? add_medium(*absorbing) : kNoMedium;
  }
  if (material.index_matched) return kNoMedium;
  return std::nullopt;
}

}  // namespace rtpro
