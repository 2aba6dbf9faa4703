#pragma once
// A model file read as the whole scene (`rtpro render model.glb`, `model.obj`, `model.ply`): rtpro
// writes the scene around the model as YAML text and reads it with the ordinary parser, so `--set`
// overrides (camera.fov, render.spp, lights.0.intensity, ...) work exactly as for scene files.
// What every model format shares is here: a camera framing the model when the file has none, a
// default light when nothing in it emits, the render settings, the model's materials reachable by
// name from `materials:` overrides, the lines the commands say about what rtpro chose, and errors
// in the text named by what each line was written for. gltf_scene.h and mesh_scene.h write the
// format's own parts.
#include "rtpro/core/bbox.h"
#include "rtpro/scene/description.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// The YAML text of the scene and, line by line, the element of the file each line was written
// for: an error the scene parser finds in the text names that element (a glTF's JSON path, e.g.
// "nodes[3] (cameras[1])") and the model file, never a line of text the user did not write.
struct ModelSceneText {
  std::string yaml;
  std::vector<std::string> origin_of_line;  // [line - 1]

  void add(const std::string& line, const std::string& origin);
  // What line `line` (1-based) was written for; the scene as a whole past the last line.
  const std::string& origin(int line) const;
};

// The image a model file's scene is rendered at, unless its camera says another aspect ratio.
inline constexpr int kModelImageWidth = 640;
inline constexpr int kModelImageHeight = 480;

// Numbers and vectors as YAML that reads back the same float.
std::string yaml_number(double v);
std::string yaml_vector(const Vec3& v);
// Whether YAML can hold `name` (a YAML document is UTF-8), and the name as a YAML string read back
// exactly, `$` doubled against variable substitution.
bool writable_in_yaml(std::string_view name);
std::string quoted_yaml(const std::string& text);

// The comment naming the file and the format version.
void add_model_header(const std::filesystem::path& file, ModelSceneText& text);
// A 40-degree camera in front of the model (+z, the front of glTF models and of most OBJ and PLY
// exports, +y up), a little to the right and above, from where the bounding sphere just fits.
void add_framing_camera(const BBox& bounds, const std::string& origin, ModelSceneText& text);
// Path traced; a model that nothing lights (`lit` false) gets a grey sky of radiance 0.18 and the
// default light, a sun from the upper front right, named kDefaultLightName.
void add_model_lighting(bool lit, ModelSceneText& text);
inline constexpr const char* kDefaultLightName = "rtpro default light";

// What the model file gives the scene, for parse_model_scene.
struct ModelSceneParts {
  const ModelSceneText& text;
  std::vector<MaterialDesc>* materials;  // the model's own, changed in place by `materials:` overrides
  bool has_camera;                       // false: rtpro framed `bounds`
  BBox bounds;
  bool has_lights;
  bool emits;  // some material of the model emits
};

// Reads the text with `overrides` applied. A `materials:` entry named like one of the model's
// materials changes that material (the keys it gives; the others keep the file's values); one
// that names no material of the model and that nothing uses is refused at its override, with the
// nearest name. Under an environment (--environment), the default light is left out. Says in
// `notes` what rtpro chose for the file: the framing camera, the default light, the emissive-only
// lighting.
SceneDescription parse_model_scene(const ModelSceneParts& parts, const std::filesystem::path& file,
                                   const std::vector<std::string>& overrides);

}  // namespace rtpro
