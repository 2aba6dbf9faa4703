#pragma once
// Command-line values that change the scene: --set KEY=VALUE, -D NAME=VALUE, --size, --environment
// and the flags that set one render key (--spp, --seed, --max-depth, the path controls...). Each
// becomes a scene override ("render.spp=16"), so it is
// validated by the scene file's own rules, and they apply in the order they were typed: the last
// one that sets a key wins, whichever spelling it used.
#include "rtpro/scene/description.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rtpro::cli {

// An override together with the command-line text it came from, so errors name the flag the
// user typed (--spp 10) rather than the override it became (--set render.spp=10).
struct SceneOverride {
  std::string assignment;
  std::string flag;
};

// The overrides of a parsed subcommand in command-line order. Throws InputError for a value no
// override could hold (--spp ten, --size 640, -D =3).
std::vector<SceneOverride> command_line_overrides(const CLI::App& command);

// Adds --set, -D/--define and --environment to `command` (the shorthands belong to `render`); the
// values are read back in order through command_line_overrides.
void add_scene_override_options(CLI::App& command, std::vector<std::string>& sets, std::vector<std::string>& defines,
                                std::vector<std::string>& environments, std::vector<std::string>& shutters);

// The scene (a file, or "-" for standard input) with the overrides applied; an error about an
// override names its flag.
SceneDescription parse_with_overrides(const std::string& scene, const std::vector<SceneOverride>& overrides);

}  // namespace rtpro::cli
