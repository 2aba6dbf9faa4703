#include "gltf_json_types.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "rtpro/core/printable_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <utility>

namespace rtpro::gltf {

namespace {

using Json = nlohmann::json;

enum class JsonKind { kObject, kArray, kIndex, kNumber, kString, kBool };

const char* expected_name(JsonKind kind) {
  switch (kind) {
    case JsonKind::kObject: return "an object";
    case JsonKind::kArray: return "an array";
    case JsonKind::kIndex: return "a non-negative integer";
    case JsonKind::kNumber: return "a number";
    case JsonKind::kString: return "a string";
    case JsonKind::kBool: return "true or false";
  }
  return "?";
}

std::string found_name(const Json& value) {
  switch (value.type()) {
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "the string " + ascii::quoted(value.get_ref<const std::string&>());
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::null: return "null";
    default: return value.dump();
  }
}

bool is_kind(const Json& value, JsonKind kind) {
  switch (kind) {
    case JsonKind::kObject: return value.is_object();
    case JsonKind::kArray: return value.is_array();
    case JsonKind::kNumber: return value.is_number();
    case JsonKind::kString: return value.is_string();
    case JsonKind::kBool: return value.is_boolean();
    case JsonKind::kIndex:
      if (value.is_number_unsigned()) return true;
      if (value.is_number_float()) {  // 2.0 is read as 2 by tinygltf
        const double number = value.get<double>();
        return number >= 0.0 && number <= 2147483647.0 && std::floor(number) == number;
      }
      return false;
  }
  return false;
}

class TypeCheck {
 public:
  explicit TypeCheck(const std::string& file) : file_(file) {}

