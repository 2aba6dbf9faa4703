#include "rtpro/scene/scene_parser.h"

#include "gltf_loader.h"
#include "gltf_scene.h"
#include "mesh_scene.h"
#include "model_scene.h"
#include "yaml_camera.h"
#include "yaml_document.h"
#include "yaml_environment.h"
#include "yaml_medium.h"
#include "yaml_lights.h"
#include "yaml_materials.h"
#include "yaml_reader.h"
#include "yaml_scene_objects.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/core/special_file_kind.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstring>

namespace rtpro {

namespace {

constexpr std::int64_t kMaxSpp = 65536;
// Cycles' limit: pbrt-v4's Transparent Machines and scenes of many stacked glass layers need
// paths longer than 64.
constexpr std::int64_t kMaxDepth = 1024;
constexpr std::uintmax_t kMaxSceneFileBytes = std::uintmax_t{256} << 20;
// Frames per second: far above any camera's, low enough that frame / fps stays a usable time.
constexpr double kMaxFps = 1e6;

bool absent(const YamlNode* node) { return !node || node->is_null(); }

void read_version(const YamlNode& root) {
  const YamlEntry* version = root.find("rtpro");
  if (!version) {
    fail_at(root, "missing the required key 'rtpro' (the format version; this rtpro reads version " +
                      std::to_string(kSceneFormatVersion) + ")");
  }
  if (read_integer(*version->value, "rtpro") != kSceneFormatVersion) {
    fail_at(*version->value, "rtpro: unsupported scene format version " + std::string(version->value->scalar()) +
                                 "; this rtpro reads version " + std::to_string(kSceneFormatVersion));
  }
}

int read_spp(const YamlNode& node) {
  const std::int64_t spp = read_integer(node, "render.spp");
  if (spp < 1 || spp > kMaxSpp)
    fail_at(node, "render.spp must be from 1 to " + std::to_string(kMaxSpp) + ", got " + std::string(node.scalar()));
  return static_cast<int>(spp);
}

int read_depth(const YamlNode& node, const std::string& name, std::int64_t least = 0, const std::string& why = "") {
  const std::int64_t value = read_integer(node, name);
  if (value < least || value > kMaxDepth)
    fail_at(node, name + " must be from " + std::to_string(least) + " to " + std::to_string(kMaxDepth) + why +
                      ", got " + std::string(node.scalar()));
  return static_cast<int>(value);
}

// Cycles' Light Paths controls (scene/render_settings.h, PathControls). A per-lobe limit of 0 would
// end every path at its first surface, whatever lobes it has: at least 1, Cycles' 0.
void read_path_controls(const MappingReader& render, PathControls& path) {
  const auto depth = [&](const char* key, std::optional<int>& out) {
    if (const YamlNode* node = render.optional(key))
      out = read_depth(*node, std::string("render.") + key, 1,
                       " (1 lets light scatter once off that kind of lobe: Cycles' 0)");
  };
  depth("max_diffuse_depth", path.max_diffuse_depth);
  depth("max_glossy_depth", path.max_glossy_depth);
  depth("max_transmission_depth", path.max_transmission_depth);
  depth("max_volume_depth", path.max_volume_depth);
  const auto non_negative = [&](const char* key, float& out) {
    if (const YamlNode* node = render.optional(key)) out = read_non_negative(*node, std::string("render.") + key);
  };
  non_negative("clamp_direct", path.clamp_direct);
  non_negative("clamp_indirect", path.clamp_indirect);
  non_negative("filter_glossy", path.filter_glossy);
}

// `units`: the light units the file's own integrator implies, used where render.light_units is absent.
RenderSettings read_render(const YamlNode* node, LightUnits units) {
  RenderSettings settings;
  settings.light_units = units;
  if (absent(node)) return settings;
  const MappingReader render(
      *node, "render",
      {"spp", "max_depth", "seed", "ambient", "background", "integrator", "sampling", "sampler", "light_sampler",
       "light_units", "max_diffuse_depth", "max_glossy_depth", "max_transmission_depth", "max_volume_depth",
       "clamp_direct", "clamp_indirect", "filter_glossy", "fps"});
  if (const YamlNode* spp = render.optional("spp")) settings.spp = read_spp(*spp);
  if (const YamlNode* integrator = render.optional("integrator"))
    settings.integrator = read_keyword<Integrator>(*integrator, "render.integrator",
                                                   {{"path", Integrator::kPath}, {"whitted", Integrator::kWhitted}});
  if (const YamlNode* sampling = render.optional("sampling"))
    settings.path_sampling = read_keyword<PathSampling>(
        *sampling, "render.sampling",
        {{"mis", PathSampling::kMis}, {"light", PathSampling::kLight}, {"bsdf", PathSampling::kBsdf}});
  settings.sampler = settings.integrator == Integrator::kPath ? SamplerKind::kSobol : SamplerKind::kStratified;
  if (const YamlNode* sampler = render.optional("sampler"))
    settings.sampler = read_keyword<SamplerKind>(
        *sampler, "render.sampler", {{"sobol", SamplerKind::kSobol}, {"stratified", SamplerKind::kStratified}});
  if (const YamlNode* light_sampler = render.optional("light_sampler"))
    settings.light_sampler =
        read_keyword<LightSamplerKind>(*light_sampler, "render.light_sampler",
                                       {{"tree", LightSamplerKind::kTree}, {"power", LightSamplerKind::kPower}});
  if (const YamlNode* light_units = render.optional("light_units"))
    settings.light_units =
        read_keyword<LightUnits>(*light_units, "render.light_units",
                                 {{"whitted", LightUnits::kWhitted}, {"radiometric", LightUnits::kRadiometric}});
  if (const YamlNode* depth = render.optional("max_depth")) settings.max_depth = read_depth(*depth, "render.max_depth");
  read_path_controls(render, settings.path);
  if (const YamlNode* seed = render.optional("seed")) settings.seed = read_unsigned(*seed, "render.seed");
  if (const YamlNode* fps = render.optional("fps")) {
    settings.fps = read_number(*fps, "render.fps");
    if (!(settings.fps > 0.0 && settings.fps <= kMaxFps))
      fail_at(*fps, "render.fps must be more than 0 and at most " + std::to_string(int(kMaxFps)) +
                        " frames per second, got " + std::string(fps->scalar()));
  }
  if (const YamlNode* ambient = render.optional("ambient"))
    settings.ambient = read_non_negative(*ambient, "render.ambient");
  if (const YamlNode* background = render.optional("background"))
    settings.background = read_color(*background, "render.background");
  return settings;
}

// The frame being rendered: the scene variable `frame` (--frames and -D set it), 1 when unset, as
// keyframes read it. Read before variables are substituted (which removes `variables:`).
double frame_of(const YamlNode& root) {
  const YamlEntry* variables = root.is_mapping() ? root.find("variables") : nullptr;
  const YamlEntry* frame =
      variables && variables->value && variables->value->is_mapping() ? variables->value->find("frame") : nullptr;
  if (!frame || !frame->value) return 1.0;
  const YamlNode& value = *frame->value;
  double number = 0.0;
  const std::string_view text = value.is_scalar() ? value.scalar() : std::string_view();
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (!value.is_scalar() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(number))
    fail_at(value, "frame: expected a frame number, got " + value.describe());
  return number;
}

void check_scene_root(const YamlNode& root) {
  if (root.is_null()) {
    fail_at(root,
            "the scene is empty; it needs at least 'rtpro: " + std::to_string(kSceneFormatVersion) + "' and a camera");
  }
  if (!root.is_mapping())
    fail_at(root, "expected the scene to be a mapping (rtpro: 1, camera: ...), got " + root.describe());
}

// The light units of a scene written for the integrator the file names: radiometric for `path`,
// whitted otherwise. Read before --set, --integrator and -D apply, so that rendering a scene with
// the other integrator does not change what its lights mean; a `$name` integrator is looked up
// among the file's own variables.
LightUnits written_light_units(const YamlNode& root) {
  const YamlEntry* render = root.find("render");
  const YamlEntry* integrator = render && render->value ? render->value->find("integrator") : nullptr;
  if (!integrator || !integrator->value) return LightUnits::kWhitted;
  std::string_view name = integrator->value->scalar();
  if (name.starts_with('$')) {
    const YamlEntry* variables = root.find("variables");
    const YamlEntry* variable = variables && variables->value ? variables->value->find(name.substr(1)) : nullptr;
    name = variable && variable->value ? variable->value->scalar() : std::string_view();
  }
  return name == "path" ? LightUnits::kRadiometric : LightUnits::kWhitted;
}

SceneDescription read_scene(const YamlDocument& document, const std::filesystem::path& file, LightUnits written_units,
                            std::vector<MaterialDesc>* model_materials) {
  const YamlNode& root = document.root();
  check_scene_root(root);
  read_version(root);
  const MappingReader scene(
      root, "the scene",
      {"rtpro", "camera", "render", "materials", "lights", "environment", "medium", "objects", "world"});

  SceneDescription desc;
  desc.file = file;
  desc.camera = read_camera(scene.required("camera"));
  desc.camera.frame_steps = camera_frame_steps(document, scene.required("camera"), desc.camera.shutter);
  desc.render = read_render(scene.optional("render"), written_units);
  desc.materials = read_materials(scene.optional("materials"), file.parent_path(), model_materials);
  read_lights(scene.optional("lights"), desc.lights, desc.light_names);
  desc.light_sources.assign(desc.lights.size(), std::string());
  desc.environment = read_environment(scene.optional("environment"), file.parent_path());
  if (const YamlNode* medium = scene.optional("medium"); medium && !medium->is_null())
    desc.medium = read_medium(*medium, "medium");
  read_scene_objects(scene.optional("objects"), scene.optional("world"), file.parent_path(),
                     YamlMotion(document, desc.camera.shutter), desc);
  return desc;
}

// A scene file is YAML (JSON is YAML too); a name without an extension is read as one. Any other
// extension is refused before the file is read: an image or a mesh format rtpro does not read
// would otherwise fail as a YAML syntax error far from the cause.
void check_scene_file_extension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension.empty() || extension == ".yaml" || extension == ".yml" || extension == ".json") return;
  throw InputError(SourceLocation{file.string()},
                   "rtpro does not read '" + printable_text(file.extension().string(), 40) +
                       "' files as scenes; it reads a scene file (.yaml, .yml or .json) or a model file as the whole "
                       "scene (.gltf, .glb, .obj or .ply)");
}

