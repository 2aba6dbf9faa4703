#pragma once
// The keys several kinds of material share in a scene file, read the same way for each (each
// kind's reader is its own file: yaml_phong_material.cpp and its neighbours).
#include "rtpro/scene/dielectric.h"
#include "yaml_reader.h"

namespace rtpro {

// `roughness`, from 0 (smooth) to 1.
void read_roughness(const MappingReader& material, float& roughness);
// `ior`, an index of refraction above 0 and at most 100, when the material has one.
void read_ior(const MappingReader& material, float& ior);
// `transmittance` and `transmittance_distance`: absorption inside glass.
void read_absorption(const MappingReader& material, Dielectric& glass);
// A weight or colour from 0 to 1 (in each channel), when the material has it.
void read_unit(const MappingReader& material, const char* key, float& value);
void read_unit_color(const MappingReader& material, const char* key, Color& value);

}  // namespace rtpro
