#include "rtpro/image/output_check.h"

#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"

#include <OpenImageIO/imageio.h>

namespace rtpro {

void check_image_output(const std::filesystem::path& file) {
  if (file.empty()) throw InputError("no output file given");
  if (!OIIO::ImageOutput::create(file.string())) {
    OIIO::geterror();  // clear OIIO's global error text
    throw InputError("cannot write '" + file.string() + "': unknown image format '" + file.extension().string() +
                     "' (use .exr, .png, .jpg or .tif)");
  }
  // The atomic writer's own checks: folder, file type, a full file system.
  check_replaceable(file);
}

}  // namespace rtpro
