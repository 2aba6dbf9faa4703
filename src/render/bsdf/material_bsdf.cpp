#include "material_bsdf.h"

#include <variant>

namespace rtpro {

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
