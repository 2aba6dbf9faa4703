#pragma once
// Internals of the glTF loader: one glTF mesh (all its primitives) as one TriangleMesh.
// - Modes 4 (TRIANGLES), 5 (TRIANGLE_STRIP) and 6 (TRIANGLE_FAN), indexed or not. Points and
//   lines (modes 0 to 3) and primitives without POSITION are skipped with a warning naming the
//   primitive. Triangles with a repeated index are dropped and counted.
// - NORMAL when present (normalised; zero-length ones make that primitive flat, with a warning).
//   Without NORMAL a primitive is flat, as the specification requires: its triangles get
//   vertices of their own carrying the face normal when other primitives of the mesh have
//   normals, and the mesh has no normals at all when none has. options.normals overrides this
//   like for OBJ files (kSmooth: area-weighted over the shared vertices).
// - The texture coordinates the primitive's material maps by (TEXCOORD_0 unless its textures say
//   `texCoord`; gltf_uv_mapping.h), with its KHR_texture_transform applied and v flipped to OBJ's
//   convention, and COLOR_0 (linear, alpha dropped), filled with (0, 0) and white for primitives
//   without them.
// - A TRIANGLES primitive whose index (or vertex) count is not a multiple of 3, or a strip or fan
//   of 1 or 2, is refused: the file is truncated or wrong.
// - Each triangle's material: the primitive's (an index into the file's materials), or
//   kNoMaterial.
// - Morph targets and JOINTS_0/WEIGHTS_0, per vertex of the merged mesh, into a MeshDeformation
//   (gltf_deformation.h); primitives without them offset nothing and carry weights 0.
#include "rtpro/scene/mesh_loader.h"
#include "gltf_accessor.h"
#include "gltf_deformation.h"
#include "gltf_uv_mapping.h"

#include <tiny_gltf.h>

namespace rtpro::gltf {

// `uv_mappings`: one per material of the model (gltf_uv_mapping.h).
TriangleMesh read_mesh(const tinygltf::Model& model, int mesh, const AccessorReader& reader,
                       const MeshLoadOptions& options, const std::vector<UvMapping>& uv_mappings, MeshLoadStats& stats,
                       MeshDeformation& deformation);

}  // namespace rtpro::gltf
