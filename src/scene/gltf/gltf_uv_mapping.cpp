#include "gltf_uv_mapping.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace rtpro::gltf {

namespace {

constexpr const char* kTextureTransform = "KHR_texture_transform";
constexpr double kMaxTransformValue = 1e9;  // FORMAT.md's limit on numbers

// A texture slot rtpro reads: its JSON path, texture index, texCoord and extensions.
struct TextureSlotRef {
  std::string path;
  int index;
  int tex_coord;
  const tinygltf::ExtensionMap* extensions;
};

double finite_number(const tinygltf::Value& value, const std::string& path, const std::string& file) {
  if (!value.IsNumber()) throw InputError(SourceLocation{file}, path + ": a number expected");
  const double number = value.GetNumberAsDouble();
  if (!std::isfinite(number) || std::fabs(number) > kMaxTransformValue)
    throw InputError(SourceLocation{file}, path + ": a finite number of magnitude at most 1e9 expected");
  return number;
}

// [x, y] of an extension member, or `fallback` when absent.
std::array<double, 2> pair_of(const tinygltf::Value& object, const char* key, std::array<double, 2> fallback,
                              const std::string& path, const std::string& file) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value& value = object.Get(key);
  if (!value.IsArray() || value.ArrayLen() != 2)
    throw InputError(SourceLocation{file}, path + "." + key + ": an array of 2 numbers expected");
  return {finite_number(value.Get(0), path + "." + key + "[0]", file),
          finite_number(value.Get(1), path + "." + key + "[1]", file)};
}

// The slot's mapping: its texCoord, and the transform of its KHR_texture_transform.
UvMapping slot_mapping(const TextureSlotRef& slot, const std::string& file) {
  UvMapping mapping;
  mapping.set = slot.tex_coord;
  mapping.textured = true;
  const auto found = slot.extensions->find(kTextureTransform);
  if (found == slot.extensions->end() || !found->second.IsObject()) return mapping;
  const tinygltf::Value& transform = found->second;
  const std::string path = slot.path + ".extensions." + kTextureTransform;
  const std::array<double, 2> offset = pair_of(transform, "offset", {0.0, 0.0}, path, file);
  const std::array<double, 2> scale = pair_of(transform, "scale", {1.0, 1.0}, path, file);
  const double rotation =
      transform.Has("rotation") ? finite_number(transform.Get("rotation"), path + ".rotation", file) : 0.0;
  if (transform.Has("texCoord")) {
    const tinygltf::Value& set = transform.Get("texCoord");
    if (!set.IsInt() || set.Get<int>() < 0)
      throw InputError(SourceLocation{file}, path + ".texCoord: a non-negative integer expected");
    mapping.set = set.Get<int>();
  }
  // The extension's matrix: translation × rotation × scale, rotation counter-clockwise in
  // glTF's texture space (v down).
  const double c = std::cos(rotation), s = std::sin(rotation);
  const double m[6] = {c * scale[0], s * scale[1], offset[0], -s * scale[0], c * scale[1], offset[1]};
  std::copy(std::begin(m), std::end(m), mapping.m);
  return mapping;
}

bool same(const UvMapping& a, const UvMapping& b) {
  return a.set == b.set && std::equal(std::begin(a.m), std::end(a.m), std::begin(b.m));
}

}  // namespace

UvMapping uv_mapping(const tinygltf::Model& model, int material, const std::string& file,
                     std::vector<std::string>& warnings) {
  if (material < 0 || std::size_t(material) >= model.materials.size()) return {};
  const tinygltf::Material& m = model.materials[std::size_t(material)];
  const std::string path = "materials[" + std::to_string(material) + "]";
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  const TextureSlotRef slots[] = {
      {path + ".pbrMetallicRoughness.baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
       &pbr.baseColorTexture.extensions},
      {path + ".pbrMetallicRoughness.metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
       pbr.metallicRoughnessTexture.texCoord, &pbr.metallicRoughnessTexture.extensions},
      {path + ".normalTexture", m.normalTexture.index, m.normalTexture.texCoord, &m.normalTexture.extensions},
      {path + ".emissiveTexture", m.emissiveTexture.index, m.emissiveTexture.texCoord, &m.emissiveTexture.extensions},
  };
  std::optional<UvMapping> chosen;
  std::string chosen_path;
  for (const TextureSlotRef& slot : slots) {
    if (slot.index < 0) continue;
    const UvMapping mapping = slot_mapping(slot, file);
    if (!chosen) {
      chosen = mapping;
      chosen_path = slot.path;
    } else if (!same(mapping, *chosen)) {
      warnings.push_back(file + ": " + slot.path +
                         " uses other texture coordinates (texCoord or KHR_texture_transform) than " + chosen_path +
                         "; rtpro maps all of a material's textures the same way, as " + chosen_path);
    }
  }
  return chosen.value_or(UvMapping{});
}

void apply_uv_mapping(const UvMapping& mapping, std::vector<TexCoord>& uvs) {
  if (mapping.identity()) return;
  const double* m = mapping.m;
  for (TexCoord& uv : uvs) {
    const double u = uv.u, v = 1.0 - double(uv.v);  // back to glTF's v
    const double mapped_u = m[0] * u + m[1] * v + m[2];
    const double mapped_v = m[3] * u + m[4] * v + m[5];
    uv = TexCoord{float(mapped_u), float(1.0 - mapped_v)};
  }
}

}  // namespace rtpro::gltf
