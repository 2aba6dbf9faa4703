// The entry point of librtpro_image_oiio.so, the OpenImageIO half of the image layer as a plugin:
// a table of the image functions this library holds (image_io.cpp, image_compare.cpp,
// diff_image.cpp). Everything else in the plugin is hidden (--exclude-libs), so its copies of
// rtpro's code never interpose on the executable's.
#include "image_layer_api.h"
#include "rtpro/image/diff_image.h"

namespace {

rtpro::TextureLookup* open_textures(const rtpro::TextureSource* sources, std::size_t count, std::uint64_t max_bytes) {
  return rtpro::open_textures(std::span(sources, count), max_bytes).release();
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const rtpro::ImageLayerApi* rtpro_image_layer() {
  static const rtpro::ImageLayerApi api{
      rtpro::kImageLayerAbiVersion, RTPRO_VERSION,          &rtpro::write_image,      &rtpro::read_image,
      &rtpro::read_image_size,      &rtpro::compare_images, &rtpro::write_diff_image, &open_textures,
  };
  return &api;
}
