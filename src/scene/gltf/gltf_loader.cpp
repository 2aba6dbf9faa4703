#include "gltf_loader.h"

#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "rtpro/core/printable_text.h"
#include "gltf_accessor.h"
#include "gltf_animation.h"
#include "gltf_skin.h"
#include "gltf_json_types.h"
#include "gltf_material.h"
#include "gltf_mesh.h"
#include "gltf_nodes.h"
#include "mapped_file.h"

// tinygltf parses its JSON with nlohmann-json (a header-only library it requires); the failure
// diagnosis below reads the same JSON with it.
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>

namespace rtpro {

namespace fs = std::filesystem;

namespace {

// Extensions without which the geometry cannot be read at all.
constexpr const char* kGeometryExtensions[] = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                               "KHR_mesh_quantization"};
// Extensions rtpro reads. A file that requires any other is refused (the glTF specification: a
// loader that does not support a required extension must not load the file); one that merely
// uses another is read with a warning naming it. Of the material extensions, the factors are read
// and their own textures are not (gltf_material.cpp warns about those).
constexpr const char* kSupportedExtensions[] = {
    "KHR_lights_punctual",    "KHR_materials_emissive_strength", "KHR_texture_transform",   "KHR_materials_ior",
    "KHR_materials_specular", "KHR_materials_transmission",      "KHR_materials_clearcoat", "KHR_materials_sheen",
    "KHR_materials_volume"};

// Characters of a tinygltf message line shown.
constexpr std::size_t kMaxTinygltfLine = 300;

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// The deepest nesting of objects and arrays in the JSON text (strings skipped), stopping early
// once past `limit`.
int json_depth(std::string_view text, int limit) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return deepest;
}

// Filesystem callbacks that confine tinygltf to the glTF's folder.
struct Confinement {
  fs::path folder;  // canonical
  std::vector<fs::path> files_read;
};

bool inside(const Confinement& c, const std::string& path) {
  std::error_code error;
  const fs::path target = fs::weakly_canonical(fs::path(path), error);
  if (error) return false;
  const fs::path relative = target.lexically_relative(c.folder);
  return !relative.empty() && *relative.begin() != "..";
}

bool file_exists(const std::string& path, void* user) {
  std::error_code error;
  return inside(*static_cast<Confinement*>(user), path) && fs::is_regular_file(path, error);
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  if (!inside(*static_cast<Confinement*>(user), path)) {
    if (err) *err += "'" + path + "' is outside the glTF's folder\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    if (err) *err += "cannot open '" + path + "'\n";
    return false;
  }
  const std::streamoff size = in.tellg();
  if (size < 0 || std::uint64_t(size) >= (std::uint64_t(1) << 32)) {
    if (err) *err += "'" + path + "' is 4 GiB or larger\n";
    return false;
  }
  out->resize(std::size_t(size));
  static_cast<Confinement*>(user)->files_read.push_back(path);
  in.seekg(0);
  in.read(reinterpret_cast<char*>(out->data()), size);
  return bool(in);
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "rtpro never writes files while loading a glTF\n";
  return false;
}

