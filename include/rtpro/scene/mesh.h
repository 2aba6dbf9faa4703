#pragma once
// A triangle mesh in the one layout both backends use: Embree shares these arrays directly.
#include "rtpro/core/bbox.h"
#include "rtpro/core/octahedral_normal.h"
#include "rtpro/core/vec3.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace rtpro {

struct MeshVertex {
  float x, y, z;
  Vec3 position() const { return {x, y, z}; }
};
static_assert(sizeof(MeshVertex) == 12);

// Allocates 16 zeroed bytes past the elements it is asked for. Embree reads a vertex as four floats
// and asks that 16 bytes be readable from the last one, and the surface batch loads positions the
// same way; a 12-byte vertex in such an array costs 4 bytes less than a padded one (2 bytes a
// triangle on a closed mesh) and reads the same values.
template <class T>
struct OverreadAllocator {
  using value_type = T;
  static constexpr std::size_t kSlack = 16;
  OverreadAllocator() = default;
  template <class U>
  OverreadAllocator(const OverreadAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > (std::size_t(-1) - kSlack) / sizeof(T)) throw std::bad_array_new_length();
    auto* bytes = static_cast<unsigned char*>(::operator new (n * sizeof(T) + kSlack, std::align_val_t{16}));
    std::memset(bytes + n * sizeof(T), 0, kSlack);
    return reinterpret_cast<T*>(bytes);
  }
  void deallocate(T* p, std::size_t) noexcept { ::operator delete (p, std::align_val_t{16}); }
  template <class U>
  bool operator==(const OverreadAllocator<U>&) const noexcept {
    return true;
  }
};

using VertexArray = std::vector<MeshVertex, OverreadAllocator<MeshVertex>>;

struct TriangleIndices {
  std::uint32_t v0, v1, v2;
};
static_assert(sizeof(TriangleIndices) == 12);

// A texture coordinate as the file wrote it (OBJ and PLY: v up; glTF: v down, flipped on load so
// that every mesh uses OBJ's convention).
struct TexCoord {
  float u, v;
};

struct TriangleMesh {
  std::string name;
  VertexArray vertices;
  std::vector<TriangleIndices> triangles;
  // Per vertex, unit length: as floats in `normals` or, when the render asked for compact normals
  // (pack_normals), as 32-bit octahedral codes in `packed_normals`; both empty: flat shading.
  std::vector<Vec3> normals;
  std::vector<std::uint32_t> packed_normals;
  std::vector<std::uint32_t> triangle_materials;  // per triangle; empty: `material` for all
  std::uint32_t material = 0;
  // Per vertex when the file has them, else empty; kept for texturing, not rendered yet.
  std::vector<TexCoord> uvs;
  std::vector<Color> colors;  // linear RGB
  // Deformation during the shutter (scene/motion.h): the vertices at each time step, each as long
  // as `vertices` (which holds them at the frame's time); empty: the mesh does not deform.
  // normal_steps likewise for `normals`; empty while vertex_steps is not: the normals stay put.
  std::vector<VertexArray> vertex_steps = {};
  std::vector<std::vector<Vec3>> normal_steps = {};
  // Non-zero: the triangles come in spatially compact runs of this many (the last shorter), which
  // a backend may build as separate BVHs (scene/mesh_pieces.h).
  std::uint32_t piece_triangles = 0;

  std::size_t triangle_count() const { return triangles.size(); }
  std::uint32_t material_of(std::uint32_t triangle) const {
    return triangle_materials.empty() ? material : triangle_materials[triangle];
  }
  Vec3 vertex(std::uint32_t i) const { return vertices[i].position(); }
  bool smooth() const { return !normals.empty() || !packed_normals.empty(); }
  // Vertex i's shading normal; only for a smooth mesh.
  Vec3 normal(std::uint32_t i) const {
    return packed_normals.empty() ? normals[i] : decode_octahedral(packed_normals[i]);
  }
  // Moves `normals` into `packed_normals` (a third of their bytes, each within 5e-5 radians). A
  // mesh whose normals move (normal_steps) keeps them as floats.
  void pack_normals();
  bool moving() const { return !vertex_steps.empty(); }
  // Vertex i and its shading normal at ray time `time` in [0, 1] (a moving mesh's).
  Vec3 vertex_at(std::uint32_t i, float time) const;
  Vec3 normal_at(std::uint32_t i, float time) const;
  // Over the whole shutter for a moving mesh.
  BBox triangle_bounds(std::uint32_t t) const;
  BBox bounds() const;
  std::size_t memory_bytes() const;
  std::size_t motion_memory_bytes() const;  // of vertex_steps and normal_steps
};

}  // namespace rtpro
