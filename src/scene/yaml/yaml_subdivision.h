#pragma once
// A mesh entry's `subdivision:` and `displacement:` (scenes/FORMAT.md, "Subdivision surfaces").
#include "rtpro/scene/subdivision.h"
#include "yaml_reader.h"

#include <filesystem>
#include <string>

namespace rtpro {

// {scheme: catmull-clark | loop, level: N, edge_length: pixels, creases: [[v0, v1, s], ...],
// corners: [[v, s], ...]}
SubdivisionDesc read_subdivision(const YamlNode& node, const std::string& name);

// {texture: FILE, value: v, scale: s, bound: b}: `texture` relative to `folder`.
DisplacementDesc read_displacement(const YamlNode& node, const std::string& name, const std::filesystem::path& folder);

}  // namespace rtpro
