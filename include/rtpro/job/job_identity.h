#pragma once
// What a render job is, as text both sides of a comparison can print: the rtpro version, a digest
// of every file a pixel can depend on (scene text, includes, meshes, glTF files, textures) and
// every setting that changes a pixel. A resume journal starts with it and the ranks of a
// distributed job compare theirs before any work, so a different scene, build or setting is
// refused with what differs instead of mixing two renders in one image.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/description.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rtpro {

class JobIdentity {
 public:
  // Keys are unique and kept in the order added; a value is one line.
  void set(std::string key, std::string value);
  const std::vector<std::pair<std::string, std::string>>& entries() const { return entries_; }

  // "key: value" lines, newline-terminated; parse(text()) gives back an equal identity.
  std::string text() const;
  // Throws InputError naming `source` for text that is not an identity.
  static JobIdentity parse(std::string_view text, std::string_view source);

  // One line per key whose value differs or that only one side has, e.g.
  // "mesh dragon.ply: 9f3c… here, 41aa… in the journal". Empty when they are the same.
  std::vector<std::string> differences(const JobIdentity& other, std::string_view other_name) const;

  bool operator==(const JobIdentity&) const = default;

 private:
  std::vector<std::pair<std::string, std::string>> entries_;
};

// The 64-bit XXH3 digest of a file's bytes as 16 hex digits; throws InputError if it can't be read.
std::string file_digest(const std::filesystem::path& file);
std::string text_digest(std::string_view text);

// The rtpro version and the digest of every file the scene's pixels depend on, each once: the
// description's source files, what building it loaded (meshes, glTF files and the files they read,
// such as MTL libraries and glTF buffers) and the image textures of the built scene.
JobIdentity scene_identity(const SceneDescription& description, const SceneBuildReport& report,
                           const RenderScene& scene);

}  // namespace rtpro
