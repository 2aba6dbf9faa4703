#include "rtpro/image/image_size.h"

#include "image_format_sniff.h"
#include "image_header_check.h"
#include "image_file_check.h"
#include "rtpro/core/error.h"

#include <OpenImageIO/imageio.h>

#include <exception>
#include <string>

namespace rtpro {

ImageSize read_image_size(const std::filesystem::path& file) {
  // Formats whose library allocates from the declared size when a file is opened (image_header_check.h)
  // are answered from rtpro's own reading of the header, without opening them.
  if (const std::optional<ImageSize> size = image_size_from_header(file)) return *size;
  const SourceLocation where{file.string()};
  const std::string reader = image_reader_name(file);
  if (reader.empty())
    throw InputError(where, "cannot tell what kind of image this is: it has no extension and no signature rtpro knows");
  try {
    const auto input = OIIO::ImageInput::create(reader, /*do_open=*/false);
    OIIO::ImageSpec spec;
    if (!input || !input->open(file.string(), spec))
      throw InputError(
          where, "cannot read the image's header as " + reader + ": " + (input ? input->geterror() : OIIO::geterror()));
    input->close();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw InputError(where, "the image has no pixels");
    return {static_cast<std::uint64_t>(spec.width), static_cast<std::uint64_t>(spec.height),
            static_cast<std::uint64_t>(spec.nchannels)};
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& failure) {
    throw InputError(where, "the image library failed on this file's header: " + std::string(failure.what()));
  }
}

}  // namespace rtpro
