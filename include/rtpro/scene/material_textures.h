#pragma once
// The images and patterns a material reads, as a scene file describes them (TextureSlotDesc) and
// as shading evaluates them (ColorTexture, NormalMap: render/texture.h), shared by every kind of
// material.
#include "rtpro/core/error.h"
#include "rtpro/core/texture_sampling.h"
#include "rtpro/core/vec3.h"
#include "rtpro/scene/checker_axes.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace rtpro {

// An image a material parameter other than the colour reads (glTF's metallicRoughnessTexture,
// normalTexture and emissiveTexture), looked up at the surface's texture coordinates.
struct TextureSlotDesc {
  std::filesystem::path file;  // for an image stored inside a glTF, its name ("model.glb#images[0].png")
  std::string colorspace;      // the OpenColorIO colour space its values are decoded from; "Raw" for data
  std::shared_ptr<const std::vector<unsigned char>> bytes;  // an image stored inside a glTF
  SourceLocation where;                                     // where it was named, for a missing file
  TextureSampling sampling{};                               // glTF: the texture's sampler
};

// A checkerboard as shading evaluates it (CheckerDesc, with the reciprocal size).
// Two named colours, not an array: with `Color colors[2]` here GCC 12.2 (-O1 and above) copied
// the Color alternative of ColorTexture as (x, x, y) in build_render_scene.cpp — every material's
// colour wrong, found by the regression images; clang was right.
struct CheckerTexture {
  float inv_size;
  Color even, odd;  // the square containing the origin's positive corner is even
  CheckerAxes axes;
};

// A material's diffuse colour: constant, or a texture evaluated at the shading point
// (render/texture.h). Adding a kind fails to compile where it is not evaluated.
// An image texture (RenderScene::textures[image]) times `tint`, at the surface's texture
// coordinates.
struct ImageTexture {
  std::uint32_t image;
  Color tint;
  TextureSampling sampling;
};

using ColorTexture = std::variant<Color, CheckerTexture, ImageTexture>;

// An image file a texture reads, and the OpenColorIO colour space its values are encoded in.
struct TextureImage {
  std::filesystem::path file;
  std::string colorspace;
  // An image stored inside a glTF: its encoded bytes (`file` then only names it).
  std::shared_ptr<const std::vector<unsigned char>> bytes;
  SourceLocation where{};  // the key that named it first, for messages about the image
};

// A tangent-space normal map (glTF normalTexture): the image's RGB in [0, 1] read as a normal in
// the frame of the surface's tangent (increasing u), bitangent (increasing v) and normal; x and y
// scaled by `scale`.
struct NormalMap {
  std::uint32_t image;
  float scale;
  TextureSampling sampling;
};

}  // namespace rtpro
