#pragma once
// How a file format stores pixels, chosen by the file's extension. Float formats keep scene-linear
// values; the others hold display-referred code values. TIFF gets 16 bits so that its
// display-referred gradients do not band; PNG and JPEG stay 8-bit, what every viewer expects.
// Kept apart from image_io.cpp because the executable answers writes_scene_linear (image_io.h)
// without loading OpenImageIO.
#include <filesystem>
#include <string>

namespace rtpro {

enum class PixelEncoding { kSceneLinearFloat, kDisplay8Bit, kDisplay16Bit };

PixelEncoding encoding_for(const std::filesystem::path& file);

// The file's extension with its dot, in lower case (".exr" for "a.EXR"; empty without one).
std::string lowercase_extension(const std::filesystem::path& file);

}  // namespace rtpro
