#include "gltf_accessor.h"

#include "rtpro/core/error.h"
#include "rtpro/core/large_buffer.h"
#include "mesh_limits.h"

#include <array>
#include <cmath>
#include <cstring>

namespace rtpro::gltf {

namespace {

std::size_t component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;  // inverseBindMatrices
    default: return 0;                   // MAT2 and MAT3: nothing rtpro reads uses them
  }
}

// Animation and skin accessors without a bufferView: more zeros than any real file keys.
constexpr std::size_t kMaxImplicitZeros = std::size_t(1) << 20;

std::string index_path(const char* array, int index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

}  // namespace

void AccessorReader::fail(const std::string& path, const std::string& message) const {
  throw InputError(SourceLocation{file_}, path + ": " + message);
}

AccessorReader::View AccessorReader::view(int index, const std::string& where, std::initializer_list<int> types,
                                          std::initializer_list<int> component_types) const {
  if (index < 0 || std::size_t(index) >= model_.accessors.size())
    fail(where, "accessor " + std::to_string(index) + " does not exist (the file has " +
                    std::to_string(model_.accessors.size()) + ")");
  const tinygltf::Accessor& a = model_.accessors[std::size_t(index)];
  const std::string path = index_path("accessors", index);
  if (std::find(types.begin(), types.end(), a.type) == types.end())
    fail(path + ".type", "type not allowed for " + where);
  if (std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
    fail(path + ".componentType", "component type " + std::to_string(a.componentType) + " not allowed for " + where);
  if (a.sparse.isSparse) fail(path + ".sparse", "sparse accessors are not supported");
  if (a.count > kMaxMeshElements) fail(path + ".count", "more than 2^32 - 2 elements");
  View v{nullptr, a.count, 0, component_count(a.type), a.componentType, a.normalized, path};
  const std::size_t element = component_size(a.componentType) * std::size_t(v.components);
  if (a.bufferView < 0) return v;  // all zeros, as the specification says
  if (std::size_t(a.bufferView) >= model_.bufferViews.size())
    fail(path + ".bufferView", "bufferView " + std::to_string(a.bufferView) + " does not exist");
  const std::string view_path = index_path("bufferViews", a.bufferView);
  const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(a.bufferView)];
  if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size())
    fail(view_path + ".buffer", "buffer " + std::to_string(bv.buffer) + " does not exist");
  const std::vector<unsigned char>& data = model_.buffers[std::size_t(bv.buffer)].data;
  if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
    fail(view_path + ".byteLength", "bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
                                        " lie beyond the end of buffers[" + std::to_string(bv.buffer) + "] (" +
                                        std::to_string(data.size()) + " bytes)");
  v.stride = bv.byteStride == 0 ? element : bv.byteStride;
  if (v.stride < element)
    fail(view_path + ".byteStride", "stride " + std::to_string(v.stride) + " is smaller than one element");
  // All in 64 bits: count < 2^32 and stride, offsets < 2^32 (bufferView sizes), so no product overflows.
  if (a.count > 0) {
    const std::uint64_t needed = std::uint64_t(a.byteOffset) + std::uint64_t(v.stride) * (a.count - 1) + element;
    if (a.byteOffset > bv.byteLength || needed > bv.byteLength)
      fail(path + ".count", std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                                " do not fit in " + view_path + " (" + std::to_string(bv.byteLength) + " bytes)");
  }
  v.data = data.data() + bv.byteOffset + a.byteOffset;
  return v;
}

float AccessorReader::component(const View& v, std::size_t i, int k) const {
  if (!v.data) return 0.0f;
  const unsigned char* p = v.data + i * v.stride + std::size_t(k) * component_size(v.component_type);
  const auto load = [p](auto value) {
    std::memcpy(&value, p, sizeof value);
    return value;
  };
  switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load(float{});
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return v.normalized ? float(load(std::uint8_t{})) / 255.0f : float(load(std::uint8_t{}));
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return v.normalized ? float(load(std::uint16_t{})) / 65535.0f : float(load(std::uint16_t{}));
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return v.normalized ? std::max(float(load(std::int8_t{})) / 127.0f, -1.0f) : float(load(std::int8_t{}));
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return v.normalized ? std::max(float(load(std::int16_t{})) / 32767.0f, -1.0f) : float(load(std::int16_t{}));
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(load(std::uint32_t{}));
    default: return 0.0f;
  }
}

template <int N>
std::vector<std::array<float, N>> AccessorReader::floats(const View& v) const {
  std::vector<std::array<float, N>> out;
  resize_large(out, v.count);
  // An empty accessor leaves `out` without storage: memcpy must not see its null pointer.
  if (v.count == 0) return out;
  if (v.data && v.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT && v.stride == sizeof(float) * N) {
    // The common case, tightly packed floats: one copy, then one pass checking them.
    std::memcpy(out.data(), v.data, v.count * sizeof(float) * N);
    for (std::size_t i = 0; i < v.count; ++i)
      for (const float value : out[i])
        if (!std::isfinite(value)) fail(v.path, "element " + std::to_string(i) + " is not a finite number");
    return out;
  }
  for (std::size_t i = 0; i < v.count; ++i) {
    for (int k = 0; k < N; ++k) {
      const float value = component(v, i, k);
      if (!std::isfinite(value)) fail(v.path, "element " + std::to_string(i) + " is not a finite number");
      out[i][std::size_t(k)] = value;
    }
  }
  return out;
}

