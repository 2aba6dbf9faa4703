#include "material_bsdf.h"

#include "dielectric_albedo.h"
#include "microfacet.h"

#include <optional>
#include <variant>
#include <vector>

namespace rtpro {

namespace {

// The interface whose energy albedo a kind's BSDF reads, if any: a rough one, or a smooth one that
// Filter Glossy may roughen (`roughened`). One overload per kind, so that a new kind says.
bool rough(float roughness, bool roughened) {
  return roughened || !GgxDistribution{roughness_to_alpha(roughness)}.effectively_smooth();
}
std::optional<RoughInterface> rough_interface(const DielectricSurface& d, bool roughened) {
  if (!rough(d.roughness, roughened)) return std::nullopt;
  return RoughInterface{d.glass.ior, GlassFresnel::kExact};
}
// Its transmission lobe (PrincipledBsdf): glass of the material's index, with Schlick's Fresnel.
// An image's roughness only scales the material's, so a smooth material stays smooth.
std::optional<RoughInterface> rough_interface(const PrincipledSurface& p, bool roughened) {
  if (!(p.transmission_weight > 0.0f) || !(p.ior > 1.0f) || !rough(p.roughness, roughened)) return std::nullopt;
  return RoughInterface{p.ior, GlassFresnel::kSchlick};
}
std::optional<RoughInterface> rough_interface(const PhongSurface&, bool) { return std::nullopt; }
std::optional<RoughInterface> rough_interface(const DiffuseSurface&, bool) { return std::nullopt; }
std::optional<RoughInterface> rough_interface(const ConductorSurface&, bool) { return std::nullopt; }
std::optional<RoughInterface> rough_interface(const HairSurface&, bool) { return std::nullopt; }
std::optional<RoughInterface> rough_interface(const InterfaceSurface&, bool) { return std::nullopt; }

}  // namespace

void prepare_material_bsdfs(const RenderScene& scene) {
  const bool roughened = scene.render.path.filter_glossy > 0.0f;
  std::vector<RoughInterface> interfaces;
  for (const Material& material : scene.materials)
    if (const std::optional<RoughInterface> interface =
            std::visit([&](const auto& model) { return rough_interface(model, roughened); }, material.model))
      interfaces.push_back(*interface);
  prepare_rough_dielectric_albedo(interfaces);
}

void material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures,
                   SurfaceBsdf& out) {
  // Each kind's own step (bsdf_from, in its render/bsdf/KIND_bsdf.h), written in place: a record
  // returned and then moved into the caller's was copied with wide loads over the narrow stores
  // that built it, a store-forwarding stall per vertex.
  const Vec3 normal = std::visit(
      [&](const auto& model) { return bsdf_from(model, material.base_color, point, textures, out); }, material.model);
  // Whether the BSDF tells the inside from the outside (it transmits): then its frame's +z is the
  // outside rather than the side the ray came from.
  const bool outward = std::visit([](const auto& b) { return b.needs_outward_frame(); }, out.bsdf);
  out.frame = ShadingFrame::from_normal(!outward || point.front_face ? normal : -normal);
}

}  // namespace rtpro
