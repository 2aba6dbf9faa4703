#pragma once
// Internals of the glTF loader: a texture's sampler (glTF's samplers[]) as rtpro reads images.
// wrapS and wrapT choose each axis's wrap (CLAMP_TO_EDGE, MIRRORED_REPEAT, REPEAT); magFilter
// chooses between the nearest texel (NEAREST) and bilinear filtering (LINEAR, and rtpro's choice
// when it is absent). rtpro's rays carry no footprint, so every lookup reads the finest level and
// pixel supersampling filters what a minified texture shows: minFilter's values are checked but
// change nothing.
#include "rtpro/core/texture_sampling.h"

#include <tiny_gltf.h>

#include <string>

namespace rtpro::gltf {

// The sampling of model.textures[texture] (the default, repeat and linear, for a texture without
// a sampler). Throws InputError at the JSON path for a sampler index out of range or a wrap or
// filter value glTF does not define.
TextureSampling texture_sampling(const tinygltf::Model& model, int texture, const std::string& file);

}  // namespace rtpro::gltf
