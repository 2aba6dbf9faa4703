#include "grid_medium.h"

#include "blackbody.h"

namespace rtpro {

MediumPoint medium_point(const GridMedium& medium, const Vec3& p) {
  const GridVolume& grid = *medium.grid;
  const float density = grid.density.at(p);
  Color emission(0.0f);
  if (grid.emission) emission = medium.emission * grid.emission->at(p);
  if (grid.temperature) emission += blackbody_emission(medium.temperature_scale * grid.temperature->at(p));
  return {medium.sigma_a * density, medium.sigma_s * density, emission, medium.anisotropy};
}

}  // namespace rtpro
