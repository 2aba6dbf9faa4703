#include "scene_overrides.h"

#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/scene/scene_parser.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <map>
#include <string_view>

namespace rtpro::cli {

namespace {

// An optional sign and decimal digits: what the scene file's integer rules then judge (range,
// sign) without any conversion in between that could wrap.
bool is_integer_text(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

SceneOverride integer_override(const std::string& key, const std::string& flag, const std::string& value) {
  if (!is_integer_text(value)) throw InputError(flag + " '" + value + "': expected an integer");
  return {key + "=" + value, flag + " " + value};
}

SceneOverride size_override(const std::string& value) {
  const std::size_t x = value.find('x');
  const std::string width = value.substr(0, x), height = x == std::string::npos ? "" : value.substr(x + 1);
  if (!is_integer_text(width) || !is_integer_text(height))
    throw InputError("--size '" + value + "': expected WIDTHxHEIGHT, e.g. 640x480");
  return {"camera.resolution=[" + width + "," + height + "]", "--size " + value};
}

// -D NAME=VALUE is --set variables.NAME=VALUE: the scene's `variables:` hold the defaults.
SceneOverride variable_override(const std::string& value) {
  const std::size_t equals = value.find('=');
  const std::string name = value.substr(0, equals);
  const bool valid_name = !name.empty() && name.find_first_not_of(
                                               "abcdefghijklmnopqrstuvwxyz"
                                               "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == std::string::npos;
  if (equals == std::string::npos || !valid_name)
    throw InputError("-D '" + value +
                     "': expected NAME=VALUE with a name of letters, digits and '_', e.g. -D radius=2");
  return {"variables." + value, "-D " + value};
}

// The flags that set one key of the scene's `render:` block. An integer's text is checked for
// digits here; the other values (numbers, keywords) are judged by the scene file's rules alone.
struct RenderKeyFlag {
  std::string_view flag, key;
  bool integer;
};
constexpr RenderKeyFlag kRenderKeyFlags[] = {
    {"--spp", "render.spp", true},
    {"--max-depth", "render.max_depth", true},
    {"--max-diffuse-depth", "render.max_diffuse_depth", true},
    {"--max-glossy-depth", "render.max_glossy_depth", true},
    {"--max-transmission-depth", "render.max_transmission_depth", true},
    {"--seed", "render.seed", true},
    {"--integrator", "render.integrator", false},
    {"--clamp-direct", "render.clamp_direct", false},
    {"--clamp-indirect", "render.clamp_indirect", false},
    {"--filter-glossy", "render.filter_glossy", false},
};

const RenderKeyFlag* render_key_flag(std::string_view name) {
  for (const RenderKeyFlag& f : kRenderKeyFlags)
    if (f.flag == name) return &f;
  return nullptr;
}

// Three numbers (or one, a grey) separated by commas, each as the scene file would take it.
std::optional<std::vector<std::string>> color_components(const std::string& value) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t comma = value.find(',', start);
    parts.push_back(value.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 1 && parts.size() != 3) return std::nullopt;
  for (const std::string& part : parts) {
    char* end = nullptr;
    std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0') return std::nullopt;
  }
  if (parts.size() == 1) parts = {parts[0], parts[0], parts[0]};
  return parts;
}

// --environment FILE|R,G,B is --set environment={file: FILE} or {color: [R, G, B]}: the scene's
// environment replaced, checked as the scene file's. The file is relative to where rtpro runs, so
// it is written absolute (the scene's own paths are relative to the scene file).
SceneOverride environment_override(const std::string& value) {
  const std::string flag = "--environment " + value;
  if (const auto rgb = color_components(value))
    return {"environment={color: [" + (*rgb)[0] + ", " + (*rgb)[1] + ", " + (*rgb)[2] + "]}", flag};
  if (value.empty()) throw InputError("--environment: expected an image file (.exr, .hdr, .pfm) or a colour R,G,B");
  const std::string file = std::filesystem::absolute(value).lexically_normal().string();
  const std::optional<std::string> quoted = yaml_string_literal(file);
  if (!quoted)
    throw InputError("--environment '" + printable_text(value, 200) +
                     "': the file's path is not UTF-8, which a scene cannot hold; rename the file");
  return {"environment={file: " + *quoted + "}", flag};
}

// --shutter OPEN,CLOSE is --set camera.shutter=[OPEN, CLOSE], checked as the scene file's.
SceneOverride shutter_override(const std::string& value) {
  const std::size_t comma = value.find(',');
  const auto is_number = [](const std::string& part) {
    char* end = nullptr;
    std::strtod(part.c_str(), &end);
    return !part.empty() && *end == '\0';
  };
  if (comma == std::string::npos || !is_number(value.substr(0, comma)) || !is_number(value.substr(comma + 1)))
    throw InputError("--shutter '" + printable_text(value, 200) +
                     "': expected OPEN,CLOSE in frames relative to the frame, e.g. --shutter -0.25,0.25");
  return {"camera.shutter=[" + value.substr(0, comma) + ", " + value.substr(comma + 1) + "]", "--shutter " + value};
}

SceneOverride override_of(const std::string& option_name, const std::string& value) {
  if (option_name == "--set") return {value, "--set " + value};
  if (option_name == "--define") return variable_override(value);
  if (option_name == "--size") return size_override(value);
  if (const RenderKeyFlag* f = render_key_flag(option_name)) {
    const std::string flag(f->flag), key(f->key);
    if (f->integer) return integer_override(key, flag, value);
    return {key + "=" + value, flag + " " + value};
  }
  if (option_name == "--environment") return environment_override(value);
  if (option_name == "--shutter") return shutter_override(value);
  throw std::logic_error("not a scene override option: " + option_name);
}

bool is_override_option(const std::string& name) {
  return name == "--set" || name == "--define" || name == "--size" || name == "--environment" || name == "--shutter" ||
         render_key_flag(name) != nullptr;
}

constexpr std::size_t kMaxStdinSceneBytes = std::size_t{256} << 20;

std::string read_standard_input() {
  std::string text;
  char chunk[65536];
  while (true) {
    const ssize_t got = ::read(STDIN_FILENO, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0)
      throw InputError(SourceLocation{"<stdin>"}, std::string("cannot read the scene: ") + std::strerror(errno));
    if (got == 0) return text;
    if (text.size() + static_cast<std::size_t>(got) > kMaxStdinSceneBytes)
      throw InputError(SourceLocation{"<stdin>"}, "the scene on standard input is larger than the limit of 256 MiB");
    text.append(chunk, static_cast<std::size_t>(got));
  }
}

}  // namespace

std::vector<SceneOverride> command_line_overrides(const CLI::App& command) {
  std::vector<SceneOverride> overrides;
  std::map<const CLI::Option*, std::size_t> used;
  for (const CLI::Option* option : command.parse_order()) {
    const std::string name = option->get_name();
    if (!is_override_option(name)) continue;
    const std::size_t index = used[option]++;
    if (index < option->results().size()) overrides.push_back(override_of(name, option->results()[index]));
  }
  return overrides;
}

void add_scene_override_options(CLI::App& command, std::vector<std::string>& sets, std::vector<std::string>& defines,
                                std::vector<std::string>& environments, std::vector<std::string>& shutters) {
  // One value per occurrence: a list option would otherwise swallow the scene file after it.
  const auto one_each = [](CLI::Option* option) {
    option->allow_extra_args(false)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  };
  one_each(command.add_option("--set", sets, "Override a scene value, e.g. --set camera.fov=30 (repeatable)"));
  one_each(command.add_option("-D,--define", defines,
                              "Set a scene variable, used as $NAME in the scene, e.g. -D radius=2 (repeatable)"));
  command
      .add_option("--environment", environments,
                  "Light the scene from every direction: a latitude-longitude image (.exr, .hdr, .pfm) or a constant "
                  "colour R,G,B; replaces the scene's environment")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      .add_option("--shutter", shutters,
                  "Open the camera's shutter from OPEN to CLOSE frames relative to the frame (e.g. -0.25,0.25: half "
                  "a frame centred on it): keyframed transforms and sphere centres blur; sets camera.shutter")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

SceneDescription parse_with_overrides(const std::string& scene, const std::vector<SceneOverride>& overrides) {
  std::vector<std::string> assignments;
  for (const SceneOverride& o : overrides) assignments.push_back(o.assignment);
  try {
    if (scene == "-") return parse_scene_text(read_standard_input(), "<stdin>", assignments);
    return parse_scene_file(scene, assignments);
  } catch (const InputError& e) {
    for (const SceneOverride& o : overrides)
      if (e.where().file == override_source(o.assignment)) throw InputError(o.flag + ": " + e.message());
    throw;
  }
}

}  // namespace rtpro::cli