std::vector<Vec3> AccessorReader::positions(int accessor, const std::string& where) const {
  const View v = view(accessor, where, {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  static_assert(sizeof(Vec3) == 3 * sizeof(float));
  std::vector<Vec3> out;
  resize_large(out, v.count);
  if (v.count == 0) return out;  // no storage: memcpy must not see a null pointer
  if (v.data && v.stride == sizeof(Vec3)) std::memcpy(out.data(), v.data, v.count * sizeof(Vec3));
  else if (v.data)
    for (std::size_t i = 0; i < v.count; ++i) std::memcpy(&out[i], v.data + i * v.stride, sizeof(Vec3));
  for (std::size_t i = 0; i < out.size(); ++i) {
    // One test per coordinate for both: NaN fails it, and so do infinities and magnitudes beyond
    // the limit.
    const Vec3& p = out[i];
    if (!(std::fabs(p.x) <= kMaxAbsCoordinate && std::fabs(p.y) <= kMaxAbsCoordinate &&
          std::fabs(p.z) <= kMaxAbsCoordinate)) {
      if (!is_finite(out[i])) fail(v.path, "element " + std::to_string(i) + " is not a finite number");
      fail(v.path, "element " + std::to_string(i) + " has a coordinate beyond the supported magnitude 1e16");
    }
  }
  return out;
}

std::vector<Vec3> AccessorReader::normals(int accessor, const std::string& where) const {
  const View v = view(accessor, where, {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  std::vector<Vec3> out;
  out.reserve(v.count);
  for (const auto& n : floats<3>(v)) out.emplace_back(n[0], n[1], n[2]);
  return out;
}

std::vector<TexCoord> AccessorReader::texcoords(int accessor, const std::string& where) const {
  const View v = view(
      accessor, where, {TINYGLTF_TYPE_VEC2},
      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
  std::vector<TexCoord> out;
  out.reserve(v.count);
  // glTF's v grows down the image; rtpro's texture coordinates are OBJ's and PLY's (v up), which
  // the texture lookup turns back. Flipped here and nowhere else.
  for (const auto& uv : floats<2>(v)) out.push_back({uv[0], 1.0f - uv[1]});
  return out;
}

std::vector<Color> AccessorReader::colors(int accessor, const std::string& where) const {
  const View v = view(
      accessor, where, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
      {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
  std::vector<Color> out;
  out.reserve(v.count);
  for (std::size_t i = 0; i < v.count; ++i) {
    Color c(component(v, i, 0), component(v, i, 1), component(v, i, 2));
    if (!is_finite(c)) fail(v.path, "element " + std::to_string(i) + " is not a finite number");
    out.push_back(c);
  }
  return out;
}

std::vector<std::uint32_t> AccessorReader::indices(int accessor, std::uint32_t vertex_count,
                                                   const std::string& where) const {
  const View v = view(accessor, where, {TINYGLTF_TYPE_SCALAR},
                      {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
  if (v.normalized) fail(v.path + ".normalized", "indices must not be normalized");
  std::vector<std::uint32_t> out;
  resize_large(out, v.count);
  if (v.count == 0) return out;  // no storage: memcpy must not see a null pointer
  if (v.data && v.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && v.stride == 4) {
    std::memcpy(out.data(), v.data, v.count * 4);
    for (std::size_t i = 0; i < v.count; ++i)
      if (out[i] >= vertex_count)
        fail(v.path, "index " + std::to_string(out[i]) + " (element " + std::to_string(i) +
                         ") is out of range: the primitive has " + std::to_string(vertex_count) + " vertices");
    return out;
  }
  for (std::size_t i = 0; i < v.count; ++i) {
    std::uint32_t index = 0;
    if (v.data) {
      const unsigned char* p = v.data + i * v.stride;
      switch (v.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: index = *p; break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t s;
          std::memcpy(&s, p, 2);
          index = s;
          break;
        }
        default: std::memcpy(&index, p, 4); break;
      }
    }
    if (index >= vertex_count)
      fail(v.path, "index " + std::to_string(index) + " (element " + std::to_string(i) +
                       ") is out of range: the primitive has " + std::to_string(vertex_count) + " vertices");
    out[i] = index;
  }
  return out;
}

std::vector<float> AccessorReader::values(int accessor, const std::string& where, int type,
                                          bool normalized_integers) const {
  const View v =
      normalized_integers
          ? view(accessor, where, {type},
                 {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                  TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT})
          : view(accessor, where, {type}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  if (v.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !v.normalized)
    fail(v.path + ".normalized", "integer components here must be normalized");
  // Without a bufferView the values are zeros that take no bytes in the file: bounded here, or a
  // few bytes of JSON could ask for gigabytes.
  if (!v.data && v.count > kMaxImplicitZeros)
    fail(v.path + ".count", std::to_string(v.count) + " elements without a bufferView (all zeros); at most " +
                                std::to_string(kMaxImplicitZeros) + " are read");
  std::vector<float> out;
  resize_large(out, v.count * std::size_t(v.components));
  for (std::size_t i = 0; i < v.count; ++i)
    for (int k = 0; k < v.components; ++k) {
      const float value = component(v, i, k);
      if (!std::isfinite(value)) fail(v.path, "element " + std::to_string(i) + " is not a finite number");
      out[i * std::size_t(v.components) + std::size_t(k)] = value;
    }
  return out;
}

std::vector<std::array<std::uint16_t, 4>> AccessorReader::joints(int accessor, const std::string& where) const {
  const View v = view(accessor, where, {TINYGLTF_TYPE_VEC4},
                      {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
  if (v.normalized) fail(v.path + ".normalized", "joint indices must not be normalized");
  std::vector<std::array<std::uint16_t, 4>> out;
  resize_large(out, v.count);
  for (std::size_t i = 0; i < v.count; ++i)
    for (int k = 0; k < 4; ++k) out[i][std::size_t(k)] = std::uint16_t(component(v, i, k));
  return out;
}

}  // namespace rtpro::gltf
