#pragma once
// Reads rtpro's YAML scene format (see scenes/FORMAT.md) into a validated SceneDescription.
// Every error is an InputError at file:line:column naming the key and what was expected.
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// A .gltf or .glb file is read as a whole scene (see src/scene/yaml/gltf_scene.h): the file in the
// world, its camera and lights or defaults.
// `overrides` are "dotted.key=value" strings (e.g. "render.spp=64", "camera.fov=30") applied to
// the document before validation, so they are checked exactly like the file's own values.
SceneDescription parse_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Same, for text already in memory; `file` names it in errors and anchors relative paths.
SceneDescription parse_scene_text(std::string_view text, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides = {});

// The source an override's errors are located in ("--set KEY=VALUE"): an InputError about an
// override has it as where().file, so a caller can tell which override it is about and name it
// as the user typed it.
std::string override_source(std::string_view override_text);

}  // namespace rtpro
