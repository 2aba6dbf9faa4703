#include "yaml_volume_entry.h"

#include "rtpro/core/printable_text.h"
#include "yaml_reader.h"
#include "yaml_transform.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace rtpro {

namespace {

std::filesystem::path resolve_volume_file(const YamlNode& node, const std::string& field,
                                          const std::filesystem::path& folder) {
  const std::string written = read_string(node, field);
  const std::filesystem::path base = node.at.line > 0 ? std::filesystem::path(*node.at.source).parent_path() : folder;
  const std::filesystem::path file = (base / written).lexically_normal();
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".vdb") fail_at(node, field + ": '" + printable_text(written) + "' is not an OpenVDB file (.vdb)");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
    fail_at(node, field + ": volume file '" + printable_text(written) + "' not found (looked for '" +
                      printable_text(file.string()) + "')");
  if (!std::filesystem::is_regular_file(status))
    fail_at(node, field + ": '" + printable_text(file.string()) + "' is not a file");
  return file;
}

std::string read_grid_name(const YamlNode& node, const std::string& field) {
  std::string name = read_string(node, field);
  if (name.empty()) fail_at(node, field + ": expected a grid name, got an empty string");
  return name;
}

}  // namespace

VolumeDesc read_volume_entry(const YamlNode& node, const std::filesystem::path& folder) {
  const MappingReader volume(node, "volume",
                             {"type", "file", "grid", "density_scale", "albedo", "anisotropy", "emission_grid",
                              "emission", "emission_scale", "temperature_grid", "temperature_scale", "transform"});
  VolumeDesc desc;
  const YamlNode& file = volume.required("file");
  desc.file = resolve_volume_file(file, volume.field("file"), folder);
  desc.where = file.at.location();
  if (const YamlNode* grid = volume.optional("grid")) desc.grid = read_grid_name(*grid, volume.field("grid"));
  if (const YamlNode* scale = volume.optional("density_scale"))
    desc.density_scale = read_non_negative(*scale, volume.field("density_scale"));
  if (const YamlNode* albedo = volume.optional("albedo")) {
    desc.albedo = read_color(*albedo, volume.field("albedo"));
    if (max_component(desc.albedo) > 1.0f)
      fail_at(*albedo, volume.field("albedo") + ": each component is σs/σt, between 0 and 1");
  }
  if (const YamlNode* g = volume.optional("anisotropy")) {
    desc.anisotropy = static_cast<float>(read_number(*g, volume.field("anisotropy")));
    if (!(desc.anisotropy > -1.0f && desc.anisotropy < 1.0f))
      fail_at(*g, volume.field("anisotropy") + ": the Henyey-Greenstein g must lie strictly between -1 and 1");
  }
  if (const YamlNode* grid = volume.optional("emission_grid"))
    desc.emission_grid = read_grid_name(*grid, volume.field("emission_grid"));
  if (const YamlNode* emission = volume.optional("emission"))
    desc.emission = read_color(*emission, volume.field("emission"));
  if (const YamlNode* scale = volume.optional("emission_scale"))
    desc.emission_scale = read_non_negative(*scale, volume.field("emission_scale"));
  if (const YamlNode* grid = volume.optional("temperature_grid"))
    desc.temperature_grid = read_grid_name(*grid, volume.field("temperature_grid"));
  if (const YamlNode* scale = volume.optional("temperature_scale"))
    desc.temperature_scale = read_non_negative(*scale, volume.field("temperature_scale"));
  for (const char* key : {"emission", "emission_scale"})
    if (desc.emission_grid.empty() && volume.optional(key))
      fail_at(*volume.optional(key), volume.field(key) + " needs an emission_grid to scale");
  if (desc.temperature_grid.empty() && volume.optional("temperature_scale"))
    fail_at(*volume.optional("temperature_scale"), volume.field("temperature_scale") + " needs a temperature_grid");
  if (const YamlNode* transform = volume.optional("transform"))
    desc.transform = read_transform(*transform, volume.field("transform"));
  return desc;
}

}  // namespace rtpro
