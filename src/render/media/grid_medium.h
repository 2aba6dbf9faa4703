#pragma once
// The render side of a grid medium (scene/grid_medium.h, a world `volume` entry): σa and σs are
// its per-density coefficients times the trilinear density at the point, its majorant segments
// are the density's majorant grid walked by the DDA (volume/majorant_iterator.h) and scaled by the
// largest channel of σt per unit density, so tracking skips cells that are empty and takes long
// steps through thin ones. Its transmittance has no closed form: shadow rays ratio-track it.
//
// Emission is Cycles' Principled Volume's: an emission grid's value × `emission` (already times
// its scale), plus, from a temperature grid, blackbody radiance (render/media/blackbody.h). Both
// are radiance per unit length, not multiplied by the density; the tracking gathers them at its
// tentative collisions, so emission in a majorant cell whose density is 0 throughout is not seen.
#include "medium_interface.h"
#include "rtpro/scene/grid_medium.h"

#include <optional>

namespace rtpro {

MediumPoint medium_point(const GridMedium& medium, const Vec3& p);

// The DDA's segments as the tracking takes them; cells of majorant 0 are left out.
class GridMajorants {
 public:
  explicit GridMajorants(DdaMajorantIterator cells) : cells_(cells) {}
  std::optional<MajorantSegment> next() {
    RayMajorantSegment cell;
    if (!cells_.next(cell)) return std::nullopt;
    return MajorantSegment{cell.t_min, cell.t_max, cell.sigma_maj};
  }

 private:
  DdaMajorantIterator cells_;
};

inline GridMajorants majorants(const GridMedium& medium, const Ray& ray, float t_max) {
  return GridMajorants(medium.grid->majorants_along(ray, t_max, max_component(medium.sigma_a + medium.sigma_s), true));
}

inline bool only_absorbs(const GridMedium& medium) {
  const bool scatters = medium.sigma_s.x > 0.0f || medium.sigma_s.y > 0.0f || medium.sigma_s.z > 0.0f;
  return !scatters && !medium.grid->emission && !medium.grid->temperature;
}

inline std::optional<Color> closed_form_transmittance(const GridMedium&, const Ray&, float) { return std::nullopt; }

}  // namespace rtpro
