#pragma once
// A heterogeneous medium from an OpenVDB file (a world `volume` entry), as the renderer reads it:
// the placed grids (volume/grid_volume.h) and the optical parameters per unit of density. The
// path integrator's grid kind takes at a point σ_a and σ_s × the density there, and along a ray the
// density's majorant segments scaled by max_component(σ_a + σ_s).
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"
#include "rtpro/scene/volume_desc.h"
#include "rtpro/volume/grid_volume.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

namespace rtpro {

struct GridMedium {
  std::shared_ptr<const GridVolume> grid;
  Color sigma_a{0.0f}, sigma_s{0.0f};  // per scene unit per unit of density
  float anisotropy = 0.0f;
  Color emission{0.0f};  // radiance per scene unit of length per unit of the emission grid
  float temperature_scale = 1.0f;
  std::string file;  // for `rtpro info` and messages
  std::string grid_name;
};

// The volume object's boundary (a world `volume` entry has no surface): the density's majorant
// box, half a voxel wider, placed in the world, twelve triangles wound outward (a mirroring transform is rewound), all
// of `material`, an index-matched interface whose interior is the medium. Empty when the grid
// holds no density.
TriangleMesh bounding_box_mesh(const GridMedium& medium, std::uint32_t material);

// Reads the entry's grids (InputError at the entry, naming the file and grid, for what
// read_vdb_grids refuses, a grid larger than `max_bytes` among them) and places them by its
// transform.
GridMedium make_grid_medium(const VolumeDesc& desc,
                            std::uint64_t max_bytes = std::numeric_limits<std::uint64_t>::max());

// The bytes reading the entry's grids needs at most, from the file's grid metadata (the same
// errors as make_grid_medium for what the metadata shows).
std::uint64_t estimate_grid_medium_bytes(const VolumeDesc& desc);

}  // namespace rtpro
