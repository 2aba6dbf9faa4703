#pragma once
// Moving a refined mesh's vertices along their limit normals (`displacement:`), then shading it
// with the normals of the displaced triangles.
#include "rtpro/scene/subdivision.h"
#include "subdivision_refine.h"

#include <string>
#include <vector>

namespace rtpro {

// The value a displacement texture holds at (u, v): bilinear between texels, repeating, v = 0 at
// the image's bottom row (OBJ's convention, which every mesh uses).
float sample_scalar_image(const ScalarImage& image, float u, float v);

// Each point of the surface moves by scale × value (the texture's at its texture coordinates, the
// copies of a vertex on a uv seam averaged so the surface stays closed) along its limit normal,
// clamped to ±bound when one is stated (a warning naming `where` counts the clamped vertices).
// Normals are then the area-weighted normals of the displaced triangles around each point.
// `image`: the texture, read; null for a constant.
void displace_mesh(RefinedMesh& refined, const DisplacementDesc& desc, const ScalarImage* image,
                   std::vector<std::string>& warnings);

}  // namespace rtpro
