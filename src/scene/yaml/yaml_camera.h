#pragma once
// The scene file's `camera:` (FORMAT.md, "Camera"): where it stands and looks, its projection
// (perspective or orthographic), image size, lens and shutter, and its motion during the shutter
// when its values are keyframed.
#include "rtpro/scene/description.h"
#include "yaml_document.h"

namespace rtpro {

// The camera at `node` (the mapping under `camera:`) at the scene's frame.
CameraDesc read_camera(const YamlNode& node);

// The camera's frame (camera_frame, scene/render_camera.h) at each time step of `shutter` when a
// keyframed value (or $frame) moves it during the shutter; empty otherwise.
std::vector<Affine> camera_frame_steps(const YamlDocument& document, const YamlNode& node, const Shutter& shutter);

}  // namespace rtpro
