#include "yaml_scene_objects.h"

#include "rtpro/core/closest_match.h"
#include "rtpro/core/overloaded.h"
#include "yaml_light_linking.h"
#include "yaml_name_table.h"
#include "yaml_reader.h"
#include "yaml_shape_entry.h"
#include "yaml_transform.h"
#include "yaml_volume_entry.h"

#include <algorithm>
#include <string>
#include <vector>

namespace rtpro {

namespace {

// One instance entry seen from the instance graph: which object it places, and where it says so.
struct InstanceLink {
  std::uint32_t target;
  YamlPosition at;
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

// Calls visit(shapes) with the object's list of each kind of shape an entry's `type:` names
// (visit_shape_lists' order): a glTF file is written as a mesh entry, so its list has no type of
// its own. A kind without entry_type_name and read_shape_entry (see scene/sphere_geometry.h) does
// not compile.
template <typename Visit>
void visit_entry_kinds(ObjectDesc& object, Visit&& visit) {
  visit_shape_lists(object, Overloaded{[](std::vector<GltfDesc>&) {}, [&](auto& shapes) { visit(shapes); }});
}

std::vector<std::string> entry_types() {
  std::vector<std::string> types;
  ObjectDesc kinds;
  visit_entry_kinds(kinds, [&](const auto& shapes) { types.push_back(entry_type_name(shapes)); });
  types.push_back("instance");
  types.push_back("volume");
  return types;
}

class ObjectsReader {
 public:
  ObjectsReader(const std::vector<MaterialDesc>& materials, std::filesystem::path folder, SceneDescription& scene)
      : shapes_(materials, folder, scene), folder_(std::move(folder)), volumes_(scene.volumes) {}

  void set_motion(const YamlMotion& motion) { shapes_.set_motion(motion); }

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
    static const std::vector<std::string> types = entry_types();
    if (!list->is_sequence()) {
      std::string listed;
      for (const std::string& type : types) listed += (listed.empty() ? "" : ", ") + type;
      fail_at(*list, what + ": expected a list of entries (" + listed + "), got " + list->describe());
    }
    shapes_.start(object, in_world);
    for (const YamlNodePtr& entry : list->items()) {
      if (++entries_ > kMaxSceneEntries) {
        fail_at(*entry, "the scene has more than " + std::to_string(kMaxSceneEntries) +
                            " entries (counting every alias expansion); use meshes or instances");
      }
      const std::string type = read_entry_type(*entry, "entry", types);
      if (type == "instance") {
        object.instances.push_back(read_instance(*entry, links));
        continue;
      }
      if (type == "volume") {
        // A volume is a medium, not a shape: instancing one would need a medium per placement.
        if (!in_world) fail_at(*entry, what + ": a volume entry belongs in world:, not in an object");
        volumes_.push_back(read_volume_entry(*entry, folder_));
        continue;
      }
      visit_entry_kinds(object, [&](auto& shapes) {
        if (type == entry_type_name(shapes)) read_shape_entry(*entry, shapes_, shapes);
      });
    }
  }

  InstanceDesc read_instance(const YamlNode& node, std::vector<InstanceLink>& links) {
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
    if (const YamlNode* transform = instance.optional("transform")) {
      const auto read = [&](const YamlNode& at) { return read_transform(at, instance.field("transform")); };
      desc.transform = read(*transform);
      desc.transform_steps = shapes_.motion().transform_steps(*transform, read);
    }
    desc.where = node.at.location();
    desc.linking = shapes_.read_linking(instance);
    links.push_back({*index, object.at});
    return desc;
  }

  ShapeEntryReader shapes_;
  std::filesystem::path folder_;
  std::vector<VolumeDesc>& volumes_;
  NameTable objects_;
  std::vector<std::vector<InstanceLink>> links_;  // per object, the world last
  std::size_t entries_ = 0;
};

}  // namespace

void read_scene_objects(const YamlNode* objects, const YamlNode* world, const std::filesystem::path& folder,
                        const YamlMotion& motion, SceneDescription& scene) {
  ObjectsReader reader(scene.materials, folder, scene);
  reader.set_motion(motion);
  reader.read(objects, world, scene);
}

}  // namespace rtpro
