#include "model_scene.h"

#include "rtpro/core/closest_match.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/scene/scene_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rtpro {

namespace {

constexpr float kDefaultFov = 40.0f;
// What an error about the text's first lines, or about the scene as a whole, is about.
constexpr const char* kWholeScene = "the scene rtpro makes of the file";

std::string bounds_text(const BBox& bounds) {
  char text[160];
  std::snprintf(text, sizeof text, "[%.3g, %.3g, %.3g] .. [%.3g, %.3g, %.3g]", bounds.lower.x, bounds.lower.y,
                bounds.lower.z, bounds.upper.x, bounds.upper.y, bounds.upper.z);
  return text;
}

// Whether a shape of the scene draws with materials[index]: only then may an override add a
// material the model does not have (`--set materials.clay=... --set world.0.material=clay`).
bool material_in_use(const SceneDescription& scene, std::uint32_t index) {
  bool used = false;
  const auto check = [&](const ObjectDesc& object) {
    visit_shape_lists(object, [&](const auto& shapes) {
      for (const auto& shape : shapes) used = used || shape.material == index;
    });
  };
  check(scene.world);
  for (const ObjectDesc& object : scene.objects) check(object);
  return used;
}

// The override that wrote materials.NAME (the first that names it, or the whole `materials`).
std::string override_of_material(const std::vector<std::string>& overrides, const std::string& name) {
  for (const std::string& o : overrides)
    for (const std::string& spelt : {name, '"' + name + '"', '\'' + name + '\''})
      if (o.starts_with("materials." + spelt + ".") || o.starts_with("materials." + spelt + "=")) return o;
  for (const std::string& o : overrides)
    if (o.starts_with("materials")) return o;
  return overrides.empty() ? std::string() : overrides.front();
}

// Materials the text does not write come from overrides: one the model lacks that nothing draws
// with is a misspelt name, which would otherwise change nothing.
void check_override_materials(const SceneDescription& scene, const std::vector<MaterialDesc>& model,
                              const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::vector<std::string> names{"default"};
  for (const MaterialDesc& m : model)
    if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
  for (std::uint32_t i = 1; i < scene.materials.size(); ++i) {
    if (material_in_use(scene, i)) continue;
    const std::string& name = scene.materials[i].name;
    std::string listed;
    for (std::size_t n = 0; n < names.size() && n < 12; ++n) listed += (n ? ", " : "") + printable_text(names[n], 80);
    if (names.size() > 12) listed += ", ...";
    std::string hint = suggestion(name, names);
    if (hint.starts_with("; expected one of")) hint.clear();
    throw InputError(SourceLocation{override_source(override_of_material(overrides, name))},
                     printable_text(file.filename().string(), 200) + " has no material '" + printable_text(name, 80) +
                         "'" + hint + " (its materials: " + listed + ")");
  }
}

// Under an environment (--environment, --set environment=...) the default light is not wanted:
// it was there only because nothing else lit the model.
bool drop_default_light(SceneDescription& scene) {
  if (!scene.environment) return false;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    if (scene.light_names[i] != kDefaultLightName) continue;
    scene.lights.erase(scene.lights.begin() + std::ptrdiff_t(i));
    scene.light_names.erase(scene.light_names.begin() + std::ptrdiff_t(i));
    scene.light_sources.erase(scene.light_sources.begin() + std::ptrdiff_t(i));
    return true;
  }
  return false;
}

void add_notes(const ModelSceneParts& parts, const std::filesystem::path& file, bool default_light_dropped,
               SceneDescription& scene) {
  const std::string name = printable_text(file.filename().string(), 200);
  if (!parts.has_camera)
    scene.notes.push_back(name + " has no camera: rtpro frames its bounds, " +
                          (parts.bounds.empty() ? std::string("empty") : bounds_text(parts.bounds)) +
                          ", with a 40° view from the front (--set camera.position=[x,y,z] to move it)");
  if (parts.has_lights || scene.environment) return;
  if (parts.emits) {
    scene.notes.push_back(name +
                          " has no lights: it is lit only by emissive surfaces (--environment FILE|R,G,B adds light)");
  } else if (!default_light_dropped) {
    scene.notes.push_back(name + " has no lights and nothing emissive: rtpro adds a directional light ('" +
                          kDefaultLightName +
                          "') and a grey sky of radiance 0.18 (--environment FILE|R,G,B lights it instead)");
  }
}

}  // namespace

