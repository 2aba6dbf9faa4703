#pragma once
// A glTF 2.0 file as rtpro uses it: one triangle mesh per glTF mesh (its primitives merged), the
// materials mapped onto rtpro's model, and the node hierarchy resolved to world placements of
// meshes, cameras and lights. See gltf_loader.h for what is read and how it is validated.
#include "rtpro/core/bbox.h"
#include "rtpro/core/transform.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/mesh.h"
#include "rtpro/scene/mesh_loader.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

// The JSON path of nodes[node], which errors about what the node places name.
std::string gltf_node_path(std::uint32_t node);

// A node that draws a mesh: meshes[mesh] placed by `transform` (object to the glTF's world).
struct GltfPlacement {
  std::uint32_t mesh;
  std::uint32_t node;  // the index of the node in nodes[]
  Affine transform;
};

struct GltfCamera {
  std::uint32_t node;  // nodes[node] places cameras[camera]
  std::uint32_t camera;
  Vec3 position;
  Vec3 forward;  // the node's -z
  Vec3 up;       // the node's +y
  float yfov_degrees;
  float aspect_ratio;  // width / height; 0 when the file gives none
};

struct GltfLight {
  enum class Kind : std::uint8_t { kPoint, kDirectional, kSpot };
  Kind kind;
  std::uint32_t node;  // nodes[node] places extensions.KHR_lights_punctual.lights[light]
  std::uint32_t light;
  Vec3 position;   // point and spot
  Vec3 direction;  // directional and spot: the direction light travels in (the node's -z)
  Color color;
  float intensity;  // as the file says: candela (point, spot) or lux (directional)
  // Spot: the cone's half-angles in radians, 0 <= inner <= outer <= π/2 (a light's spot.innerConeAngle
  // and spot.outerConeAngle, default 0 and π/4).
  float inner_cone_angle;
  float outer_cone_angle;
};

struct GltfAsset {
  std::filesystem::path file;
  // triangle_materials and `material` index into `materials`; kNoMaterial marks primitives
  // without a material (they take the scene's default).
  std::vector<TriangleMesh> meshes;
  std::vector<MaterialDesc> materials;  // one per glTF material, in file order
  std::vector<GltfPlacement> placements;
  std::vector<GltfCamera> cameras;  // in node order
  std::vector<GltfLight> lights;    // in node order
  MeshLoadStats stats;              // summed over all meshes, with the loader's warnings

  // The world bounds of every placed mesh; empty when nothing is placed.
  BBox bounds() const;
};

}  // namespace rtpro
