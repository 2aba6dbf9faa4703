#pragma once
// No output of `rtpro render` may be a file the scene read: writing the image, the statistics or
// the resume journal over an included YAML, a mesh, an MTL library, a glTF buffer, a texture or
// the environment map would destroy the input with exit 0. Checked once the scene is parsed against
// the files it names (before loading them) and again once it is loaded (only then is every file it
// read known), and always before anything is rendered or written.
#include "render_request.h"
#include "rtpro/scene/scene_inputs.h"

#include <vector>

namespace rtpro::cli {

// Throws InputError naming the output and the input when one of the request's outputs (-o, the
// partial image of an interrupted render, --stats-json, the resume journal and its lock) is the
// same file as one of `inputs`: the same device and inode whatever the spelling (`./x`, `../d/x`,
// a symbolic or hard link).
void check_outputs_spare_inputs(const RenderRequest& request, const std::vector<SceneInput>& inputs);

}  // namespace rtpro::cli
