#include "gltf_material.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "path_containment.h"
#include "mtl_parser.h"
#include "gltf_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rtpro::gltf {

namespace {

float clamped_unit(double value) { return float(std::clamp(std::isfinite(value) ? value : 0.0, 0.0, 1.0)); }

// The image a texture reference points at, as a path rtpro can open later; empty when the
// reference leads nowhere (a warning).
std::filesystem::path texture_path(const tinygltf::Model& model, int texture, const std::filesystem::path& file,
                                   const std::string& where, std::vector<std::string>& warnings,
                                   std::shared_ptr<const std::vector<unsigned char>>* bytes) {
  if (texture < 0) return {};
  if (std::size_t(texture) >= model.textures.size() || model.textures[std::size_t(texture)].source < 0 ||
      std::size_t(model.textures[std::size_t(texture)].source) >= model.images.size()) {
    warnings.push_back(file.string() + ": " + where + ": texture " + std::to_string(texture) +
                       " has no image; ignored");
    return {};
  }
  const int source = model.textures[std::size_t(texture)].source;
  const tinygltf::Image& image = model.images[std::size_t(source)];
  if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) {
    if (image.image.empty()) {
      warnings.push_back(file.string() + ": images[" + std::to_string(source) + "] has no data; ignored");
      return {};
    }
    // Stored inside the glTF: kept encoded, named with an extension OpenImageIO picks a reader by.
    const std::string mime =
        !image.mimeType.empty()
            ? image.mimeType
            : image.uri.substr(5, image.uri.find(';') == std::string::npos ? 0 : image.uri.find(';') - 5);
    const std::string extension = mime == "image/png" ? ".png" : mime == "image/jpeg" ? ".jpg" : ".img";
    *bytes = std::make_shared<const std::vector<unsigned char>>(image.image);
    return file.string() + "#images[" + std::to_string(source) + "]" + extension;
  }
  const std::filesystem::path relative(image.uri);
  const std::filesystem::path normal = relative.lexically_normal();
  if (relative.is_absolute() || normal.empty() || *normal.begin() == "..") {
    warnings.push_back(file.string() + ": images[" + std::to_string(source) +
                       "].uri leaves the glTF's folder; ignored");
    return {};
  }
  const std::filesystem::path path = file.parent_path() / normal;
  if (!resolves_inside(file.parent_path(), path))
    throw InputError(SourceLocation{file.string()}, "images[" + std::to_string(source) +
                                                        "].uri: " + ascii::quoted(image.uri) +
                                                        " leads outside the glTF's folder (through a symbolic link)");
  return path;
}

// A texture slot other than the base colour; nothing when the reference leads nowhere (a warning).
// Data textures (metallic-roughness, normals) are decoded as "Raw", colour ones as sRGB, as the
// glTF specification defines them.
std::optional<TextureSlotDesc> texture_slot(const tinygltf::Model& model, int texture,
                                            const std::filesystem::path& file, const std::string& where,
                                            const char* colorspace, std::vector<std::string>& warnings) {
  TextureSlotDesc slot;
  slot.file = texture_path(model, texture, file, where, warnings, &slot.bytes);
  if (slot.file.empty()) return std::nullopt;
  slot.colorspace = colorspace;
  slot.where = SourceLocation{file.string() + ": " + where};
  slot.sampling = texture_sampling(model, texture, file.string());
  return slot;
}

// emissiveFactor × KHR_materials_emissive_strength, from both sides of a double-sided material
// (glTF renders its back faces as front faces with the normal flipped).
void read_emission(const tinygltf::Material& m, MaterialDesc& desc) {
  if (m.emissiveFactor.size() != 3) return;
  Color emission(clamped_unit(m.emissiveFactor[0]), clamped_unit(m.emissiveFactor[1]),
                 clamped_unit(m.emissiveFactor[2]));
  if (const auto ext = m.extensions.find("KHR_materials_emissive_strength"); ext != m.extensions.end()) {
    const tinygltf::Value& strength = ext->second.Get("emissiveStrength");
    if (strength.IsNumber()) {
      const double value = strength.GetNumberAsDouble();
      emission = emission * (std::isfinite(value) && value > 0.0 ? static_cast<float>(std::min(value, 1e9)) : 0.0f);
    }
  }
  desc.emission = emission;
  desc.emission_two_sided = m.doubleSided;
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  const auto found = m.extensions.find(name);
  return found == m.extensions.end() || !found->second.IsObject() ? nullptr : &found->second;
}

// A number of an extension object, or `fallback` when absent or not a finite number.
float number_of(const tinygltf::Value& object, const char* key, float fallback) {
  const tinygltf::Value& value = object.Get(key);
  if (!value.IsNumber()) return fallback;
  const double number = value.GetNumberAsDouble();
  return std::isfinite(number) ? static_cast<float>(number) : fallback;
}

Color color_of(const tinygltf::Value& object, const char* key, Color fallback) {
  const tinygltf::Value& value = object.Get(key);
  if (!value.IsArray() || value.ArrayLen() != 3) return fallback;
  Color c;
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Value& channel = value.Get(i);
    if (!channel.IsNumber()) return fallback;
    c[i] = clamped_unit(channel.GetNumberAsDouble());
  }
  return c;
}

