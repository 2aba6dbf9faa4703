#pragma once
// The calls the rtpro executable makes into the OpenImageIO half of the image layer, which it
// loads as a plugin (librtpro_image_oiio.so, see rtpro/image/image_layer.h). The plugin and the
// executable are built from the same sources in one build; the version fields catch a stale
// plugin left beside a newer executable.
#include "rtpro/image/image.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"
#include "rtpro/image/image_size.h"
#include "rtpro/image/texture_lookup.h"

#include <cstdint>
#include <filesystem>

namespace rtpro {

// Raise whenever a call is added, removed or changes its signature.
inline constexpr int kImageLayerAbiVersion = 6;
inline constexpr const char* kImageLayerEntryPoint = "rtpro_image_layer";
inline constexpr const char* kImageLayerFileName = "librtpro_image_oiio.so";

struct ImageLayerApi {
  int abi_version;
  const char* rtpro_version;
  void (*write_image)(const std::filesystem::path&, const Image&, const ImageWriteOptions&);
  Image (*read_image)(const std::filesystem::path&, std::uint64_t);
  ImageSize (*read_image_size)(const std::filesystem::path&);
  ImageComparison (*compare_images)(const Image&, const Image&, const CompareThresholds&);
  void (*write_diff_image)(const std::filesystem::path&, const Image&, const Image&, float);
  // Owned by the caller.
  TextureLookup* (*open_textures)(const TextureSource*, std::size_t, std::uint64_t max_bytes);
};

// The plugin's one exported symbol, named by kImageLayerEntryPoint, is a `const ImageLayerApi* ()`
// (opened by core/plugin_file.h's open_plugin_table).

}  // namespace rtpro
