#include "yaml_materials.h"

#include "rtpro/core/special_file_kind.h"

#include "yaml_medium.h"
#include "yaml_reader.h"
#include "rtpro/core/overloaded.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

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
  if (const YamlNode* axes = checker.optional("axes"))
    desc.axes = read_keyword<CheckerAxes>(
        *axes, checker.field("axes"),
        {{"xz", CheckerAxes::kXZ}, {"xy", CheckerAxes::kXY}, {"yz", CheckerAxes::kYZ}, {"xyz", CheckerAxes::kXYZ}});
  return desc;
}

TextureWrap read_wrap(const YamlNode& node, const std::string& name) {
  return read_keyword<TextureWrap>(node, name,
                                   {{"repeat", TextureWrap::kRepeat},
                                    {"clamp", TextureWrap::kClamp},
                                    {"mirror", TextureWrap::kMirror},
                                    {"black", TextureWrap::kBlack}});
}

// `wrap: MODE` for both axes, or `wrap: [ACROSS, DOWN]` (glTF's wrapS, wrapT).
void read_wraps(const YamlNode& node, const std::string& name, TextureSampling& sampling) {
  if (!node.is_sequence()) {
    sampling.wrap_s = sampling.wrap_t = read_wrap(node, name);
    return;
  }
  const YamlNodeList axes = read_list(node, name, 2, "a wrap mode, or [across, down]");
  sampling.wrap_s = read_wrap(*axes[0], name + "[0]");
  sampling.wrap_t = read_wrap(*axes[1], name + "[1]");
}

// color: {texture: FILE, colorspace: srgb | linear | an OpenColorIO colour space, wrap: repeat |
// clamp | mirror | black (or [across, down]), filter: linear | nearest, tint: [r, g, b]}
void read_image_texture(const YamlNode& node, const std::string& name, const std::filesystem::path& folder,
                        MaterialDesc& desc) {
  const MappingReader texture(node, name, {"texture", "colorspace", "wrap", "filter", "tint"});
  const YamlNode& file = texture.required("texture");
  const std::string written = read_string(file, texture.field("texture"));
  if (written.empty()) fail_at(file, texture.field("texture") + " must name an image file");
  desc.color_texture = folder / written;
  desc.texture_where = file.at.location();
  if (const std::string problem = unreadable_file_problem(desc.color_texture); !problem.empty())
    fail_at(file, texture.field("texture") + ": image file '" + desc.color_texture.string() + "' " + problem);
  if (const YamlNode* colorspace = texture.optional("colorspace")) {
    const std::string text = read_string(*colorspace, texture.field("colorspace"));
    desc.texture_colorspace = text == "srgb" ? "sRGB - Texture" : text == "linear" ? "Linear Rec.709 (sRGB)" : text;
  }
  if (const YamlNode* wrap = texture.optional("wrap")) read_wraps(*wrap, texture.field("wrap"), desc.texture_sampling);
  if (const YamlNode* filter = texture.optional("filter"))
    desc.texture_sampling.filter = read_keyword<TextureFilter>(
        *filter, texture.field("filter"), {{"linear", TextureFilter::kLinear}, {"nearest", TextureFilter::kNearest}});
  desc.color = Color(1.0f);
  if (const YamlNode* tint = texture.optional("tint")) desc.color = read_color(*tint, texture.field("tint"));
}

// What a scene file calls each kind of material (its `type:`), the keys it reads and how it reads
// them are the kind's own (scene/phong_material.h and its neighbours): the visits below name any
// of them a new kind lacks.
const char* material_type(const MaterialParams& kind) {
  return std::visit([](const auto& params) { return material_type_name(params); }, kind);
}

// One material of every kind, in MaterialParams' order, with the kind's defaults.
template <std::size_t... I>
std::vector<MaterialParams> every_material_kind(std::index_sequence<I...>) {
  return {MaterialParams(std::in_place_index<I>)...};
}

MaterialParams read_material_kind(const YamlNode& node, const std::string& name) {
  static const std::vector<MaterialParams> kinds =
      every_material_kind(std::make_index_sequence<std::variant_size_v<MaterialParams>>());
  const std::string text = read_string(node, name);
  std::vector<std::string_view> types;
  for (const MaterialParams& kind : kinds) {
    if (text == material_type(kind)) return kind;
    types.push_back(material_type(kind));
  }
  fail_not_one_of(node, name, text, types);
}

// The keys a material may have: type, colour and emission, and its kind's own, so that a key of
// another kind (a conductor's `reflectivity`) is an error, not silently ignored.
std::vector<std::string_view> allowed_keys(const MaterialParams& kind) {
  std::vector<std::string_view> keys{"type", "color", "emission", "emission_strength", "emission_sides", "interior"};
  const std::vector<std::string_view> own = std::visit([](const auto& params) { return material_keys(params); }, kind);
  keys.insert(keys.end(), own.begin(), own.end());
  return keys;
}

