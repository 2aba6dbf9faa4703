#include "rtpro/scene/grid_medium.h"

#include "rtpro/core/printable_text.h"

#include <limits>
#include <utility>

namespace rtpro {

namespace {

VdbRequest request_of(const VolumeDesc& desc, std::uint64_t max_bytes = std::numeric_limits<std::uint64_t>::max()) {
  VdbRequest request;
  request.max_bytes = max_bytes;
  request.file = desc.file;
  request.where = desc.where;
  request.density = desc.grid;
  request.emission = desc.emission_grid;
  request.temperature = desc.temperature_grid;
  return request;
}

}  // namespace

GridMedium make_grid_medium(const VolumeDesc& desc, std::uint64_t max_bytes) {
  GridMedium medium;
  medium.grid = std::make_shared<const GridVolume>(
      place_grid_volume(read_vdb_grids(request_of(desc, max_bytes)), desc.transform, desc.where));
  // albedo = σs/σt with σt = density_scale per unit of density.
  medium.sigma_s = desc.albedo * desc.density_scale;
  medium.sigma_a = (Color(1.0f) - desc.albedo) * desc.density_scale;
  medium.anisotropy = desc.anisotropy;
  medium.emission = desc.emission * desc.emission_scale;
  medium.temperature_scale = desc.temperature_scale;
  medium.file = printable_text(desc.file.string());
  medium.grid_name = printable_text(desc.grid);
  return medium;
}

TriangleMesh bounding_box_mesh(const GridMedium& medium, std::uint32_t material) {
  TriangleMesh mesh;
  mesh.name = medium.file + ":" + medium.grid_name;
  mesh.material = material;
  const BBox& majorant_box = medium.grid->majorants.bounds();
  if (majorant_box.empty()) return mesh;
  // Half a voxel wider than the majorant grid, so that a ray enters the box a little before the
  // grid and the tracking's segments start and end where the DDA clips them, not where a backend
  // found the boundary (the backends round triangle hits differently; the images stay the same).
  const BBox box{majorant_box.lower - Vec3(0.5f), majorant_box.upper + Vec3(0.5f)};
  // Corner i has the box's upper x when bit 0 of i is set, upper y for bit 1, upper z for bit 2.
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? box.upper.x : box.lower.x, (i & 2) ? box.upper.y : box.lower.y,
                      (i & 4) ? box.upper.z : box.lower.z};
    const Vec3 p = medium.grid->density_to_world.apply_point(corner);
    mesh.vertices.push_back({p.x, p.y, p.z});
  }
  // Two triangles a face, counter-clockwise seen from outside (the geometric normal is
  // (v1 - v0) × (v2 - v0)): -x, +x, -y, +y, -z, +z.
  mesh.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  if (medium.grid->density_to_world.determinant() < 0.0f)
    for (TriangleIndices& t : mesh.triangles) std::swap(t.v1, t.v2);
  return mesh;
}

std::uint64_t estimate_grid_medium_bytes(const VolumeDesc& desc) { return estimate_vdb_bytes(request_of(desc)); }

}  // namespace rtpro
