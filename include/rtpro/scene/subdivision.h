#pragma once
// Subdivision surfaces and displacement as a mesh entry asks for them (`subdivision:` and
// `displacement:` in scenes/FORMAT.md), and the polygon cage they refine: an OBJ's faces kept as
// the file wrote them. OpenSubdiv refines the cage into ordinary triangles
// (src/scene/mesh/subdivision_refine.cpp), the same for both backends.
#include "rtpro/core/error.h"
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace rtpro {

enum class SubdivisionScheme : std::uint8_t { kCatmullClark, kLoop };

// A cage edge (v0, v1) or vertex made sharper: 0 smooth, 10 and above infinitely sharp (OpenSubdiv's
// semi-sharp creases in between, a level of sharpness lost per refinement).
struct EdgeCrease {
  std::uint32_t v0, v1;
  float sharpness;
  SourceLocation where;
};

struct VertexCorner {
  std::uint32_t vertex;
  float sharpness;
  SourceLocation where;
};

// The deepest uniform level rtpro refines to: a quad becomes 4^12 (16.7 million) quads there.
inline constexpr int kMaxSubdivisionLevel = 12;
// The deepest level an `edge_length:` may choose when no `level:` caps it.
inline constexpr int kDefaultAdaptiveLevelCap = 8;

struct SubdivisionDesc {
  SubdivisionScheme scheme = SubdivisionScheme::kCatmullClark;
  // The uniform level; with `edge_length`, the deepest level the adaptive choice may reach.
  int level = 2;
  // Pixels: when > 0, the level is the smallest at which the cage's longest edge, as the camera
  // sees it, is subdivided below this many pixels (choose_subdivision_level), at most `level`.
  float edge_length = 0.0f;
  bool level_given = false;  // `level:` written (with edge_length: the cap)
  std::vector<EdgeCrease> creases;
  std::vector<VertexCorner> corners;
  SourceLocation where;
};

// `displacement:` — each refined vertex moved along the limit normal by scale × value, the value a
// texture's first channel at the vertex's texture coordinates or a constant.
struct DisplacementDesc {
  std::filesystem::path texture;  // empty: `value`
  float value = 0.0f;
  float scale = 1.0f;
  // How far (scene units) any point may move, as the user states it: a constant beyond it is an
  // input error, a texture's values beyond it are clamped to it (with a warning). Unset: measured,
  // |scale × value| or the texture's largest |scale × value|.
  std::optional<float> bound;
  SourceLocation where;
};

// A displacement texture's values: its first channel, row 0 at the top (v = 1).
struct ScalarImage {
  int width = 0, height = 0;
  std::vector<float> values;  // width × height
};

// The faces of a mesh file as written (not triangulated), with face-varying texture coordinates
// when every corner has one.
struct PolygonCage {
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> face_sizes;
  std::vector<std::uint32_t> face_vertices;  // face_sizes[f] entries per face, in order
  std::vector<TexCoord> uvs;
  std::vector<std::uint32_t> face_uvs;        // like face_vertices, into uvs; empty without uvs
  std::vector<std::uint32_t> face_materials;  // per face; empty: one material
  std::vector<std::uint64_t> face_lines;      // the file line of each face, for messages

  std::size_t face_count() const { return face_sizes.size(); }
};

}  // namespace rtpro