// Images are decoded by OpenImageIO when texturing needs them, never by tinygltf: an image file
// is found again by its URI; an image inside the glTF (a buffer view or a data: URI) is kept
// encoded in Image::image for the texture to read.
bool keep_image_reference(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                          const unsigned char* bytes, int size, void*) {
  const bool inside = image->uri.empty() || image->uri.rfind("data:", 0) == 0;
  if (inside && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// The JSON text of a .gltf, or of a .glb's first chunk (for the depth check).
std::string_view json_text(std::string_view bytes, bool binary) {
  if (!binary) return bytes;
  if (bytes.size() < 20) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

bool is_geometry_extension(const std::string& name) {
  return std::find(std::begin(kGeometryExtensions), std::end(kGeometryExtensions), name) !=
         std::end(kGeometryExtensions);
}

bool is_supported_extension(const std::string& name) {
  return std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), name) !=
         std::end(kSupportedExtensions);
}

// extensionsRequired: each one rtpro lacks refuses the file; extensionsUsed: each one it lacks is
// a warning, by name.
void check_extensions(const tinygltf::Model& model, const std::string& name, std::vector<std::string>& warnings) {
  const SourceLocation where{name};
  for (std::size_t i = 0; i < model.extensionsRequired.size(); ++i) {
    const std::string& required = model.extensionsRequired[i];
    if (!is_supported_extension(required))
      throw InputError(where, "extensionsRequired[" + std::to_string(i) + "]: the file needs " +
                                  ascii::quoted(required) + ", which rtpro does not support" +
                                  (is_geometry_extension(required) ? " (its meshes cannot be read without it)" : ""));
  }
  for (std::size_t i = 0; i < model.extensionsUsed.size(); ++i) {
    const std::string& used = model.extensionsUsed[i];
    if (!is_supported_extension(used))
      warnings.push_back(name + ": extensionsUsed[" + std::to_string(i) + "]: " + ascii::quoted(used) +
                         " is not supported; what it adds is ignored and the file may look different in other tools");
  }
}

// tinygltf's errors name no JSON path ("File not found : a.bin"). When it fails, the JSON is
// read again (only then) to name the element at fault where that can be found.
std::string diagnose(std::string_view json_text, const Confinement& confinement, const fs::path& folder) {
  const nlohmann::json json = nlohmann::json::parse(json_text.begin(), json_text.end(), nullptr, false);
  if (json.is_discarded() || !json.is_object()) return {};
  if (const auto asset = json.find("asset"); asset != json.end() && asset->is_object()) {
    const auto version = asset->find("version");
    if (version == asset->end())
      return "asset.version: missing; rtpro reads glTF 2.0 files, whose asset.version is \"2.0\"";
    // A number is what glTF 1.0 exporters wrote (CesiumMilkTruck's `1`), or a mistake for "2.0";
    // tinygltf calls both missing.
    if (version->is_number()) {
      const double number = version->get<double>();
      if (number >= 2.0 && number < 3.0)
        return "asset.version must be a string, got a number (" + version->dump() + "); a glTF 2.0 file says \"2.0\"";
      return "asset.version: " + version->dump() +
             " (a number, as glTF 1.0 exporters wrote it): rtpro reads glTF 2.0 files only";
    }
    if (!version->is_string()) {
      const std::string kind = version->type_name();  // "boolean", "array", "object", "null"
      const std::string article = kind == "null" ? "" : kind[0] == 'a' || kind[0] == 'o' ? "an " : "a ";
      return "asset.version must be a string, got " + article + kind + "; a glTF 2.0 file says \"2.0\"";
    }
    if (version->get<std::string>().rfind("2.", 0) != 0)
      return "asset.version: " + ascii::quoted(version->get<std::string>()) + ": rtpro reads glTF 2.0 files only";
  } else {
    return "asset: missing; a glTF 2.0 file needs asset.version \"2.0\" (glTF 1.0 files are not read)";
  }
  if (const auto required = json.find("extensionsRequired"); required != json.end() && required->is_array())
    for (std::size_t i = 0; i < required->size(); ++i)
      if ((*required)[i].is_string() && is_geometry_extension((*required)[i].get<std::string>()))
        return "extensionsRequired[" + std::to_string(i) + "]: the file needs " +
               ascii::quoted((*required)[i].get<std::string>()) +
               ", which rtpro does not support (its meshes cannot be read without it)";
  if (const auto buffers = json.find("buffers"); buffers != json.end() && buffers->is_array()) {
    for (std::size_t i = 0; i < buffers->size(); ++i) {
      const nlohmann::json& buffer = (*buffers)[i];
      const auto uri = buffer.is_object() ? buffer.find("uri") : buffer.end();
      if (uri == buffer.end() || !uri->is_string() || uri->get<std::string>().rfind("data:", 0) == 0) continue;
      const std::string name = uri->get<std::string>();
      const std::string path = (folder / name).string();
      const std::string where = "buffers[" + std::to_string(i) + "].uri: ";
      if (!inside(confinement, path)) return where + ascii::quoted(name) + " leads outside the glTF's folder";
      std::error_code error;
      if (!fs::is_regular_file(path, error))
        return where + ascii::quoted(name) + " not found (looked for '" + path + "')";
    }
  }
  return {};
}

tinygltf::Model parse(const fs::path& file, std::vector<std::string>& warnings, std::vector<fs::path>& files_read) {
  const std::string name = file.string();
  const SourceLocation where{name};
  const MappedFile bytes(file);
  if (bytes.size() >= (std::size_t(1) << 32))
    throw InputError(where, "the file is 4 GiB or larger, beyond what glTF allows");
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (binary && bytes.size() >= 8) {
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 4, 4);
    if (version != 2)
      throw InputError(where, "GLB container version " + std::to_string(version) + ": rtpro reads glTF 2.0 files only");
  }
  if (json_depth(json_text(bytes.text(), binary), kMaxGltfJsonDepth) > kMaxGltfJsonDepth)
    throw InputError(where, "the JSON nests deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
  gltf::check_json_types(json_text(bytes.text(), binary), name);

  std::error_code error;
  Confinement confinement{fs::weakly_canonical(file.parent_path().empty() ? fs::path(".") : file.parent_path(), error),
                          {}};
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(keep_image_reference, nullptr);
  gltf.SetFsCallbacks({file_exists, expand_path, read_whole_file, write_whole_file, &confinement});
  tinygltf::Model model;
  std::string err, warn;
  const std::string base = file.parent_path().string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, data, size, base)
                         : gltf.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base);
  // tinygltf's messages quote the file (URIs, names): printable and short, whatever it holds.
  const auto lines = [](const std::string& text) {
    std::vector<std::string> out;
    std::size_t begin = 0;
    while (begin < text.size()) {
      const std::size_t end = std::min(text.find('\n', begin), text.size());
      if (end > begin)
        out.push_back(printable_text(std::string_view(text).substr(begin, end - begin), kMaxTinygltfLine));
      begin = end + 1;
    }
    return out;
  };
  if (!ok) {
    if (const std::string diagnosis = diagnose(json_text(bytes.text(), binary), confinement, file.parent_path());
        !diagnosis.empty())
      throw InputError(where, diagnosis);
    std::string message;
    for (const std::string& line : lines(err)) message += (message.empty() ? "" : "; ") + line;
    throw InputError(where, message.empty() ? "tinygltf could not read the file" : "tinygltf: " + message);
  }
  for (const std::string& line : lines(warn)) warnings.push_back(name + ": " + line);
  files_read = std::move(confinement.files_read);
  if (model.asset.version.rfind("2.", 0) != 0)
    throw InputError(where,
                     "asset.version: " + ascii::quoted(model.asset.version) + ": rtpro reads glTF 2.0 files only");
  check_extensions(model, name, warnings);
  return model;
}

}  // namespace