// emission: [r, g, b] radiance, times emission_strength (1), from the front side or both
// (emission_sides: front | both).
void read_emission(const MappingReader& material, MaterialDesc& desc) {
  const YamlNode* emission = material.optional("emission");
  const YamlNode* strength = material.optional("emission_strength");
  const YamlNode* sides = material.optional("emission_sides");
  // A model's material read over (model_materials) may qualify the emission it already has.
  if (!emission && (strength || sides) && !(max_component(desc.emission) > 0.0f))
    fail_at(strength ? *strength : *sides, material.field(strength ? "emission_strength" : "emission_sides") +
                                               " qualifies the emission: give the material an emission colour too");
  if (emission) {
    desc.emission = read_vec3(*emission, material.field("emission"));  // radiance: no 1-is-full rule
    if (std::min({desc.emission.x, desc.emission.y, desc.emission.z}) < 0.0f)
      fail_at(*emission, material.field("emission") + " is emitted radiance: each channel 0 or more");
  }
  if (strength) {
    const float factor = read_non_negative(*strength, material.field("emission_strength"));
    desc.emission = desc.emission * factor;
    if (!is_finite(desc.emission))
      fail_at(*strength, material.field("emission_strength") + " makes the emission overflow");
  }
  if (sides)
    desc.emission_two_sided =
        read_keyword<bool>(*sides, material.field("emission_sides"), {{"front", false}, {"both", true}});
}

// Whether a kind's `color` is a reflectance, from 0 to 1 in each channel: above 1 a surface
// reflects more light than it receives and a path's weight grows with every bounce (pixels near
// 1e33). Phong's colour is not held to it (Whitted and POV-Ray scenes brighten a pigment above 1),
// nor the dielectric's, which is unused.
bool colour_is_reflectance(const MaterialParams& kind) {
  return std::visit(
      Overloaded{[](const PhongParams&) { return false; }, [](const DiffuseParams&) { return true; },
                 [](const ConductorParams&) { return true; }, [](const DielectricParams&) { return false; },
                 [](const PrincipledParams&) { return true; }, [](const HairParams&) { return true; },
                 [](const InterfaceParams&) { return false; }},
      kind);
}

void require_reflectance(const YamlNode& node, const std::string& field, const Color& colour) {
  if (max_component(colour) > 1.0f)
    fail_at(node, field + " is a reflectance: each channel from 0 to 1 (light above 1 is an emission)");
}

// Read over `desc`: the keys the entry gives replace its values, the others stay (a fresh material's
// defaults, or a model's material). A `type:` of another kind starts that kind from its defaults.
MaterialDesc read_material(const std::string& name, const YamlNode& node, const std::filesystem::path& folder,
                           MaterialDesc desc = {}) {
  if (!node.is_mapping())
    fail_at(node, "material '" + name + "': expected a mapping such as {type: diffuse, color: [0.8, 0.8, 0.8]}, got " +
                      node.describe());
  desc.name = name;
  if (const YamlEntry* type = node.find("type")) {
    MaterialParams kind = read_material_kind(*type->value, "material '" + name + "'.type");
    if (kind.index() != desc.params.index()) desc.params = std::move(kind);
  }
  const std::vector<std::string_view> keys = allowed_keys(desc.params);
  const MappingReader material(node, "material '" + name + "'", keys);
  read_emission(material, desc);
  std::visit([&](auto& params) { read_material_params(material, params); }, desc.params);
  if (const YamlNode* interior = material.optional("interior")) {
    if (material.optional("transmittance") || material.optional("transmittance_distance"))
      fail_at(*interior, material.field("interior") +
                             " replaces the glass's transmittance: give its absorption as the interior's sigma_a");
    desc.interior = read_medium(*interior, material.field("interior"));
  }
  if (const YamlNode* color = material.optional("color")) {
    if (color->is_mapping() && color->find("texture")) {
      read_image_texture(*color, material.field("color"), folder, desc);
    } else if (color->is_mapping()) {
      desc.checker = read_checker(*color, material.field("color"));
    } else {
      desc.color = read_color(*color, material.field("color"));
    }
    if (colour_is_reflectance(desc.params)) {
      require_reflectance(*color, material.field("color"), desc.color);
      if (desc.checker) {
        require_reflectance(*color, material.field("color") + ".colors[0]", desc.checker->even);
        require_reflectance(*color, material.field("color") + ".colors[1]", desc.checker->odd);
      }
    }
  }
  return desc;
}

}  // namespace

std::vector<MaterialDesc> read_materials(const YamlNode* node, const std::filesystem::path& folder,
                                         std::vector<MaterialDesc>* model_materials) {
  std::vector<MaterialDesc> materials(1);
  materials[0].name = "default";
  if (!node || node->is_null()) return materials;
  if (!node->is_mapping())
    fail_at(*node, "materials: expected a mapping of name: {color: ...}, got " + node->describe());
  for (const YamlEntry& entry : node->entries()) {
    bool model_material = false;
    for (std::size_t i = 0; model_materials && i < model_materials->size(); ++i) {
      MaterialDesc& m = (*model_materials)[i];
      if (m.name != entry.key) continue;
      m = read_material(m.name, *entry.value, folder, m);
      model_material = true;
    }
    if (model_material) continue;
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
