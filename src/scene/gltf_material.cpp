#include "gltf_material.h"

#include "mtl_parser.h"

#include <algorithm>
#include <cmath>

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
    warnings.push_back(file.string() + ": " + where + ": texture " + std::to_string(texture) + " has no image; ignored");
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
    const std::string mime = !image.mimeType.empty() ? image.mimeType
                                                     : image.uri.substr(5, image.uri.find(';') == std::string::npos
                                                                               ? 0
                                                                               : image.uri.find(';') - 5);
    const std::string extension = mime == "image/png" ? ".png" : mime == "image/jpeg" ? ".jpg" : ".img";
    *bytes = std::make_shared<const std::vector<unsigned char>>(image.image);
    return file.string() + "#images[" + std::to_string(source) + "]" + extension;
  }
  const std::filesystem::path relative(image.uri);
  const std::filesystem::path normal = relative.lexically_normal();
  if (relative.is_absolute() || normal.empty() || *normal.begin() == "..") {
    warnings.push_back(file.string() + ": images[" + std::to_string(source) + "].uri leaves the glTF's folder; ignored");
    return {};
  }
  return file.parent_path() / normal;
}

// emissiveFactor × KHR_materials_emissive_strength, from both sides of a double-sided material
// (glTF renders its back faces as front faces with the normal flipped).
void read_emission(const tinygltf::Material& m, MaterialDesc& desc) {
  if (m.emissiveFactor.size() != 3) return;
  Color emission(clamped_unit(m.emissiveFactor[0]), clamped_unit(m.emissiveFactor[1]), clamped_unit(m.emissiveFactor[2]));
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

}  // namespace

MaterialDesc read_material(const tinygltf::Model& model, int index, const std::filesystem::path& file,
                           std::vector<std::string>& warnings) {
  const tinygltf::Material& m = model.materials[std::size_t(index)];
  const std::string path = "materials[" + std::to_string(index) + "]";
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  Color base(1.0f, 1.0f, 1.0f);
  float alpha = 1.0f;
  if (pbr.baseColorFactor.size() == 4) {
    base = Color(clamped_unit(pbr.baseColorFactor[0]), clamped_unit(pbr.baseColorFactor[1]), clamped_unit(pbr.baseColorFactor[2]));
    alpha = clamped_unit(pbr.baseColorFactor[3]);
  }
  const float metallic = clamped_unit(pbr.metallicFactor);
  const float roughness = clamped_unit(pbr.roughnessFactor);
  if (m.extensions.count("KHR_materials_pbrSpecularGlossiness"))
    warnings.push_back(file.string() + ": " + path + ": KHR_materials_pbrSpecularGlossiness is not read; using the metallic-roughness values");

  const float f0 = 0.04f + ((base.x + base.y + base.z) / 3.0f - 0.04f) * metallic;
  const float gloss = (1.0f - roughness) * (1.0f - roughness);
  const float alpha4 = std::max(roughness * roughness * roughness * roughness, 1e-6f);
  const float n = std::clamp(2.0f / alpha4 - 2.0f, 1.0f, 10000.0f);

  MaterialDesc desc;
  desc.name = m.name.empty() ? path : m.name;
  desc.reflectivity = std::clamp(f0 * gloss, 0.0f, 1.0f);
  desc.color = base * (1.0f - desc.reflectivity);
  desc.shininess = n;
  desc.specular = std::min(f0 * (n + 2.0f) / 2.0f, 2.0f) * std::min(1.0f, n / kFullHighlightNs);
  desc.opacity = alpha;
  desc.color_texture = texture_path(model, pbr.baseColorTexture.index, file, path + ".pbrMetallicRoughness.baseColorTexture",
                                    warnings, &desc.texture_bytes);
  desc.texture_where = SourceLocation{file.string() + ": " + path + ".pbrMetallicRoughness.baseColorTexture"};
  read_emission(m, desc);
  return desc;
}

}  // namespace rtpro::gltf
