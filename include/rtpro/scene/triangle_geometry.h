#pragma once
// Triangle meshes, the scene's side of the geometry kind in one place (as scene/sphere_geometry.h
// has it for spheres): the mesh itself is scene/mesh.h, what the scene needs of it is defined in
// src/scene/build/triangle_geometry.cpp, its intersector is geometry/triangle_intersect.h.
#include "rtpro/core/bbox.h"
#include "rtpro/scene/mesh.h"

#include <cstdint>

namespace rtpro {

struct ShapeTally;  // scene/scene_summary.h
struct SceneSummary;

std::uint32_t primitive_count_of(const TriangleMesh& mesh);
BBox primitive_bounds_of(const TriangleMesh& mesh, std::uint32_t prim);
BBox bounds_of(const TriangleMesh& mesh);
void tally_shapes(const TriangleMesh& mesh, ShapeTally& tally, SceneSummary& summary);

}  // namespace rtpro
