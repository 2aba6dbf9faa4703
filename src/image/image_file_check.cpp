#include "image_file_check.h"

#include "rtpro/core/error.h"

namespace rtpro {

void require_image_file(const std::filesystem::path& file) {
  const SourceLocation where{file.string()};
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw InputError(where, "no such image file");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(where, "not a regular file (a FIFO, device or folder is never read as an image)");
}

}  // namespace rtpro
