#pragma once
// Every file a loaded scene read, with what it was to the scene: the scene text and its includes,
// meshes, MTL libraries, glTF files and their buffers, image textures and the environment map.
// A resume journal hashes them (job/job_identity.h), and `rtpro render` refuses an output that is
// one of them, so that no output ever replaces an input.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/render_scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro {

struct SceneInput {
  std::string kind;  // "scene", "mesh", "mesh data", "texture", "environment": how messages name it
  std::filesystem::path file;
};

// Each file once (by its spelling), in the order the scene read them: the description's source
// files, what building it loaded (report) and the image files of the built scene. Images stored
// inside a glTF are not files of their own: the glTF stands for them.
std::vector<SceneInput> scene_inputs(const SceneDescription& description, const SceneBuildReport& report,
                                     const RenderScene& scene);

// The files the description itself names, known before anything is loaded: the scene text and its
// includes, mesh and glTF files, the environment map and texture images named by path. The
// files those read in turn (MTL libraries, glTF buffers and images) come with scene_inputs only.
std::vector<SceneInput> named_inputs(const SceneDescription& description);

}  // namespace rtpro
