#include "yaml_scene_objects.h"

#include "gltf_loader.h"
#include "yaml_light_linking.h"
#include "yaml_reader.h"
#include "yaml_transform.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace rtpro {

namespace {

const std::vector<std::string> kEntryTypes = {"sphere", "mesh", "instance"};
const std::vector<std::string> kMeshExtensions = {".obj", ".ply", ".gltf", ".glb"};
const std::vector<std::string> kNormalsModes = {"flat", "smooth", "file"};

// One instance entry seen from the instance graph: which object it places, and where it says so.
struct InstanceLink {
  std::uint32_t target;
  YamlPosition at;
};

// Names resolved to indices, with the names kept in order for suggestions.
class NameTable {
 public:
  void add(const std::string& name, std::uint32_t index) {
    if (indices_.emplace(name, index).second) names_.push_back(name);
  }
  const std::uint32_t* find(const std::string& name) const {
    const auto found = indices_.find(name);
    return found == indices_.end() ? nullptr : &found->second;
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::unordered_map<std::string, std::uint32_t> indices_;
  std::vector<std::string> names_;
};

std::string chain_text(const std::vector<std::string>& names, const std::vector<std::uint32_t>& chain) {
  std::string text;
  for (std::uint32_t node : chain) text += (text.empty() ? "" : " -> ") + names[node];
  return text;
}

// Depth-first over objects (world last) with an explicit stack, since chains of objects can be
// long before the depth limit is checked. Heights are computed on the way back up: an object
// without instances has height 0, and the world's height is its deepest nesting.
void check_instance_graph(const std::vector<std::string>& names, const std::vector<std::vector<InstanceLink>>& links) {
  enum class State { unvisited, active, done };
  std::vector<State> state(links.size(), State::unvisited);
  std::vector<int> height(links.size(), 0);
  struct Frame {
    std::uint32_t node;
    std::size_t next_link;
  };
  std::vector<Frame> stack;

  for (std::uint32_t root = 0; root < links.size(); ++root) {
    if (state[root] != State::unvisited) continue;
    state[root] = State::active;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      Frame& frame = stack.back();
      if (frame.next_link < links[frame.node].size()) {
        const InstanceLink& link = links[frame.node][frame.next_link++];
        if (state[link.target] == State::active) {
          std::vector<std::uint32_t> cycle;
          auto first = std::find_if(stack.begin(), stack.end(), [&](const Frame& f) { return f.node == link.target; });
          for (; first != stack.end(); ++first) cycle.push_back(first->node);
          cycle.push_back(link.target);
          fail_at(link.at, "instance cycle: " + chain_text(names, cycle));
        }
        if (state[link.target] == State::unvisited) {
          state[link.target] = State::active;
          stack.push_back({link.target, 0});
        }
        continue;
      }
      const std::uint32_t node = frame.node;
      const InstanceLink* deepest = nullptr;
      for (const InstanceLink& link : links[node]) {
        if (1 + height[link.target] > height[node]) {
          height[node] = 1 + height[link.target];
          deepest = &link;
        }
      }
      if (height[node] > kMaxInstanceNesting) {
        std::vector<std::uint32_t> chain{node};
        while (!links[chain.back()].empty()) {
          const auto next = std::max_element(
              links[chain.back()].begin(), links[chain.back()].end(),
              [&](const InstanceLink& a, const InstanceLink& b) { return height[a.target] < height[b.target]; });
          chain.push_back(next->target);
        }
        fail_at(deepest->at, "instances nest deeper than " + std::to_string(kMaxInstanceNesting) +
                                 " levels: " + chain_text(names, chain));
      }
      state[node] = State::done;
      stack.pop_back();
    }
  }
}

class ObjectsReader {
 public:
  ObjectsReader(const std::vector<MaterialDesc>& materials, std::filesystem::path folder, SceneDescription& scene)
      : folder_(std::move(folder)), scene_(scene) {
    for (std::uint32_t i = 0; i < materials.size(); ++i) materials_.add(materials[i].name, i);
  }

  void read(const YamlNode* objects, const YamlNode* world, SceneDescription& scene) {
    const bool has_objects = objects && !objects->is_null();
    if (has_objects && !objects->is_mapping())
      fail_at(*objects, "objects: expected a mapping of name: [entries], got " + objects->describe());
    if (has_objects) {
      for (const YamlEntry& entry : objects->entries()) {
        objects_.add(std::string(entry.key), static_cast<std::uint32_t>(scene.objects.size()));
        scene.objects.emplace_back().name = entry.key;
      }
    }
    links_.resize(scene.objects.size() + 1);
    if (has_objects) {
      for (std::size_t i = 0; i < objects->entries().size(); ++i) {
        const YamlEntry& entry = objects->entries()[i];
        read_entries(entry.value, "object '" + std::string(entry.key) + "'", scene.objects[i], links_[i], false);
      }
    }
    scene.world.name = "world";
    read_entries(world, "world", scene.world, links_.back(), true);

    std::vector<std::string> names = objects_.names();
    names.push_back("world");
    check_instance_graph(names, links_);
  }

 private:
  // `in_world`: the entries are the world's, which may be light-linked.
  void read_entries(const YamlNode* list, const std::string& what, ObjectDesc& object, std::vector<InstanceLink>& links,
                    bool in_world) {
    if (!list || list->is_null()) return;
    if (!list->is_sequence())
      fail_at(*list, what + ": expected a list of entries (sphere, mesh, instance), got " + list->describe());
    for (const YamlNodePtr& entry : list->items()) {
      if (++entries_ > kMaxSceneEntries) {
        fail_at(*entry, "the scene has more than " + std::to_string(kMaxSceneEntries) +
                            " entries (counting every alias expansion); use meshes or instances");
      }
      const std::string type = read_entry_type(*entry, "entry", kEntryTypes);
      if (type == "sphere") {
        object.spheres.push_back(read_sphere(*entry, in_world));
      } else if (type == "mesh") {
        read_mesh(*entry, object, in_world);
      } else {
        object.instances.push_back(read_instance(*entry, links, in_world));
      }
    }
  }

