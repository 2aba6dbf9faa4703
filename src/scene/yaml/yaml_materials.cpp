#include "yaml_materials.h"

#include "yaml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace rtpro {

namespace {

// color: {checker: {size: 1, colors: [[r, g, b], [r, g, b]], axes: xz}}
CheckerDesc read_checker(const YamlNode& node, const std::string& name) {
  const MappingReader texture(node, name, {"checker"});
  const MappingReader checker(texture.required("checker"), name + ".checker", {"size", "colors", "axes"});
  CheckerDesc desc;
  if (const YamlNode* size = checker.optional("size")) {
    const double side = read_number(*size, checker.field("size"));
    if (!(side > 0.0) || !std::isfinite(static_cast<float>(1.0 / side)) || !std::isfinite(static_cast<float>(side)))
      fail_at(*size, checker.field("size") + " is the side of a square in scene units: positive and finite, got " +
                         std::string(size->scalar()));
    desc.size = static_cast<float>(side);
  }
  if (const YamlNode* colors = checker.optional("colors")) {
    const auto& items = read_list(*colors, checker.field("colors"), 2, "two colours, [[r, g, b], [r, g, b]]");
    desc.even = read_color(*items[0], checker.field("colors") + "[0]");
    desc.odd = read_color(*items[1], checker.field("colors") + "[1]");
  }
  if (const YamlNode* axes = checker.optional("axes")) {
    const std::string text = read_string(*axes, checker.field("axes"));
    if (text == "xz") desc.axes = CheckerAxes::kXZ;
    else if (text == "xy") desc.axes = CheckerAxes::kXY;
    else if (text == "yz") desc.axes = CheckerAxes::kYZ;
    else if (text == "xyz") desc.axes = CheckerAxes::kXYZ;
    else fail_at(*axes, checker.field("axes") + " must be xz, xy, yz or xyz, got '" + text + "'");
  }
  return desc;
}

// color: {texture: FILE, colorspace: srgb | linear | an OpenColorIO colour space, wrap: repeat |
// clamp | mirror | black, tint: [r, g, b]}
void read_image_texture(const YamlNode& node, const std::string& name, const std::filesystem::path& folder,
                        MaterialDesc& desc) {
  const MappingReader texture(node, name, {"texture", "colorspace", "wrap", "tint"});
  const YamlNode& file = texture.required("texture");
  const std::string written = read_string(file, texture.field("texture"));
  if (written.empty()) fail_at(file, texture.field("texture") + " must name an image file");
  desc.color_texture = folder / written;
  desc.texture_where = file.at.location();
  std::error_code error;
  if (!std::filesystem::is_regular_file(desc.color_texture, error))
    fail_at(file, texture.field("texture") + ": image file '" + desc.color_texture.string() + "' not found");
  if (const YamlNode* colorspace = texture.optional("colorspace")) {
    const std::string text = read_string(*colorspace, texture.field("colorspace"));
    desc.texture_colorspace = text == "srgb" ? "sRGB - Texture" : text == "linear" ? "Linear Rec.709 (sRGB)" : text;
  }
  if (const YamlNode* wrap = texture.optional("wrap")) {
    const std::string text = read_string(*wrap, texture.field("wrap"));
    if (text == "repeat") desc.texture_wrap = TextureWrap::kRepeat;
    else if (text == "clamp") desc.texture_wrap = TextureWrap::kClamp;
    else if (text == "mirror") desc.texture_wrap = TextureWrap::kMirror;
    else if (text == "black") desc.texture_wrap = TextureWrap::kBlack;
    else fail_at(*wrap, texture.field("wrap") + " must be repeat, clamp, mirror or black, got '" + text + "'");
  }
  desc.color = Color(1.0f);
  if (const YamlNode* tint = texture.optional("tint")) desc.color = read_color(*tint, texture.field("tint"));
}

// What a scene file calls each kind (its `type:`); nothing past the last kind, so that
// read_material_kind can list them all without a list of its own.
const char* material_type(MaterialKind kind) {
  switch (kind) {
    case MaterialKind::kPhong: return "phong";
    case MaterialKind::kDiffuse: return "diffuse";
    case MaterialKind::kConductor: return "conductor";
    case MaterialKind::kDielectric: return "dielectric";
    case MaterialKind::kPrincipled: return "principled";
  }
  return nullptr;
}

MaterialKind read_material_kind(const YamlNode& node, const std::string& name) {
  const std::string text = read_string(node, name);
  std::string kinds;
  for (std::uint8_t k = 0; const char* type = material_type(static_cast<MaterialKind>(k)); ++k) {
    if (text == type) return static_cast<MaterialKind>(k);
    const bool last = !material_type(static_cast<MaterialKind>(k + 1));
    kinds += (k == 0 ? "" : (last ? " or " : ", ")) + std::string(type);
  }
  fail_at(node, name + " must be " + kinds + ", got '" + text + "'");
}

// The keys a material of `kind` may have besides `type`, colour and emission: each kind names its
// own, so a key of another kind (a conductor's `reflectivity`) is an error, not silently ignored.
std::vector<std::string_view> material_keys(MaterialKind kind) {
  std::vector<std::string_view> keys{"type", "color", "emission", "emission_strength", "emission_sides"};
  const auto add = [&keys](std::initializer_list<std::string_view> more) { keys.insert(keys.end(), more); };
  switch (kind) {
    case MaterialKind::kPhong:
      add({"specular", "shininess", "reflectivity", "ior", "transmittance", "transmittance_distance"});
      break;
    case MaterialKind::kDiffuse: break;
    case MaterialKind::kConductor: add({"roughness", "eta", "k"}); break;
    case MaterialKind::kDielectric: add({"roughness", "ior", "transmittance", "transmittance_distance"}); break;
    case MaterialKind::kPrincipled:
      add({"roughness", "ior", "metalness", "specular_weight", "specular_color", "transmission_weight", "coat_weight",
           "coat_roughness", "fuzz_color", "fuzz_roughness"});
      break;
  }
  return keys;
}

// emission: [r, g, b] radiance, times emission_strength (1), from the front side or both
// (emission_sides: front | both).
void read_emission(const MappingReader& material, MaterialDesc& desc) {
  const YamlNode* emission = material.optional("emission");
  const YamlNode* strength = material.optional("emission_strength");
  const YamlNode* sides = material.optional("emission_sides");
  if (!emission && (strength || sides))
    fail_at(strength ? *strength : *sides, material.field(strength ? "emission_strength" : "emission_sides") +
                                               " qualifies the emission: give the material an emission colour too");
  if (!emission) return;
  desc.emission = read_vec3(*emission, material.field("emission"));  // radiance: no 1-is-full rule
  if (std::min({desc.emission.x, desc.emission.y, desc.emission.z}) < 0.0f)
    fail_at(*emission, material.field("emission") + " is emitted radiance: each channel 0 or more");
  if (strength) {
    const float factor = read_non_negative(*strength, material.field("emission_strength"));
    desc.emission = desc.emission * factor;
    if (!is_finite(desc.emission))
      fail_at(*strength, material.field("emission_strength") + " makes the emission overflow");
  }
  if (sides) {
    const std::string text = read_string(*sides, material.field("emission_sides"));
    if (text == "front") desc.emission_two_sided = false;
    else if (text == "both") desc.emission_two_sided = true;
    else fail_at(*sides, material.field("emission_sides") + " must be front or both, got '" + text + "'");
  }
}

// roughness 0..1 and a conductor's complex index (eta and k together).
void read_microfacet_keys(const MappingReader& material, MaterialDesc& desc) {
  if (const YamlNode* roughness = material.optional("roughness")) {
    desc.roughness = read_non_negative(*roughness, material.field("roughness"));
    if (desc.roughness > 1.0f)
      fail_at(*roughness,
              material.field("roughness") + " must be from 0 (smooth) to 1, got " + std::string(roughness->scalar()));
  }
  const YamlNode* eta = material.optional("eta");
  const YamlNode* k = material.optional("k");
  if (!eta != !k)
    fail_at(eta ? *eta : *k,
            material.field(eta ? "eta" : "k") +
                ": a complex index of refraction needs both eta and k (gold: eta [0.143, 0.374, 1.442], "
                "k [3.983, 2.385, 1.603])");
  if (eta) {
    desc.conductor_eta = read_color(*eta, material.field("eta"));
    desc.conductor_k = read_color(*k, material.field("k"));
    if (std::min({desc.conductor_eta->x, desc.conductor_eta->y, desc.conductor_eta->z}) <= 0.0f)
      fail_at(*eta, material.field("eta") + " must be above 0 in each channel");
    if (std::min({desc.conductor_k->x, desc.conductor_k->y, desc.conductor_k->z}) < 0.0f)
      fail_at(*k, material.field("k") + " must be 0 or more in each channel");
  }
}

// A principled material's weights and colours, each from 0 to 1.
void read_principled_keys(const MappingReader& material, MaterialDesc& desc) {
  PrincipledDesc& p = desc.principled;
  const auto unit = [&](const char* key, float& value) {
    const YamlNode* node = material.optional(key);
    if (!node) return;
    value = read_non_negative(*node, material.field(key));
    if (value > 1.0f) fail_at(*node, material.field(key) + " must be from 0 to 1, got " + std::string(node->scalar()));
  };
  const auto unit_color = [&](const char* key, Color& value) {
    const YamlNode* node = material.optional(key);
    if (!node) return;
    value = read_color(*node, material.field(key));
    if (max_component(value) > 1.0f) fail_at(*node, material.field(key) + " must be from 0 to 1 in each channel");
  };
  unit("metalness", p.metalness);
  unit("specular_weight", p.specular_weight);
  unit_color("specular_color", p.specular_color);
  unit("transmission_weight", p.transmission_weight);
  unit("coat_weight", p.coat_weight);
  unit("coat_roughness", p.coat_roughness);
  unit_color("fuzz_color", p.fuzz_color);
  unit("fuzz_roughness", p.fuzz_roughness);
}

MaterialDesc read_material(const std::string& name, const YamlNode& node, const std::filesystem::path& folder) {
  if (!node.is_mapping())
    fail_at(node, "material '" + name + "': expected a mapping such as {type: diffuse, color: [0.8, 0.8, 0.8]}, got " +
                      node.describe());
  MaterialDesc desc;
  desc.name = name;
  if (const YamlEntry* type = node.find("type"))
    desc.kind = read_material_kind(*type->value, "material '" + name + "'.type");
  const std::vector<std::string_view> keys = material_keys(desc.kind);
  const MappingReader material(node, "material '" + name + "'", keys);
  read_emission(material, desc);
  // glTF's default roughness is 1 and OpenPBR's 0.3; a principled material without one is in between.
  if (desc.kind == MaterialKind::kPrincipled) desc.roughness = 0.5f;
  read_microfacet_keys(material, desc);
  if (desc.kind == MaterialKind::kPrincipled) read_principled_keys(material, desc);
  if (const YamlNode* color = material.optional("color")) {
    if (color->is_mapping() && color->find("texture")) {
      read_image_texture(*color, material.field("color"), folder, desc);
    } else if (color->is_mapping()) {
      desc.checker = read_checker(*color, material.field("color"));
    } else {
      desc.color = read_color(*color, material.field("color"));
    }
  }
  if (const YamlNode* specular = material.optional("specular"))
    desc.specular = read_non_negative(*specular, material.field("specular"));
  if (const YamlNode* shininess = material.optional("shininess"))
    desc.shininess = read_non_negative(*shininess, material.field("shininess"));
  if (const YamlNode* reflectivity = material.optional("reflectivity")) {
    desc.reflectivity = read_non_negative(*reflectivity, material.field("reflectivity"));
    if (desc.reflectivity > 1.0f)
      fail_at(*reflectivity,
              material.field("reflectivity") + " must be from 0 to 1, got " + std::string(reflectivity->scalar()));
  }
  if (desc.kind == MaterialKind::kDielectric || desc.kind == MaterialKind::kPrincipled) desc.ior = 1.5f;
  if (const YamlNode* ior = material.optional("ior")) {
    const double index = read_number(*ior, material.field("ior"));
    if (!(index > 0.0) || !(index <= 100.0))
      fail_at(*ior, material.field("ior") + " is an index of refraction: above 0 (glass 1.5, water 1.33), got " +
                        std::string(ior->scalar()));
    desc.ior = static_cast<float>(index);
  }
  const YamlNode* transmittance = material.optional("transmittance");
  const YamlNode* distance = material.optional("transmittance_distance");
  if ((transmittance || distance) && !desc.ior)
    fail_at(transmittance ? *transmittance : *distance,
            material.field(transmittance ? "transmittance" : "transmittance_distance") +
                " describes absorption inside glass: give the material an ior too");
  if (transmittance) {
    desc.transmittance = read_color(*transmittance, material.field("transmittance"));
    if (std::max({desc.transmittance.x, desc.transmittance.y, desc.transmittance.z}) > 1.0f)
      fail_at(*transmittance, material.field("transmittance") + " is a fraction of light kept: each channel 0 to 1");
  }
  if (distance) {
    const double d = read_number(*distance, material.field("transmittance_distance"));
    if (!(d > 0.0) || !std::isfinite(static_cast<float>(d)))
      fail_at(*distance, material.field("transmittance_distance") + " must be a positive distance, got " +
                             std::string(distance->scalar()));
    desc.transmittance_distance = static_cast<float>(d);
  }
  return desc;
}

}  // namespace

std::vector<MaterialDesc> read_materials(const YamlNode* node, const std::filesystem::path& folder) {
  std::vector<MaterialDesc> materials(1);
  materials[0].name = "default";
  if (!node || node->is_null()) return materials;
  if (!node->is_mapping())
    fail_at(*node, "materials: expected a mapping of name: {color: ...}, got " + node->describe());
  for (const YamlEntry& entry : node->entries()) {
    MaterialDesc material = read_material(std::string(entry.key), *entry.value, folder);
    if (entry.key == "default") {
      materials[0] = std::move(material);
    } else {
      materials.push_back(std::move(material));
    }
  }
  return materials;
}

}  // namespace rtpro
