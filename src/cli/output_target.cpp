#include "output_target.h"

#include "render_output.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/core/temporary_folder.h"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <utility>

namespace rtpro::cli {

const char* const kOutputFormatsHelp =
    "Output image, or '-' for standard output with --format. The extension picks the format and its "
    "encoding: .exr (.sxr .mxr) 32-bit float, scene-linear, the only format with --aov layers; .hdr .rgbe "
    "float, scene-linear, RGB only; .tif .tiff 16-bit, display-referred (the OCIO view, no clamp "
    "below 1); .png .jpg and every other OpenImageIO format 8-bit, display-referred (OCIO view, clamped)";

namespace {

std::string lowercase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string without_dot(const std::string& format) {
  return !format.empty() && format[0] == '.' ? format.substr(1) : format;
}

constexpr const char* kStdoutTemporaryPrefix = "rtpro-stdout-";

}  // namespace

OutputTarget::OutputTarget(const std::string& output, const std::string& format) {
  const std::string wanted = lowercase(without_dot(format));
  if (output == "-") {
    if (wanted.empty()) throw InputError("-o - writes to standard output and needs --format, e.g. --format exr");
    if (::isatty(STDOUT_FILENO) == 1)
      throw InputError(
          "-o - would write binary image data to the terminal; redirect standard output to a file or pipe");
    to_stdout_ = true;
    // A private folder: the image is written and read back where no one else can plant a file.
    stdout_folder_.emplace(kStdoutTemporaryPrefix, "the image for standard output");
    file_ = stdout_folder_->path() / ("image." + wanted);
    return;
  }
  file_ = output;
  const std::string extension = lowercase(without_dot(file_.extension().string()));
  if (!wanted.empty() && wanted != extension)
    throw InputError("--format " + format + " contradicts -o " + output +
                     ": a file's format comes from its extension (--format is for -o -)");
}

OutputTarget::OutputTarget(OutputTarget&& other) noexcept
    : file_(std::move(other.file_)), to_stdout_(std::exchange(other.to_stdout_, false)),
      stdout_folder_(std::move(other.stdout_folder_)) {
  other.stdout_folder_.reset();
}

OutputTarget::~OutputTarget() = default;

std::string OutputTarget::name() const { return to_stdout_ ? "standard output" : file_.string(); }

std::filesystem::path OutputTarget::write(const Image& image, bool complete, const ImageWriteOptions& options) const {
  const std::filesystem::path written = complete || to_stdout_ ? file_ : partial_path(file_);
  write_image(written, image, options);
  deliver();
  return written;
}

void OutputTarget::deliver() const {
  if (!to_stdout_) return;
  std::ifstream in(file_, std::ios::binary);
  if (!in) throw RuntimeError("cannot read back the image for standard output: " + file_.string());
  char chunk[65536];
  while (in) {
    in.read(chunk, sizeof chunk);
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    if (got > 0 && std::fwrite(chunk, 1, got, stdout) != got)
      throw RuntimeError(std::string("cannot write the image to standard output: ") + std::strerror(errno));
  }
  if (std::fflush(stdout) != 0)
    throw RuntimeError(std::string("cannot write the image to standard output: ") + std::strerror(errno));
}

namespace {

bool same_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  if (std::filesystem::exists(a, error) && std::filesystem::exists(b, error)) {
    const bool equivalent = std::filesystem::equivalent(a, b, error);
    if (!error) return equivalent;
  }
  std::error_code error_a, error_b;
  const std::filesystem::path canonical_a = std::filesystem::weakly_canonical(a, error_a);
  const std::filesystem::path canonical_b = std::filesystem::weakly_canonical(b, error_b);
  if (error_a || error_b) return a.lexically_normal() == b.lexically_normal();
  return canonical_a == canonical_b;
}

}  // namespace

void check_output_is_distinct(const NamedPath& output, const std::vector<NamedPath>& others) {
  if (output.path.empty() || output.path == "-") return;
  for (const NamedPath& other : others) {
    if (other.path.empty() || other.path == "-") continue;
    if (same_file(output.path, other.path))
      throw InputError(output.what + " " + printable_text(output.path) + " is the same file as " + other.what + " " +
                       printable_text(other.path) + ": writing it would replace that; choose another name");
  }
}

void check_exposure(double stops) {
  if (!(std::fabs(stops) <= 64.0)) throw InputError("--exposure must be a number of stops from -64 to 64");
}

void apply_exposure(Image& image, double stops) {
  check_exposure(stops);
  if (stops == 0.0) return;
  const auto scale = static_cast<float>(std::exp2(stops));
  for (int c = 0; c < image.channel_count(); ++c) {
    const std::string& name = image.channels[static_cast<std::size_t>(c)];
    if (name != "R" && name != "G" && name != "B") continue;
    for (std::size_t i = static_cast<std::size_t>(c); i < image.data.size(); i += image.channels.size())
      image.data[i] *= scale;
  }
}

}  // namespace rtpro::cli
