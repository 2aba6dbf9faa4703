#include "yaml_shape_entry.h"

#include "rtpro/core/closest_match.h"
#include "yaml_light_linking.h"
#include "yaml_medium.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <utility>

namespace rtpro {

ShapeEntryReader::ShapeEntryReader(const std::vector<MaterialDesc>& materials, std::filesystem::path folder,
                                   SceneDescription& scene)
    : folder_(std::move(folder)), scene_(scene) {
  for (std::uint32_t i = 0; i < materials.size(); ++i) materials_.add(materials[i].name, i);
}

std::uint32_t ShapeEntryReader::material_index(const YamlNode& node, const std::string& field) const {
  const std::string name = read_string(node, field);
  const std::uint32_t* index = materials_.find(name);
  if (!index) fail_at(node, field + ": unknown material '" + name + "'" + suggestion(name, materials_.names()));
  return *index;
}

std::filesystem::path ShapeEntryReader::input_file(const YamlNode& node, const std::string& field,
                                                   std::initializer_list<std::string_view> extensions,
                                                   const std::string& formats, const std::string& what) const {
  const std::string written = read_string(node, field);
  const std::filesystem::path folder =
      node.at.line > 0 ? std::filesystem::path(*node.at.source).parent_path() : folder_;
  const std::filesystem::path file = (folder / written).lexically_normal();
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end())
    fail_at(node, field + ": '" + written + "' is not a " + what + " format rtpro reads (" + formats + ")");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
    fail_at(node, field + ": " + what + " file '" + written + "' not found (looked for '" + file.string() + "')");
  if (!std::filesystem::is_regular_file(status)) fail_at(node, field + ": '" + file.string() + "' is not a file");
  if (!std::ifstream(file, std::ios::binary))
    fail_at(node, field + ": cannot open " + what + " file '" + file.string() + "'");
  return file;
}

std::uint32_t ShapeEntryReader::read_linking(const MappingReader& entry) {
  std::optional<LightLinkingDesc> linking = read_light_linking(entry, scene_.light_names);
  if (!linking) return kNoLinking;
  if (!in_world_) {
    const YamlNode* key = entry.optional(kLightLinkingKey);
    fail_at(key ? *key : *entry.optional(kShadowLinkingKey),
            entry.field(key ? kLightLinkingKey : kShadowLinkingKey) +
                ": only the world's entries are light-linked; link the instance that places this object");
  }
  scene_.linkings.push_back(std::move(*linking));
  return static_cast<std::uint32_t>(scene_.linkings.size() - 1);
}

std::uint32_t ShapeEntryReader::with_interior(const MappingReader& entry, std::uint32_t material) {
  const YamlNode* interior = entry.optional("interior");
  if (!interior) return material;
  if (material == kNoMaterial)
    fail_at(*interior, entry.field("interior") +
                           " needs the entry's material: (the file's own materials would each need it); or give the "
                           "interior on the material");
  MaterialDesc inside = scene_.materials[material];
  inside.interior = read_medium(*interior, entry.field("interior"));
  inside.name += "+interior";
  scene_.materials.push_back(std::move(inside));
  return static_cast<std::uint32_t>(scene_.materials.size() - 1);
}

}  // namespace rtpro
