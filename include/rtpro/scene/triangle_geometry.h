#pragma once
// Triangle meshes, the scene's side of the geometry kind in one place (as scene/sphere_geometry.h
// has it for spheres): the entries a scene file writes are read in
// src/scene/yaml/yaml_mesh_entry.cpp, the mesh itself is scene/mesh.h, what the scene needs of it
// is defined in src/scene/build/triangle_geometry.cpp, its intersector is
// geometry/triangle_intersect.h.
#include "rtpro/core/bbox.h"
#include "rtpro/scene/mesh.h"

#include <cstdint>
#include <vector>

namespace rtpro {

struct MeshDesc;    // scene/description.h
struct ShapeTally;  // scene/scene_summary.h
struct SceneSummary;
struct YamlNode;
class ShapeEntryReader;  // src/scene/yaml/yaml_shape_entry.h

// `type: mesh` in an object's or the world's list of entries: an OBJ or PLY file is one mesh; a
// glTF file (.gltf, .glb), a scene of its own placed as a whole, goes to the object's glTF files.
inline const char* entry_type_name(const std::vector<MeshDesc>&) { return "mesh"; }
void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<MeshDesc>& meshes);

std::uint32_t primitive_count_of(const TriangleMesh& mesh);
BBox primitive_bounds_of(const TriangleMesh& mesh, std::uint32_t prim);  // over the whole shutter
inline std::uint32_t motion_step_count_of(const TriangleMesh& mesh) {
  return static_cast<std::uint32_t>(mesh.vertex_steps.size());
}
BBox primitive_bounds_at_step(const TriangleMesh& mesh, std::uint32_t prim, std::uint32_t step);  // a moving mesh's
BBox bounds_of(const TriangleMesh& mesh);
void tally_shapes(const TriangleMesh& mesh, ShapeTally& tally, SceneSummary& summary);

}  // namespace rtpro