[[noreturn]] void refuse_special_file(const SourceLocation& where, mode_t mode) {
  throw InputError(where, std::string("cannot read the scene file: it is ") + special_file_kind(mode) +
                              "; a scene must be a regular file (an endless or blocking source would never end)");
}

// Refused by type before it is opened for reading (opening a FIFO with no writer blocks forever,
// /dev/zero never ends) and by size before it is read. The type is checked again on the opened
// descriptor, so a file swapped for a FIFO in between is refused too; O_NONBLOCK keeps that open
// from blocking.
std::string read_scene_file_text(const std::filesystem::path& file) {
  const SourceLocation where{file.string()};
  struct stat before {};
  if (::stat(file.c_str(), &before) != 0) {
    const int error = errno;
    throw InputError(where, error == ENOENT ? std::string("cannot read the scene file: it does not exist")
                                            : std::string("cannot read the scene file: ") + std::strerror(error));
  }
  if (!S_ISREG(before.st_mode)) refuse_special_file(where, before.st_mode);
  const int descriptor = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (descriptor < 0) throw InputError(where, std::string("cannot read the scene file: ") + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{descriptor};
  struct stat opened {};
  if (::fstat(descriptor, &opened) != 0)
    throw InputError(where, std::string("cannot read the scene file: ") + std::strerror(errno));
  if (!S_ISREG(opened.st_mode)) refuse_special_file(where, opened.st_mode);
  if (static_cast<std::uintmax_t>(opened.st_size) > kMaxSceneFileBytes) {
    throw InputError(where, "the scene file is " + std::to_string(static_cast<std::uintmax_t>(opened.st_size) >> 20) +
                                " MiB; the limit is " + std::to_string(kMaxSceneFileBytes >> 20) +
                                " MiB (put large geometry in mesh files)");
  }
  // Read in chunks, each checked for over-long lines as it arrives: a 100 MB line is refused
  // after its first MiB. Reading stops one chunk past the size limit if the file grows meanwhile.
  std::string text;
  text.reserve(static_cast<std::size_t>(opened.st_size));
  LineLengthGuard lines(file.string());
  char chunk[65536];
  while (true) {
    const ssize_t got = ::read(descriptor, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputError(where, std::string("cannot read the scene file: ") + std::strerror(errno));
    if (got == 0) break;
    const std::string_view bytes(chunk, static_cast<std::size_t>(got));
    lines.feed(bytes);
    if (text.size() + bytes.size() > kMaxSceneFileBytes)
      throw InputError(where, "the scene file grew past the limit of " + std::to_string(kMaxSceneFileBytes >> 20) +
                                  " MiB while it was read");
    text.append(bytes);
  }
  return text;
}

}  // namespace

std::optional<std::string> yaml_string_literal(std::string_view text) {
  if (!writable_in_yaml(text)) return std::nullopt;
  return quoted_yaml(std::string(text));
}

std::string override_source(std::string_view override_text) { return "--set " + std::string(override_text); }

SceneDescription parse_scene_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  if (is_gltf_file(file)) return parse_gltf_scene_file(file, overrides);
  if (is_mesh_scene_file(file)) return parse_mesh_scene_file(file, overrides);
  if (std::error_code error; std::filesystem::is_regular_file(file, error)) check_scene_file_extension(file);
  SceneDescription description = parse_scene_text(read_scene_file_text(file), file, overrides);
  description.source_files.insert(description.source_files.begin(), file);
  return description;
}

SceneDescription parse_scene_text(std::string_view text, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides,
                                  std::vector<MaterialDesc>* model_materials) {
  std::vector<std::filesystem::path> included;
  const auto read_include = [&included](const std::filesystem::path& include) {
    included.push_back(include);
    return read_scene_file_text(include);
  };
  YamlDocument document = YamlDocument::parse(text, file.string(), read_include);
  check_scene_root(document.root());
  const LightUnits written_units = written_light_units(document.root());
  for (const std::string& override_text : overrides) document.apply_override(override_text);
  const double frame = frame_of(document.root());
  document.resolve_variables();
  SceneDescription description = read_scene(document, file, written_units, model_materials);
  description.source_files = std::move(included);
  description.frame = frame;
  return description;
}

}  // namespace rtpro