  void document(const Json& root) {
    if (!root.is_object()) return;  // tinygltf says so
    // glTF 1.0 is laid out differently (objects where 2.0 has arrays): refused by its version later.
    const auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object()) return;
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string() || version->get_ref<const std::string&>().rfind("2.", 0) != 0)
      return;
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) elements(root, key, JsonKind::kString, key);
    member(root, "scene", JsonKind::kIndex, "scene");
    member(root, "asset", JsonKind::kObject, "asset");
    each_object(root, "scenes", [&](const Json& scene, const std::string& path) {
      elements(scene, "nodes", JsonKind::kIndex, path + ".nodes");
    });
    each_object(root, "nodes", [&](const Json& node, const std::string& path) { this->node(node, path); });
    each_object(root, "meshes", [&](const Json& mesh, const std::string& path) { this->mesh(mesh, path); });
    using enum JsonKind;
    flat_objects(root, "accessors",
                 {{"bufferView", kIndex},
                  {"byteOffset", kIndex},
                  {"componentType", kIndex},
                  {"count", kIndex},
                  {"type", kString},
                  {"normalized", kBool},
                  {"sparse", kObject}});
    flat_objects(root, "bufferViews",
                 {{"buffer", kIndex}, {"byteOffset", kIndex}, {"byteLength", kIndex}, {"byteStride", kIndex}});
    flat_objects(root, "buffers", {{"uri", kString}, {"byteLength", kIndex}});
    each_object(root, "materials",
                [&](const Json& material, const std::string& path) { this->material(material, path); });
    flat_objects(root, "textures", {{"source", kIndex}, {"sampler", kIndex}});
    flat_objects(root, "images", {{"uri", kString}, {"mimeType", kString}, {"bufferView", kIndex}});
    flat_objects(root, "samplers",
                 {{"magFilter", kIndex}, {"minFilter", kIndex}, {"wrapS", kIndex}, {"wrapT", kIndex}});
    each_object(root, "cameras", [&](const Json& camera, const std::string& path) {
      member(camera, "type", JsonKind::kString, path + ".type");
      for (const char* kind : {"perspective", "orthographic"})
        if (const Json* projection = member(camera, kind, JsonKind::kObject, path + "." + kind))
          for (const char* key : {"aspectRatio", "yfov", "zfar", "znear", "xmag", "ymag"})
            member(*projection, key, JsonKind::kNumber, path + "." + kind + "." + key);
    });
    each_object(root, "skins", [](const Json&, const std::string&) {});
    each_object(root, "animations", [](const Json&, const std::string&) {});
    extensions(root, "extensions");
  }

 private:
  // The member `key` of `object` when present, after checking its kind; null when absent.
  const Json* member(const Json& object, const char* key, JsonKind kind, const std::string& path) {
    const auto found = object.find(key);
    if (found == object.end()) return nullptr;
    if (!is_kind(*found, kind)) fail(path, *found, kind);
    return &*found;
  }

  // An array member whose elements are all of `kind`.
  void elements(const Json& object, const char* key, JsonKind kind, const std::string& path) {
    const Json* array = member(object, key, JsonKind::kArray, path);
    if (!array) return;
    for (std::size_t i = 0; i < array->size(); ++i)
      if (!is_kind((*array)[i], kind)) fail(path + "[" + std::to_string(i) + "]", (*array)[i], kind);
  }

  // The array `key` of `root`, of objects whose members named in `kinds` are of their kind where
  // present (the arrays of the glTF schema without nested objects to check).
  void flat_objects(const Json& root, const char* key, std::initializer_list<std::pair<const char*, JsonKind>> kinds) {
    each_object(root, key, [&](const Json& object, const std::string& path) {
      for (const auto& [name, kind] : kinds) member(object, name, kind, path + "." + name);
    });
  }

  template <typename Visit>
  void each_object(const Json& object, const char* key, Visit visit, const std::string& prefix = "") {
    const std::string path = prefix.empty() ? std::string(key) : prefix + "." + key;
    const Json* array = member(object, key, JsonKind::kArray, path);
    if (!array) return;
    for (std::size_t i = 0; i < array->size(); ++i) {
      const std::string element = path + "[" + std::to_string(i) + "]";
      if (!(*array)[i].is_object()) fail(element, (*array)[i], JsonKind::kObject);
      visit((*array)[i], element);
    }
  }

  // `extensions`: an object of objects, one per extension.
  void extensions(const Json& object, const std::string& path) {
    const Json* all =
        member(object, "extensions", JsonKind::kObject, path == "extensions" ? path : path + ".extensions");
    if (!all) return;
    const std::string prefix = path == "extensions" ? path : path + ".extensions";
    for (const auto& [name, value] : all->items())
      if (!value.is_object()) fail(prefix + "." + printable_text(name, 100), value, JsonKind::kObject);
  }

  void node(const Json& node, const std::string& path) {
    elements(node, "children", JsonKind::kIndex, path + ".children");
    for (const char* key : {"mesh", "camera", "skin"}) member(node, key, JsonKind::kIndex, path + "." + key);
    for (const char* key : {"matrix", "translation", "rotation", "scale", "weights"})
      elements(node, key, JsonKind::kNumber, path + "." + key);
    extensions(node, path);
    if (const auto all = node.find("extensions"); all != node.end())
      if (const auto lights = all->find("KHR_lights_punctual"); lights != all->end())
        member(*lights, "light", JsonKind::kIndex, path + ".extensions.KHR_lights_punctual.light");
  }

  void mesh(const Json& mesh, const std::string& path) {
    each_object(
        mesh, "primitives",
        [&](const Json& primitive, const std::string& primitive_path) {
          if (const Json* attributes =
                  member(primitive, "attributes", JsonKind::kObject, primitive_path + ".attributes"))
            for (const auto& [name, value] : attributes->items())
              if (!is_kind(value, JsonKind::kIndex))
                fail(primitive_path + ".attributes." + printable_text(name, 100), value, JsonKind::kIndex);
          for (const char* key : {"indices", "material", "mode"})
            member(primitive, key, JsonKind::kIndex, primitive_path + "." + key);
          member(primitive, "targets", JsonKind::kArray, primitive_path + ".targets");
          extensions(primitive, primitive_path);
        },
        path);
    elements(mesh, "weights", JsonKind::kNumber, path + ".weights");
  }

  void material(const Json& material, const std::string& path) {
    if (const Json* pbr = member(material, "pbrMetallicRoughness", JsonKind::kObject, path + ".pbrMetallicRoughness")) {
      const std::string pbr_path = path + ".pbrMetallicRoughness";
      elements(*pbr, "baseColorFactor", JsonKind::kNumber, pbr_path + ".baseColorFactor");
      member(*pbr, "metallicFactor", JsonKind::kNumber, pbr_path + ".metallicFactor");
      member(*pbr, "roughnessFactor", JsonKind::kNumber, pbr_path + ".roughnessFactor");
      texture_info(*pbr, "baseColorTexture", pbr_path);
      texture_info(*pbr, "metallicRoughnessTexture", pbr_path);
    }
    if (const Json* normal = texture_info(material, "normalTexture", path))
      member(*normal, "scale", JsonKind::kNumber, path + ".normalTexture.scale");
    if (const Json* occlusion = texture_info(material, "occlusionTexture", path))
      member(*occlusion, "strength", JsonKind::kNumber, path + ".occlusionTexture.strength");
    texture_info(material, "emissiveTexture", path);
    elements(material, "emissiveFactor", JsonKind::kNumber, path + ".emissiveFactor");
    member(material, "alphaMode", JsonKind::kString, path + ".alphaMode");
    member(material, "alphaCutoff", JsonKind::kNumber, path + ".alphaCutoff");
    member(material, "doubleSided", JsonKind::kBool, path + ".doubleSided");
    extensions(material, path);
  }

  // A textureInfo: `index` required, `texCoord` optional, both non-negative integers.
  const Json* texture_info(const Json& owner, const char* key, const std::string& owner_path) {
    const std::string path = owner_path + "." + key;
    const Json* info = member(owner, key, JsonKind::kObject, path);
    if (!info) return nullptr;
    if (!info->contains("index")) throw InputError(SourceLocation{file_}, path + ".index: missing");
    member(*info, "index", JsonKind::kIndex, path + ".index");
    member(*info, "texCoord", JsonKind::kIndex, path + ".texCoord");
    extensions(*info, path);
    return info;
  }

  [[noreturn]] void fail(const std::string& path, const Json& found, JsonKind expected) const {
    std::string shown = found_name(found);
    if (shown.size() > 80) shown = shown.substr(0, 77) + "...";
    throw InputError(SourceLocation{file_},
                     path + ": " + expected_name(expected) + " expected, found " + printable_text(shown, 100));
  }

  const std::string& file_;
};

}  // namespace

void check_json_types(std::string_view json_text, const std::string& file) {
  const Json root = Json::parse(json_text.begin(), json_text.end(), nullptr, false);
  if (root.is_discarded()) return;
  TypeCheck(file).document(root);
}

}  // namespace rtpro::gltf
