#include "rtpro/image/output_check.h"

#include "rtpro/core/error.h"

#include <OpenImageIO/imageio.h>

#include <unistd.h>

namespace rtpro {

void check_image_output(const std::filesystem::path& file) {
  if (file.empty()) throw InputError("no output file given");
  if (!OIIO::ImageOutput::create(file.string())) {
    OIIO::geterror();  // clear OIIO's global error text
    throw InputError("cannot write '" + file.string() + "': unknown image format '" + file.extension().string() +
                     "' (use .exr, .png, .jpg or .tif)");
  }
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw RuntimeError("cannot write '" + file.string() + "': folder '" + folder.string() + "' does not exist");
  if (access(folder.c_str(), W_OK) != 0)
    throw RuntimeError("cannot write '" + file.string() + "': folder '" + folder.string() + "' is not writable");
  if (std::filesystem::is_directory(file, error))
    throw RuntimeError("cannot write '" + file.string() + "': it is a folder");
}

}  // namespace rtpro
