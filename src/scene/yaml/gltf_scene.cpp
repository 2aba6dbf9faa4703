#include "gltf_scene.h"

#include "rtpro/core/printable_text.h"

#include "rtpro/scene/scene_parser.h"
#include "gltf_asset.h"
#include "gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

namespace rtpro {

namespace {

constexpr float kDefaultFov = 40.0f;
constexpr int kDefaultWidth = 640;
constexpr int kDefaultHeight = 480;
// What an error about the text's first lines, or about the scene as a whole, is about.
constexpr const char* kWholeScene = "the scene rtpro makes of the file";

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string vector(const Vec3& v) { return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]"; }

// The file name as a YAML string read back exactly: quotes and backslashes escaped, control
// characters as \xNN, and `$` doubled (the text goes through variable substitution, which would
// read the `$b` of `a$b.glb` as a variable).
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

// The file's first camera, or one that frames the placed meshes.
void add_camera(const GltfAsset& asset, const BBox& bounds, GltfSceneText& text) {
  if (!asset.cameras.empty()) {
    const GltfCamera& c = asset.cameras.front();
    const int height =
        c.aspect_ratio > 0.0f ? std::clamp(int(std::lround(kDefaultWidth / c.aspect_ratio)), 1, 65536) : kDefaultHeight;
    text.add("camera: {position: " + vector(c.position) + ", look_at: " + vector(c.position + c.forward) +
                 ", up: " + vector(c.up) + ", fov: " + number(c.yfov_degrees) + ", resolution: [" +
                 std::to_string(kDefaultWidth) + ", " + std::to_string(height) + "]}",
             gltf_node_path(c.node) + " (cameras[" + std::to_string(c.camera) + "])");
    return;
  }
  Vec3 center(0.0f, 0.0f, 0.0f);
  float radius = 1.0f;
  if (!bounds.empty()) {
    center = bounds.center();
    radius = std::max(0.5f * length(bounds.extent()), 1e-6f * std::max(1.0f, max_component(abs(center))));
  }
  // glTF models face +z with +y up: look at the front, a little from the right and above, from
  // where the bounding sphere just fits the view.
  const Vec3 direction = normalize(Vec3(0.35f, 0.3f, 1.0f));
  const float distance = radius / std::sin(0.5f * kDefaultFov * 3.14159265f / 180.0f) * 1.05f;
  text.add("camera: {position: " + vector(center + direction * distance) + ", look_at: " + vector(center) +
               ", fov: " + number(kDefaultFov) + ", resolution: [" + std::to_string(kDefaultWidth) + ", " +
               std::to_string(kDefaultHeight) + "]}",
           "the camera rtpro places to frame the meshes (the file has no perspective camera)");
}

// glTF's photometric units as radiometric ones, as Blender's importer reads them (683 lm/W): a
// point or spot light's candela become W/sr, a directional light's lux W/m².
constexpr float kLumensPerWatt = 683.0f;

// A spot light's cone, glTF's half-angles in radians as the scene format's degrees: computed in
// double and held to 90, so a float π/2 (just above it) stays within the format's limit, and
// printing (monotonic) keeps inner <= outer.
std::string spot_cone_yaml(const GltfLight& light) {
  constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
  const double outer = std::min(90.0, double(light.outer_cone_angle) * kDegreesPerRadian);
  const double inner = std::min(outer, double(light.inner_cone_angle) * kDegreesPerRadian);
  return ", inner_angle: " + number(inner) + ", outer_angle: " + number(outer);
}

bool has_emissive_material(const GltfAsset& asset) {
  return std::any_of(asset.materials.begin(), asset.materials.end(),
                     [](const MaterialDesc& m) { return max_component(m.emission) > 0.0f; });
}

// The file's punctual lights in physical units; a file that has no lights and nothing emissive
// gets a sun from the upper front right, so a bare model is not black.
void add_lights(const GltfAsset& asset, GltfSceneText& text) {
  if (asset.lights.empty()) {
    if (has_emissive_material(asset)) return;
    const std::string origin = "the light rtpro adds (the file has no lights and nothing emissive)";
    text.add("lights:", origin);
    text.add("  - {type: directional, direction: [-0.3, -0.8, -0.5], intensity: 0.9}", origin);
    return;
  }
  text.add("lights:", "the file's KHR_lights_punctual lights");
  for (const GltfLight& light : asset.lights) {
    const std::string common =
        ", color: " + vector(light.color) + ", intensity: " + number(light.intensity / kLumensPerWatt) + "}";
    const std::string origin =
        gltf_node_path(light.node) + " (extensions.KHR_lights_punctual.lights[" + std::to_string(light.light) + "])";
    switch (light.kind) {
      case GltfLight::Kind::kDirectional:
        text.add("  - {type: directional, direction: " + vector(light.direction) + common, origin);
        break;
      case GltfLight::Kind::kPoint:
        text.add("  - {type: point, position: " + vector(light.position) + common, origin);
        break;
      case GltfLight::Kind::kSpot:
        text.add("  - {type: spot, position: " + vector(light.position) + ", direction: " + vector(light.direction) +
                     spot_cone_yaml(light) + common,
                 origin);
        break;
    }
  }
}

// A glTF file as the whole scene is path traced. What lights it is the file's own lights and
// emissive materials; only a file with neither gets the sun above and a grey sky (a uniform
// environment of radiance 0.18 that escaping paths see), a lookdev studio's neutral default.
void add_render_settings(const GltfAsset& asset, GltfSceneText& text) {
  const bool lit = !asset.lights.empty() || has_emissive_material(asset);
  text.add(std::string("render: {integrator: path, background: ") + (lit ? "[0, 0, 0]" : "[0.18, 0.18, 0.18]") + "}",
           "the render settings rtpro gives a glTF file");
}

// Whether YAML can hold the name: a YAML document is UTF-8 (control characters are escaped).
bool writable_in_yaml(std::string_view name) {
  for (std::size_t i = 0; i < name.size();) {
    const std::size_t length = utf8_sequence_length(name.substr(i));
    if (length == 0) return false;
    i += length;
  }
  return true;
}

}  // namespace

void GltfSceneText::add(const std::string& line, const std::string& origin) {
  yaml += line + "\n";
  origin_of_line.push_back(origin);
}

const std::string& GltfSceneText::origin(int line) const {
  static const std::string whole_scene = kWholeScene;
  return line >= 1 && std::size_t(line) <= origin_of_line.size() ? origin_of_line[std::size_t(line) - 1] : whole_scene;
}

GltfSceneText gltf_scene_text(const GltfAsset& asset) {
  GltfSceneText text;
  const std::string name = asset.file.filename().string();
  text.add("# " + printable_text(name, 200) + " as a scene", kWholeScene);
  text.add("rtpro: 1", kWholeScene);
  add_camera(asset, asset.bounds(), text);
  add_render_settings(asset, text);
  add_lights(asset, text);
  if (writable_in_yaml(name)) {
    const std::string origin = "the file itself, the world's mesh";
    text.add("world:", origin);
    text.add("  - {type: mesh, file: " + quoted_yaml(name) + "}", origin);
  }
  return text;
}

SceneDescription parse_gltf_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  auto asset = std::make_shared<GltfAsset>(load_gltf_file(file));
  const GltfSceneText text = gltf_scene_text(*asset);
  SceneDescription description = [&] {
    try {
      return parse_scene_text(text.yaml, file, overrides);
    } catch (const InputError& e) {
      // A line of the text above, which the user never saw: named by the glTF element it was
      // written for. Errors about an override keep its own source.
      if (e.where().file != file.string() || e.where().line == 0) throw;
      throw InputError(SourceLocation{file.string()}, text.origin(e.where().line) + ": " + e.message());
    }
  }();
  // The world entry's errors (when the scene is built) name the file itself, and the nodes the
  // error is about (geometry_origin.h).
  for (GltfDesc& gltf : description.world.gltfs) {
    if (gltf.where.file == file.string()) gltf.where = SourceLocation{file.string()};
    if (gltf.file == file.lexically_normal() && gltf.normals == NormalsMode::kAuto && gltf.material == kNoMaterial)
      gltf.loaded = asset;
  }
  // A name YAML cannot hold (not UTF-8) is placed here instead of in the text.
  if (!writable_in_yaml(file.filename().string()))
    description.world.gltfs.push_back(
        {file.lexically_normal(), kNoMaterial, SourceLocation{file.string()}, NormalsMode::kAuto, asset});
  return description;
}

}  // namespace rtpro
