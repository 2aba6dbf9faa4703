#include "rtpro/image/output_check.h"

#include "oiio_output_formats.h"
#include "pixel_encoding.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace rtpro {

namespace {

// Answers from the list generated from OpenImageIO at build time, not from OpenImageIO itself,
// which is only loaded when an image is written (see image_layer.h).
bool openimageio_writes(const std::filesystem::path& file) {
  std::string extension = lowercase_extension(file);
  if (extension.size() < 2) return false;  // no extension, or a bare "."
  extension.erase(0, 1);
  return std::binary_search(kOiioOutputExtensions.begin(), kOiioOutputExtensions.end(), extension);
}

}  // namespace

void check_image_output(const std::filesystem::path& file) {
  if (file.empty()) throw InputError("no output file given");
  if (!openimageio_writes(file))
    throw InputError("cannot write '" + file.string() + "': unknown image format '" + file.extension().string() +
                     "' (use .exr, .png, .jpg or .tif)");
  // The atomic writer's own checks (folder, file type, a full file system), then its temporary
  // file created and removed again: a folder that passes the checks but takes no file (root in
  // /proc, an immutable folder, root squashed on NFS) fails here, not after the render.
  const AtomicFileReplacement probe(file);
}

}  // namespace rtpro
