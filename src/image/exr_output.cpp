#include "exr_output.h"

#include "image_metadata.h"
#include "pixel_encoding.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <set>
#include <thread>

namespace rtpro {

namespace {

// OpenEXR writes the offsets of its line blocks last, seeking back to the table it left blank.
class MemoryStream final : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}

  void write(const char c[], int n) override {
    const std::size_t end = position_ + static_cast<std::size_t>(n);
    if (end > bytes_.size()) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = static_cast<std::size_t>(position); }

  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
  std::size_t position_ = 0;
};

// OpenImageIO's EXR writer stores its standard names under OpenEXR's (its exr_meta_translation),
// and its reader maps them back.
std::string exr_attribute_name(const std::string& name) {
  if (name == "DateTime") return "capDate";
  if (name == "ImageDescription" || name == "description") return "comments";
  if (name == "Copyright") return "owner";
  return name;
}

Imf::Header describe(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  std::set<std::string> names;
  for (const std::string& name : image.channels) {
    if (name.empty() || !names.insert(name).second)
      throw RuntimeError("cannot write " + file.string() + ": channel names must be distinct and not empty");
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  }
  // EXR's own statement of the primaries.
  const float* xy = kRec709Chromaticities;
  Imf::addChromaticities(header, Imf::Chromaticities({xy[0], xy[1]}, {xy[2], xy[3]}, {xy[4], xy[5]}, {xy[6], xy[7]}));
  for (const auto& [key, value] : scene_linear_metadata(options))
    header.insert(exr_attribute_name(key), Imf::StringAttribute(value));
  return header;
}

}  // namespace

bool is_exr_file(const std::filesystem::path& file) {
  const std::string extension = lowercase_extension(file);
  return extension == ".exr" || extension == ".sxr" || extension == ".mxr";
}

std::string encode_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  require_writable_image(file, image);
  try {
    const Imf::Header header = describe(file, image, options);
    const std::size_t channels = image.channels.size();
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < channels; ++c)
      frame.insert(image.channels[c],
                   Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(image.data.data() + c)),
                              sizeof(float) * channels, sizeof(float) * channels * static_cast<std::size_t>(image.width)));
    // Line blocks compressed on every core, as OpenImageIO has OpenEXR do: OpenEXR's own thread
    // pool, started once (an OutputFile's thread count only sizes its buffers).
    static const int threads = [] {
      const int count = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
      Imf::setGlobalThreadCount(count);
      return count;
    }();
    MemoryStream stream;
    {
      Imf::OutputFile output(stream, header, threads);
      output.setFrameBuffer(frame);
      output.writePixels(image.height);
    }
    return stream.take();
  } catch (const RuntimeError&) {
    throw;
  } catch (const std::exception& error) {
    throw RuntimeError("cannot write " + file.string() + ": " + error.what());
  }
}

void write_exr(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  check_replaceable(file);
  write_file_atomically(file, encode_exr(file, image, options));
}

}  // namespace rtpro
