#pragma once
// A world entry `{type: volume, file: F.vdb, grid: density, ...}` (scenes/FORMAT.md, "Volumes"):
// a heterogeneous medium read from an OpenVDB file, with no surface: Blender's Volume object.
#include "rtpro/core/error.h"
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"

#include <filesystem>
#include <string>

namespace rtpro {

struct VolumeDesc {
  std::filesystem::path file;  // resolved against the folder of the scene file that names it
  SourceLocation where;        // the `file:` value, where errors in the file are reported
  std::string grid = "density";
  float density_scale = 1.0f;  // σ_t per scene unit = density_scale × the grid's value
  Color albedo{1.0f};          // σ_s / σ_t per channel
  float anisotropy = 0.0f;     // Henyey–Greenstein g
  // Emitted radiance per scene unit of length = emission × emission_scale × the grid's value.
  std::string emission_grid;  // empty: none
  Color emission{1.0f};
  float emission_scale = 1.0f;
  // A temperature grid (kelvin = temperature_scale × the grid's value), for blackbody emission.
  std::string temperature_grid;  // empty: none
  float temperature_scale = 1.0f;
  Affine transform;  // the file's space to the world, after the file's own index-to-world map
};

}  // namespace rtpro