void ModelSceneText::add(const std::string& line, const std::string& origin) {
  yaml += line + "\n";
  origin_of_line.push_back(origin);
}

const std::string& ModelSceneText::origin(int line) const {
  static const std::string whole_scene = kWholeScene;
  return line >= 1 && std::size_t(line) <= origin_of_line.size() ? origin_of_line[std::size_t(line) - 1] : whole_scene;
}

std::string yaml_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string yaml_vector(const Vec3& v) {
  return "[" + yaml_number(v.x) + ", " + yaml_number(v.y) + ", " + yaml_number(v.z) + "]";
}

bool writable_in_yaml(std::string_view name) {
  for (std::size_t i = 0; i < name.size();) {
    const std::size_t length = utf8_sequence_length(name.substr(i));
    if (length == 0) return false;
    i += length;
  }
  return true;
}

// Quotes and backslashes escaped, control characters as \xNN, and `$` doubled (the text goes
// through variable substitution, which would read the `$b` of `a$b.glb` as a variable).
std::string quoted_yaml(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '$') out += '$';
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[static_cast<unsigned char>(c) >> 4] + hex[c & 15];
      continue;
    }
    out += c;
  }
  return out + "\"";
}

void add_model_header(const std::filesystem::path& file, ModelSceneText& text) {
  text.add("# " + printable_text(file.filename().string(), 200) + " as a scene", kWholeScene);
  text.add("rtpro: 1", kWholeScene);
}

void add_framing_camera(const BBox& bounds, const std::string& origin, ModelSceneText& text) {
  Vec3 center(0.0f, 0.0f, 0.0f);
  float radius = 1.0f;
  if (!bounds.empty()) {
    center = bounds.center();
    radius = std::max(0.5f * length(bounds.extent()), 1e-6f * std::max(1.0f, max_component(abs(center))));
  }
  const Vec3 direction = normalize(Vec3(0.35f, 0.3f, 1.0f));
  const float distance = radius / std::sin(0.5f * kDefaultFov * 3.14159265f / 180.0f) * 1.05f;
  text.add("camera: {position: " + yaml_vector(center + direction * distance) + ", look_at: " + yaml_vector(center) +
               ", fov: " + yaml_number(kDefaultFov) + ", resolution: [" + std::to_string(kModelImageWidth) + ", " +
               std::to_string(kModelImageHeight) + "]}",
           origin);
}

// A model file as the whole scene is path traced. What lights it is the file's own lights and
// emissive materials; only a file with neither gets the sun and a grey sky (a uniform environment
// of radiance 0.18 that escaping paths see), a lookdev studio's neutral default.
void add_model_lighting(bool lit, ModelSceneText& text) {
  text.add(std::string("render: {integrator: path, background: ") + (lit ? "[0, 0, 0]" : "[0.18, 0.18, 0.18]") + "}",
           "the render settings rtpro gives a model file");
  if (lit) return;
  const std::string origin = "the light rtpro adds (the file has no lights and nothing emissive)";
  text.add("lights:", origin);
  text.add("  - {type: directional, direction: [-0.3, -0.8, -0.5], intensity: 0.9, name: " +
               quoted_yaml(kDefaultLightName) + "}",
           origin);
}

SceneDescription parse_model_scene(const ModelSceneParts& parts, const std::filesystem::path& file,
                                   const std::vector<std::string>& overrides) {
  SceneDescription scene = [&] {
    try {
      return parse_scene_text(parts.text.yaml, file, overrides, parts.materials);
    } catch (const InputError& e) {
      // A line of the text, which the user never saw: named by what it was written for. Errors
      // about an override keep its own source.
      if (e.where().file != file.string() || e.where().line == 0) throw;
      throw InputError(SourceLocation{file.string()}, parts.text.origin(e.where().line) + ": " + e.message());
    }
  }();
  static const std::vector<MaterialDesc> none;
  check_override_materials(scene, parts.materials ? *parts.materials : none, file, overrides);
  const bool dropped = drop_default_light(scene);
  add_notes(parts, file, dropped, scene);
  return scene;
}

}  // namespace rtpro