  // The index of the entry's light linking in the scene's list, or kNoLinking. Only world entries
  // are linked: an object's entries are lit as the instances placing it are.
  std::uint32_t read_linking(const MappingReader& entry, bool in_world) {
    std::optional<LightLinkingDesc> linking = read_light_linking(entry, scene_.light_names);
    if (!linking) return kNoLinking;
    if (!in_world) {
      const YamlNode* key = entry.optional(kLightLinkingKey);
      fail_at(key ? *key : *entry.optional(kShadowLinkingKey),
              entry.field(key ? kLightLinkingKey : kShadowLinkingKey) +
                  ": only the world's entries are light-linked; link the instance that places this object");
    }
    scene_.linkings.push_back(std::move(*linking));
    return static_cast<std::uint32_t>(scene_.linkings.size() - 1);
  }

  SphereDesc read_sphere(const YamlNode& node, bool in_world) {
    const MappingReader sphere(node, "sphere",
                               {"type", "center", "radius", "material", kLightLinkingKey, kShadowLinkingKey});
    SphereDesc desc;
    if (const YamlNode* center = sphere.optional("center")) desc.center = read_vec3(*center, sphere.field("center"));
    if (const YamlNode* radius = sphere.optional("radius")) {
      const double value = read_number(*radius, sphere.field("radius"));
      if (!(value > 0.0))
        fail_at(*radius, sphere.field("radius") + " must be > 0, got " + std::string(radius->scalar()));
      desc.radius = static_cast<float>(value);
    }
    if (const YamlNode* material = sphere.optional("material"))
      desc.material = material_index(*material, sphere.field("material"));
    desc.linking = read_linking(sphere, in_world);
    return desc;
  }

  // An OBJ or PLY file is one mesh; a glTF file is a scene of its own, placed as a whole.
  void read_mesh(const YamlNode& node, ObjectDesc& object, bool in_world) {
    const MappingReader mesh(node, "mesh",
                             {"type", "file", "material", "normals", kLightLinkingKey, kShadowLinkingKey});
    MeshDesc desc;
    desc.file = resolve_mesh_file(mesh.required("file"), mesh.field("file"));
    if (const YamlNode* material = mesh.optional("material"))
      desc.material = material_index(*material, mesh.field("material"));
    if (const YamlNode* normals = mesh.optional("normals"))
      desc.normals = read_normals_mode(*normals, mesh.field("normals"));
    desc.where = node.at.location();
    desc.linking = read_linking(mesh, in_world);
    if (is_gltf_file(desc.file))
      object.gltfs.push_back({desc.file, desc.material, desc.where, desc.normals, nullptr, desc.linking});
    else object.meshes.push_back(std::move(desc));
  }

  static NormalsMode read_normals_mode(const YamlNode& node, const std::string& field) {
    const std::string mode = read_string(node, field);
    if (mode == "flat") return NormalsMode::kFlat;
    if (mode == "smooth") return NormalsMode::kSmooth;
    if (mode == "file") return NormalsMode::kFile;
    fail_at(node, field + ": expected flat, smooth or file, got '" + mode + "'" + suggestion(mode, kNormalsModes));
  }

  InstanceDesc read_instance(const YamlNode& node, std::vector<InstanceLink>& links, bool in_world) {
    const MappingReader instance(node, "instance",
                                 {"type", "object", "transform", kLightLinkingKey, kShadowLinkingKey});
    InstanceDesc desc;
    const YamlNode& object = instance.required("object");
    const std::string name = read_string(object, instance.field("object"));
    const std::uint32_t* index = objects_.find(name);
    if (!index) {
      fail_at(object, instance.field("object") + ": unknown object '" + name + "'" +
                          (objects_.names().empty() ? "; no objects are defined under 'objects:'"
                                                    : suggestion(name, objects_.names())));
    }
    desc.object = *index;
    if (const YamlNode* transform = instance.optional("transform"))
      desc.transform = read_transform(*transform, instance.field("transform"));
    desc.where = node.at.location();
    desc.linking = read_linking(instance, in_world);
    links.push_back({*index, object.at});
    return desc;
  }

  std::uint32_t material_index(const YamlNode& node, const std::string& field) const {
    const std::string name = read_string(node, field);
    const std::uint32_t* index = materials_.find(name);
    if (!index) fail_at(node, field + ": unknown material '" + name + "'" + suggestion(name, materials_.names()));
    return *index;
  }

  std::filesystem::path resolve_mesh_file(const YamlNode& node, const std::string& field) const {
    const std::string written = read_string(node, field);
    // Relative to the file that wrote it: an included file's meshes sit beside it.
    const std::filesystem::path folder =
        node.at.line > 0 ? std::filesystem::path(*node.at.source).parent_path() : folder_;
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
    if (!std::ifstream(file, std::ios::binary))
      fail_at(node, field + ": cannot open mesh file '" + file.string() + "'");
    return file;
  }

  std::filesystem::path folder_;
  SceneDescription& scene_;
  NameTable materials_;
  NameTable objects_;
  std::vector<std::vector<InstanceLink>> links_;  // per object, the world last
  std::size_t entries_ = 0;
};

}  // namespace

void read_scene_objects(const YamlNode* objects, const YamlNode* world, const std::filesystem::path& folder,
                        SceneDescription& scene) {
  ObjectsReader(scene.materials, folder, scene).read(objects, world, scene);
}

}  // namespace rtpro
