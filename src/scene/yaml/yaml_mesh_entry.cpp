#include "rtpro/scene/triangle_geometry.h"

#include "gltf_loader.h"
#include "rtpro/core/closest_match.h"
#include "yaml_light_linking.h"
#include "yaml_shape_entry.h"
#include "yaml_subdivision.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

namespace rtpro {

namespace {

const std::vector<std::string> kMeshExtensions = {".obj", ".ply", ".gltf", ".glb"};
const std::vector<std::string> kNormalsModes = {"flat", "smooth", "file"};

NormalsMode read_normals_mode(const YamlNode& node, const std::string& field) {
  const std::string mode = read_string(node, field);
  if (mode == "flat") return NormalsMode::kFlat;
  if (mode == "smooth") return NormalsMode::kSmooth;
  if (mode == "file") return NormalsMode::kFile;
  fail_at(node, field + ": expected flat, smooth or file, got '" + mode + "'" + suggestion(mode, kNormalsModes));
}

// Relative to the file that wrote it: an included file's meshes sit beside it.
std::filesystem::path resolve_mesh_file(const YamlNode& node, const std::string& field,
                                        const ShapeEntryReader& reader) {
  const std::string written = read_string(node, field);
  const std::filesystem::path folder =
      node.at.line > 0 ? std::filesystem::path(*node.at.source).parent_path() : reader.folder();
  const std::filesystem::path file = (folder / written).lexically_normal();
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (std::find(kMeshExtensions.begin(), kMeshExtensions.end(), extension) == kMeshExtensions.end())
    fail_at(node,
            field + ": '" + written + "' is not a mesh format rtpro reads (.obj or .ply, or a .gltf or .glb scene)");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status))
    fail_at(node, field + ": mesh file '" + written + "' not found (looked for '" + file.string() + "')");
  if (!std::filesystem::is_regular_file(status)) fail_at(node, field + ": '" + file.string() + "' is not a file");
  if (!std::ifstream(file, std::ios::binary)) fail_at(node, field + ": cannot open mesh file '" + file.string() + "'");
  return file;
}

// `displacement:` moves the refined vertices, so it needs `subdivision:` (a level of 0 keeps the
// cage's faces, moved to the limit surface).
void read_subdivision_keys(const MappingReader& mesh, const ShapeEntryReader& reader, MeshDesc& desc) {
  if (const YamlNode* subdivision = mesh.optional("subdivision"))
    desc.subdivision = read_subdivision(*subdivision, mesh.field("subdivision"));
  const YamlNode* displacement = mesh.optional("displacement");
  if (!displacement) return;
  if (!desc.subdivision)
    fail_at(*displacement, mesh.field("displacement") + " needs `subdivision:` (level 0 for the cage as it is)");
  const std::filesystem::path folder =
      displacement->at.line > 0 ? std::filesystem::path(*displacement->at.source).parent_path() : reader.folder();
  desc.displacement = read_displacement(*displacement, mesh.field("displacement"), folder);
}

}  // namespace

// An OBJ or PLY file is one mesh; a glTF file is a scene of its own, placed as a whole.
void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<MeshDesc>& meshes) {
  const MappingReader mesh(node, "mesh",
                           {"type", "file", "material", "normals", "subdivision", "displacement", "interior",
                            kLightLinkingKey, kShadowLinkingKey});
  MeshDesc desc;
  desc.file = resolve_mesh_file(mesh.required("file"), mesh.field("file"), reader);
  if (const YamlNode* material = mesh.optional("material"))
    desc.material = reader.material_index(*material, mesh.field("material"));
  desc.material = reader.with_interior(mesh, desc.material);
  if (const YamlNode* normals = mesh.optional("normals"))
    desc.normals = read_normals_mode(*normals, mesh.field("normals"));
  desc.where = node.at.location();
  desc.linking = reader.read_linking(mesh);
  read_subdivision_keys(mesh, reader, desc);
  if (is_gltf_file(desc.file))
    reader.object().gltfs.push_back({desc.file, desc.material, desc.where, desc.normals, nullptr, desc.linking,
                                     desc.subdivision, desc.displacement});
  else meshes.push_back(std::move(desc));
}

}  // namespace rtpro