std::uint64_t count_gltf_mesh_nodes(const fs::path& file) {
  try {
    const MappedFile bytes(file);
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string_view text = json_text(bytes.text(), binary);
    if (json_depth(text, kMaxGltfJsonDepth) > kMaxGltfJsonDepth) return 1;
    const nlohmann::json json = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    const auto nodes = json.is_object() ? json.find("nodes") : json.end();
    if (json.is_discarded() || !json.is_object() || nodes == json.end() || !nodes->is_array()) return 1;
    std::uint64_t count = 0;
    for (const nlohmann::json& node : *nodes) count += node.is_object() && node.contains("mesh");
    return std::max<std::uint64_t>(count, 1);
  } catch (const InputError&) {
    return 1;
  }
}

bool is_gltf_file(const fs::path& file) {
  const std::string extension = lowercase(file.extension().string());
  return extension == ".gltf" || extension == ".glb";
}

GltfAsset load_gltf_file(const fs::path& file, const MeshLoadOptions& options) {
  GltfAsset asset;
  asset.file = file;
  MeshLoadStats& stats = asset.stats;
  const tinygltf::Model model = parse(file, stats.warnings, stats.files_read);
  const gltf::AccessorReader reader(model, file.string());
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    asset.materials.push_back(gltf::read_material(model, int(m), file, stats.warnings));
  std::vector<gltf::UvMapping> uv_mappings;
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    uv_mappings.push_back(gltf::uv_mapping(model, int(m), file.string(), stats.warnings));
  asset.deformations.resize(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m)
    asset.meshes.push_back(gltf::read_mesh(model, int(m), reader, options, uv_mappings, stats, asset.deformations[m]));
  asset.skins = gltf::read_skins(model, reader);
  asset.animations = gltf::read_animations(model, reader, stats.warnings);
  gltf::place_nodes(model, reader, asset);
  for (const TriangleMesh& mesh : asset.meshes) {
    stats.vertices += mesh.vertices.size();
    stats.triangles += mesh.triangles.size();
  }
  stats.materials = asset.materials.size();
  if (stats.triangles == 0) stats.warnings.push_back(file.string() + ": no triangles");
  return asset;
}

}  // namespace rtpro
