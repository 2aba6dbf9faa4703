#pragma once
// What an entry of any kind of shape takes from the scene around it: its material by name, its
// light linking (world entries only) and the object it belongs to. Each kind reads its own entries
// (read_shape_entry, declared beside the kind: scene/sphere_geometry.h); yaml_scene_objects.cpp
// hands each entry to the kind its `type:` names.
#include "rtpro/scene/description.h"
#include "yaml_motion.h"
#include "yaml_name_table.h"
#include "yaml_reader.h"

#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <filesystem>
#include <string>

namespace rtpro {

class ShapeEntryReader {
 public:
  ShapeEntryReader(const std::vector<MaterialDesc>& materials, std::filesystem::path folder, SceneDescription& scene);

  // The entries read next are `object`'s; `in_world`: they are the world's, which may be light-linked.
  void start(ObjectDesc& object, bool in_world) {
    object_ = &object;
    in_world_ = in_world;
  }
  ObjectDesc& object() const { return *object_; }
  // The scene file's folder, for a file named by a value no file wrote (--set).
  const std::filesystem::path& folder() const { return folder_; }
  // What moves during the shutter: keyframed values read at its steps.
  const YamlMotion& motion() const { return motion_; }
  void set_motion(const YamlMotion& motion) { motion_ = motion; }

  // The index of the material `node` names; an unknown name fails at the node, with a suggestion.
  std::uint32_t material_index(const YamlNode& node, const std::string& field) const;
  // The file a `file:` value (`node`) names, relative to the file that wrote it (an included file's
  // meshes sit beside it), with the extension one of `extensions` (lower case); `what` names the
  // kind in messages ("mesh", "hair"). Fails at the node when the file is missing or unreadable.
  std::filesystem::path input_file(const YamlNode& node, const std::string& field,
                                   std::initializer_list<std::string_view> extensions, const std::string& formats,
                                   const std::string& what) const;
  // The index of the entry's light linking in the scene's list, or kNoLinking. Only world entries
  // are linked: an object's entries are lit as the instances placing it are.
  std::uint32_t read_linking(const MappingReader& entry);
  // `material` with the entry's `interior:` when it has one: a copy of the material (named
  // "MATERIAL+interior") whose inside is that medium, so one object's inside differs from
  // another's of the same material.
  std::uint32_t with_interior(const MappingReader& entry, std::uint32_t material);

 private:
  std::filesystem::path folder_;
  SceneDescription& scene_;
  NameTable materials_;
  ObjectDesc* object_ = nullptr;
  bool in_world_ = false;
  YamlMotion motion_;
};

}  // namespace rtpro