// The material extensions tinygltf hands over, as their specifications define them (values
// clamped to their ranges); their textures are not read.
void read_extensions(const tinygltf::Material& m, PrincipledParams& p) {
  if (const tinygltf::Value* ior = extension(m, "KHR_materials_ior")) {
    const float value = number_of(*ior, "ior", 1.5f);
    p.ior = value >= 1.0f ? std::min(value, 100.0f) : 1.5f;  // 0 (a glTF "infinite" index) is not modelled
  }
  if (const tinygltf::Value* specular = extension(m, "KHR_materials_specular")) {
    p.specular_weight = clamped_unit(number_of(*specular, "specularFactor", 1.0f));
    p.specular_color = color_of(*specular, "specularColorFactor", Color(1.0f));
  }
  if (const tinygltf::Value* transmission = extension(m, "KHR_materials_transmission"))
    p.transmission_weight = clamped_unit(number_of(*transmission, "transmissionFactor", 0.0f));
  if (const tinygltf::Value* clearcoat = extension(m, "KHR_materials_clearcoat")) {
    p.coat_weight = clamped_unit(number_of(*clearcoat, "clearcoatFactor", 0.0f));
    p.coat_roughness = clamped_unit(number_of(*clearcoat, "clearcoatRoughnessFactor", 0.0f));
  }
  if (const tinygltf::Value* sheen = extension(m, "KHR_materials_sheen")) {
    p.fuzz_color = color_of(*sheen, "sheenColorFactor", Color(0.0f));
    p.fuzz_roughness = clamped_unit(number_of(*sheen, "sheenRoughnessFactor", 0.0f));
  }
}

// KHR_materials_volume: a material of thickness > 0 bounds a volume whose absorption makes white
// light attenuationColor after attenuationDistance, σa = −ln(attenuationColor) / attenuationDistance
// (the extension's own definition: an AbsorbingMedium); an infinite distance (its default) absorbs
// nothing. Thickness
// 0 is a thin wall, no volume. The thickness itself only serves rasterisers, which have no inside.
std::optional<Medium> volume_interior(const tinygltf::Material& m) {
  const tinygltf::Value* volume = extension(m, "KHR_materials_volume");
  if (!volume || !(number_of(*volume, "thicknessFactor", 0.0f) > 0.0f)) return std::nullopt;
  const float distance = number_of(*volume, "attenuationDistance", std::numeric_limits<float>::infinity());
  const Color color = color_of(*volume, "attenuationColor", Color(1.0f));
  if (!(distance > 0.0f) || !std::isfinite(distance)) return HomogeneousMedium{};
  return AbsorbingMedium{color, distance};
}

}  // namespace

MaterialDesc read_material(const tinygltf::Model& model, int index, const std::filesystem::path& file,
                           std::vector<std::string>& warnings) {
  const tinygltf::Material& m = model.materials[std::size_t(index)];
  const std::string path = "materials[" + std::to_string(index) + "]";
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  Color base(1.0f, 1.0f, 1.0f);
  float alpha = 1.0f;
  if (pbr.baseColorFactor.size() == 4) {
    base = Color(clamped_unit(pbr.baseColorFactor[0]), clamped_unit(pbr.baseColorFactor[1]),
                 clamped_unit(pbr.baseColorFactor[2]));
    alpha = clamped_unit(pbr.baseColorFactor[3]);
  }
  const float metallic = clamped_unit(pbr.metallicFactor);
  const float roughness = clamped_unit(pbr.roughnessFactor);
  // The material extensions' own textures (clearcoatTexture, sheenColorTexture, ...) are not read.
  for (const auto& [name, ext] : m.extensions)
    if (ext.IsObject())
      for (const std::string& key : ext.Keys())
        if (key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0)
          warnings.push_back(file.string() + ": " + path + ".extensions." + ascii::quoted(name) + "." +
                             ascii::quoted(key) + " is not read; the factor alone is used");
  if (m.extensions.count("KHR_materials_pbrSpecularGlossiness"))
    warnings.push_back(file.string() + ": " + path +
                       ": KHR_materials_pbrSpecularGlossiness is not read; using the metallic-roughness values");

  // The path integrator's principled model; the Whitted fields are worked out from it when the
  // render scene is built (whitted_approximation_of in scene/principled_material.h).
  MaterialDesc desc;
  desc.name = m.name.empty() ? path : m.name;
  PrincipledParams& principled = desc.params.emplace<PrincipledParams>();
  desc.color = base;
  principled.roughness = roughness;
  principled.metalness = metallic;
  read_extensions(m, principled);
  desc.interior = volume_interior(m);
  desc.opacity = alpha;
  desc.color_texture = texture_path(model, pbr.baseColorTexture.index, file,
                                    path + ".pbrMetallicRoughness.baseColorTexture", warnings, &desc.texture_bytes);
  desc.texture_where = SourceLocation{file.string() + ": " + path + ".pbrMetallicRoughness.baseColorTexture"};
  desc.texture_sampling = texture_sampling(model, pbr.baseColorTexture.index, file.string());
  read_emission(m, desc);
  principled.metallic_roughness_texture =
      texture_slot(model, pbr.metallicRoughnessTexture.index, file,
                   path + ".pbrMetallicRoughness.metallicRoughnessTexture", "Raw", warnings);
  principled.normal_texture =
      texture_slot(model, m.normalTexture.index, file, path + ".normalTexture", "Raw", warnings);
  principled.normal_scale = std::isfinite(m.normalTexture.scale) ? static_cast<float>(m.normalTexture.scale) : 1.0f;
  if (desc.emission != Color(0.0f))
    desc.emission_texture =
        texture_slot(model, m.emissiveTexture.index, file, path + ".emissiveTexture", "sRGB - Texture", warnings);
  return desc;
}

}  // namespace rtpro::gltf
