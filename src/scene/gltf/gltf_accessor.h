#pragma once
// Internals of the glTF loader: reading accessors with every bound checked, since tinygltf
// checks none of them. An accessor must name an existing bufferView of an existing buffer, its
// elements must lie inside the view (count, offset and stride, in overflow-free arithmetic), its
// type and component type must fit the use, and float values must be finite. Any violation is an
// InputError naming the file and the JSON path of the offending element (`accessors[3].count`).
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <tiny_gltf.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rtpro::gltf {

class AccessorReader {
 public:
  AccessorReader(const tinygltf::Model& model, std::string file) : model_(model), file_(std::move(file)) {}

  // `where` is the JSON path of the reference (`meshes[0].primitives[1].attributes.POSITION`),
  // named when the index itself is out of range.
  std::vector<Vec3> positions(int accessor, const std::string& where) const;
  std::vector<Vec3> normals(int accessor, const std::string& where) const;
  std::vector<TexCoord> texcoords(int accessor, const std::string& where) const;  // v flipped to OBJ's convention
  std::vector<Color> colors(int accessor, const std::string& where) const;        // RGB or RGBA, alpha dropped
  // Indices, each below `vertex_count`.
  std::vector<std::uint32_t> indices(int accessor, std::uint32_t vertex_count, const std::string& where) const;
  // Animation and skinning data, each element's components in a row: `type` one of TINYGLTF_TYPE_*
  // (SCALAR to MAT4); floats, or with `normalized_integers` also normalised (unsigned) bytes and
  // shorts (animated rotations and weights, skin weights).
  std::vector<float> values(int accessor, const std::string& where, int type, bool normalized_integers) const;
  // JOINTS_n: four unsigned bytes or shorts per vertex.
  std::vector<std::array<std::uint16_t, 4>> joints(int accessor, const std::string& where) const;

  [[noreturn]] void fail(const std::string& path, const std::string& message) const;
  const std::string& file() const { return file_; }

 private:
  struct View {
    const unsigned char* data;  // the first element; null for an accessor without bufferView (all zeros)
    std::size_t count;
    std::size_t stride;
    int components;
    int component_type;
    bool normalized;
    std::string path;  // "accessors[N]"
  };

  View view(int accessor, const std::string& where, std::initializer_list<int> types,
            std::initializer_list<int> component_types) const;
  // Component k of element i, as a float (normalised integers scaled per the specification).
  float component(const View& v, std::size_t i, int k) const;
  template <int N>
  std::vector<std::array<float, N>> floats(const View& v) const;

  const tinygltf::Model& model_;
  std::string file_;
};

}  // namespace rtpro::gltf
