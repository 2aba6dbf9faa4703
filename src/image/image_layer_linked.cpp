// The image layer's control functions (rtpro/image/image_layer.h) in a program that links
// rtpro_image, the tests among them: OpenImageIO is linked in, so there is no plugin to load and no
// write waits for one. The executable takes these functions from rtpro_image_loader instead; no
// program links both.
#include "rtpro/image/image_layer.h"

namespace rtpro {

bool writing_needs_image_layer(const std::filesystem::path&) { return false; }

bool reading_needs_image_layer(const std::filesystem::path&) { return false; }

void start_loading_image_layer() {}

bool image_layer_loading() { return false; }

}  // namespace rtpro
