#pragma once
// A checked cage refined by OpenSubdiv's Far API into the triangles both backends trace: uniform
// refinement to a level, creases and corners, boundaries interpolated edge-and-corner, every
// refined vertex moved to the limit surface with its limit normal, texture coordinates refined as
// face-varying data. The one file that includes OpenSubdiv is subdivision_refine.cpp.
#include "cage_check.h"
#include "rtpro/scene/mesh.h"
#include "rtpro/scene/subdivision.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

// Memory one refined face (a quad as two triangles, or a Loop triangle) holds at its peak: its
// triangles, vertices, normals and texture coordinates, a BVH over them, and OpenSubdiv's
// topology tables while refining. Deliberately on the high side.
inline constexpr std::uint64_t kBytesPerRefinedFace = 512;

// Faces of the cage at `level` (saturating): Catmull–Clark makes n quads of an n-gon, then 4 of
// each quad per level; Loop 4 triangles of each triangle per level.
std::uint64_t refined_face_count(const PolygonCage& cage, SubdivisionScheme scheme, int level);

// The level refine_cage() uses for `level`: Catmull–Clark limit points of a cage with non-quad
// faces need one refinement first, so such a cage is refined at least once.
int effective_subdivision_level(const CheckedCage& cage, SubdivisionScheme scheme, int level);

// The refined triangles (quads split along their shorter diagonal) with limit positions and unit
// limit normals, uvs when the cage has them, and the cage faces' materials carried to their
// triangles. A vertex on a uv seam is one mesh vertex per side: `surface_vertex` says which mesh
// vertices are one point of the surface (displacement moves them together).
struct RefinedMesh {
  TriangleMesh mesh;
  std::vector<std::uint32_t> surface_vertex;  // per mesh vertex
  std::uint32_t surface_vertex_count = 0;
};
// Throws InputError naming `file` when OpenSubdiv rejects the topology.
RefinedMesh refine_cage(const CheckedCage& cage, SubdivisionScheme scheme, int level, const std::string& file);

// A point of the limit surface by OpenSubdiv's patch evaluation (PatchTable and PatchMap), the
// reference a refined mesh is measured against: `face` is a ptex face (a cage face for an all-quad
// or all-triangle cage), (u, v) in [0, 1]^2 over it.
struct LimitSample {
  std::uint32_t face;
  float u, v;
};
struct LimitPoint {
  Vec3 position;
  Vec3 normal;  // unit, as the face winds
};
std::vector<LimitPoint> evaluate_limit_surface(const CheckedCage& cage, SubdivisionScheme scheme,
                                               std::span<const LimitSample> samples);

}  // namespace rtpro
