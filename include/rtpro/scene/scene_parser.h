#pragma once
// Reads rtpro's YAML scene format (see scenes/FORMAT.md) into a validated SceneDescription.
// Every error is an InputError at file:line:column naming the key and what was expected.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// A model file, .gltf, .glb, .obj or .ply, is read as a whole scene (src/scene/yaml/model_scene.h):
// the file in the world, its camera and lights or defaults. A .yaml, .yml or .json file, or one
// without an extension, is a scene file; any other extension is refused, naming what is read.
// `overrides` are "dotted.key=value" strings (e.g. "render.spp=64", "camera.fov=30") applied to
// the document before validation, so they are checked exactly like the file's own values.
SceneDescription parse_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Same, for text already in memory; `file` names it in errors and anchors relative paths. With
// `model_materials` (the materials of a model file read as the whole scene), a `materials:` entry
// named like one of them changes it in place instead of adding a material to the scene.
SceneDescription parse_scene_text(std::string_view text, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides = {},
                                  std::vector<MaterialDesc>* model_materials = nullptr);

// `text` as a YAML string for an override's value that reads back exactly (quotes, backslashes and
// control characters escaped, `$` doubled against variable substitution); none when it is not
// UTF-8, which a YAML document cannot hold.
std::optional<std::string> yaml_string_literal(std::string_view text);

// The source an override's errors are located in ("--set KEY=VALUE"): an InputError about an
// override has it as where().file, so a caller can tell which override it is about and name it
// as the user typed it.
std::string override_source(std::string_view override_text);

}  // namespace rtpro
