#include "gltf_scene.h"

#include "rtpro/core/printable_text.h"

#include "rtpro/scene/scene_parser.h"
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_motion.h"
#include "gltf_pose.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <variant>

namespace rtpro {

namespace {

// The pose's first camera, or one that frames the placed meshes.
void add_camera(const GltfPose& pose, const BBox& bounds, ModelSceneText& text) {
  if (!pose.cameras.empty()) {
    const GltfCamera& c = pose.cameras.front();
    const int height = c.aspect_ratio > 0.0f ? std::clamp(int(std::lround(kModelImageWidth / c.aspect_ratio)), 1, 65536)
                                             : kModelImageHeight;
    // A unit step along the view is lost in rounding far from the origin (at 1e9 a float's spacing
    // is 128): the step grows with the position, and below 256 stays 1.
    const float magnitude = std::max({std::fabs(c.position.x), std::fabs(c.position.y), std::fabs(c.position.z)});
    const Vec3 look_at = c.position + c.forward * std::max(1.0f, magnitude / 256.0f);
    const std::string projection = c.ortho_half_height > 0.0f ? "projection: orthographic, ortho_height: " +
                                                                    yaml_number(2.0f * c.ortho_half_height)
                                                              : "fov: " + yaml_number(c.yfov_degrees);
    text.add("camera: {position: " + yaml_vector(c.position) + ", look_at: " + yaml_vector(look_at) +
                 ", up: " + yaml_vector(c.up) + ", " + projection + ", resolution: [" +
                 std::to_string(kModelImageWidth) + ", " + std::to_string(height) + "]}",
             gltf_node_path(c.node) + " (cameras[" + std::to_string(c.camera) + "])");
    return;
  }
  add_framing_camera(bounds, "the camera rtpro places to frame the meshes (the file has no usable camera)", text);
}

// A spot light's cone, glTF's half-angles in radians as the scene format's degrees: computed in
// double and held to 90, so a float π/2 (just above it) stays within the format's limit, and
// printing (monotonic) keeps inner <= outer.
std::string spot_cone_yaml(const GltfLight& light) {
  constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
  const double outer = std::min(90.0, double(light.outer_cone_angle) * kDegreesPerRadian);
  const double inner = std::min(outer, double(light.inner_cone_angle) * kDegreesPerRadian);
  return ", inner_angle: " + yaml_number(inner) + ", outer_angle: " + yaml_number(outer);
}

bool has_emissive_material(const GltfAsset& asset) {
  return std::any_of(asset.materials.begin(), asset.materials.end(),
                     [](const MaterialDesc& m) { return max_component(m.emission) > 0.0f; });
}

// The pose's punctual lights in physical units (gltf_scene.h).
void add_lights(const GltfPose& pose, ModelSceneText& text) {
  if (pose.lights.empty()) return;
  text.add("lights:", "the file's KHR_lights_punctual lights");
  for (const GltfLight& light : pose.lights) {
    const std::string common =
        ", color: " + yaml_vector(light.color) + ", intensity: " + yaml_number(light.intensity / kLumensPerWatt) + "}";
    const std::string origin =
        gltf_node_path(light.node) + " (extensions.KHR_lights_punctual.lights[" + std::to_string(light.light) + "])";
    switch (light.kind) {
      case GltfLight::Kind::kDirectional:
        text.add("  - {type: directional, direction: " + yaml_vector(light.direction) + common, origin);
        break;
      case GltfLight::Kind::kPoint:
        text.add("  - {type: point, position: " + yaml_vector(light.position) + common, origin);
        break;
      case GltfLight::Kind::kSpot:
        text.add("  - {type: spot, position: " + yaml_vector(light.position) +
                     ", direction: " + yaml_vector(light.direction) + spot_cone_yaml(light) + common,
                 origin);
        break;
    }
  }
}

// As people write it (68.3, not the float's 68.3000031).
std::string short_number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", double(v));
  return text;
}

const char* photometric_unit(const GltfLight& light) {
  return light.kind == GltfLight::Kind::kDirectional ? " lx" : " cd";
}

float intensity_of(const LightDesc& light) {
  return std::visit([](const auto& desc) { return desc.intensity; }, light);
}

// The file's lights are the text's first (the default light is written only without them): each
// that an override left as written is named by its JSON path and the photometric value it had.
void note_light_sources(const GltfAsset& asset, SceneDescription& description) {
  for (std::size_t i = 0; i < asset.lights.size() && i < description.lights.size(); ++i) {
    const GltfLight& light = asset.lights[i];
    const float written = std::strtof(yaml_number(light.intensity / kLumensPerWatt).c_str(), nullptr);
    if (intensity_of(description.lights[i]) != written) continue;
    description.light_sources[i] = gltf_node_path(light.node) + " (extensions.KHR_lights_punctual.lights[" +
                                   std::to_string(light.light) + "]): " + short_number(light.intensity) +
                                   photometric_unit(light) + " / 683 lm/W";
  }
}

}  // namespace

ModelSceneText gltf_scene_text(const GltfAsset& asset, const GltfPose& pose) {
  ModelSceneText text;
  const std::string name = asset.file.filename().string();
  add_model_header(asset.file, text);
  // Framed as the file places its meshes without animation: the same view for every frame.
  add_camera(pose, asset.bounds(), text);
  add_model_lighting(!asset.lights.empty() || has_emissive_material(asset), text);
  add_lights(pose, text);
  if (writable_in_yaml(name)) {
    const std::string origin = "the file itself, the world's mesh";
    text.add("world:", origin);
    text.add("  - {type: mesh, file: " + quoted_yaml(name) + "}", origin);
  }
  return text;
}

SceneDescription parse_gltf_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  auto asset = std::make_shared<GltfAsset>(load_gltf_file(file));
  const BBox bounds = asset->bounds();
  const auto parse = [&](const GltfPose& pose) {
    return parse_model_scene({.text = gltf_scene_text(*asset, pose),
                              .materials = &asset->materials,
                              .has_camera = !asset->cameras.empty(),
                              .bounds = bounds,
                              .has_lights = !asset->lights.empty(),
                              .emits = has_emissive_material(*asset)},
                             file, overrides);
  };
  SceneDescription description = parse(*asset);
  // The frame and frames per second are known once the text is read with the overrides: an
  // animated camera or light is written again where the frame's pose puts it.
  if (asset->animated()) {
    description = parse(pose_gltf(*asset, description.frame / description.render.fps));
    // The file's camera blurs as its node moves: its frames over the shutter replace the text's
    // camera position and direction (--set camera.position moves only the closed-shutter camera).
    if (!asset->cameras.empty())
      description.camera.frame_steps = gltf_camera_frame_steps(*asset, asset->cameras.front(), description.frame,
                                                               description.render.fps, description.camera.shutter);
    const double seconds = gltf::animation_end(asset->animations);
    // Up to a thousandth of a frame past a whole frame is float rounding of the key time.
    const auto last = static_cast<long>(std::ceil(seconds * description.render.fps - 1e-3));
    description.notes.push_back(printable_text(file.filename().string(), 200) +
                                " is animated: " + short_number(float(seconds)) + " s, frames 0 to " +
                                std::to_string(last) + " at " + short_number(float(description.render.fps)) +
                                " fps (--frames 0-" + std::to_string(last) + " renders them); this is frame " +
                                short_number(float(description.frame)));
  }
  note_light_sources(*asset, description);
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
