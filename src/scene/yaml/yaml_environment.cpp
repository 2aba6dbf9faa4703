#include "yaml_environment.h"

#include "rtpro/core/special_file_kind.h"

#include "yaml_reader.h"
#include "yaml_transform.h"
#include "rtpro/scene/render_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <system_error>

namespace rtpro {

namespace {

// The formats whose values are radiance as stored (no display encoding to undo).
bool is_scene_linear_format(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* linear : {".exr", ".hdr", ".rgbe", ".pfm"})
    if (extension == linear) return true;
  return false;
}

bool read_bool(const YamlNode& node, const std::string& name) {
  return read_keyword<bool>(node, name, {{"true", true}, {"false", false}});
}

}  // namespace

std::optional<EnvironmentDesc> read_environment(const YamlNode* node, const std::filesystem::path& folder) {
  if (!node || node->is_null()) return std::nullopt;
  const MappingReader environment(*node, "environment", {"file", "color", "intensity", "rotation", "visible"});
  EnvironmentDesc desc;
  if (const YamlNode* file = environment.optional("file")) {
    const std::string written = read_string(*file, environment.field("file"));
    if (written.empty()) fail_at(*file, environment.field("file") + " must name a latitude-longitude image file");
    desc.file = folder / written;
    desc.file_where = file->at.location();
    if (const std::string problem = unreadable_file_problem(desc.file); !problem.empty())
      fail_at(*file, environment.field("file") + ": image file '" + desc.file.string() + "' " + problem);
    if (!is_scene_linear_format(desc.file))
      fail_at(*file, environment.field("file") + ": '" + desc.file.string() +
                         "' is not a scene-linear image; an environment is read from an EXR, Radiance HDR or PFM file");
  }
  if (const YamlNode* color = environment.optional("color"))
    desc.color = read_color(*color, environment.field("color"));
  if (const YamlNode* intensity = environment.optional("intensity")) {
    const double value = read_number(*intensity, environment.field("intensity"));
    if (!(value >= 0.0) || !std::isfinite(static_cast<float>(value)))
      fail_at(*intensity, environment.field("intensity") + " must be 0 or more and finite, got " +
                              std::string(intensity->scalar()));
    desc.intensity = static_cast<float>(value);
    const float brightest = std::max({desc.color.x, desc.color.y, desc.color.z}) * desc.intensity;
    if (desc.file.empty() && !(brightest <= kMaxEnvironmentRadiance))
      fail_at(*intensity, environment.field("intensity") + ": color x intensity is " + std::to_string(brightest) +
                              ", more than the most radiance an environment may have (1e12)");
  }
  if (const YamlNode* rotation = environment.optional("rotation"))
    desc.rotation = read_rotation(*rotation, environment.field("rotation"));
  if (const YamlNode* visible = environment.optional("visible"))
    desc.visible = read_bool(*visible, environment.field("visible"));
  return desc;
}

}  // namespace rtpro
