#include "direct_output.h"

#include "exr_output.h"
#include "png_output.h"

namespace rtpro {

bool written_without_openimageio(const std::filesystem::path& file) { return is_exr_file(file) || is_png_file(file); }

bool write_without_openimageio(const std::filesystem::path& file, const Image& image,
                               const ImageWriteOptions& options) {
  if (is_exr_file(file)) {
    write_exr(file, image, options);
    return true;
  }
  if (is_png_file(file)) {
    write_png(file, image, options);
    return true;
  }
  return false;
}

}  // namespace rtpro
