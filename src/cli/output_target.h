#pragma once
// Where `rtpro render` writes its image: a file named by -o (the extension picks the format), or
// standard output for `-o -` (the format from --format), and what --exposure does to it.
#include "rtpro/image/image.h"
#include "rtpro/image/image_io.h"
#include "rtpro/core/temporary_folder.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtpro::cli {

// --help text: each format and how its pixels are encoded.
extern const char* const kOutputFormatsHelp;

class OutputTarget {
 public:
  // Throws InputError for `-o -` without --format, or a --format that contradicts the extension.
  OutputTarget(const std::string& output, const std::string& format);
  // Moving hands over the temporary folder of a stdout target: only one of them removes it.
  OutputTarget(OutputTarget&& other) noexcept;
  OutputTarget(const OutputTarget&) = delete;
  OutputTarget& operator=(const OutputTarget&) = delete;
  ~OutputTarget();  // removes the temporary folder of a stdout target

  // What the image writer writes: the -o file, or "image.FORMAT" in a private temporary folder.
  const std::filesystem::path& file() const { return file_; }
  bool to_stdout() const { return to_stdout_; }
  // How messages name the target: the file, or "standard output".
  std::string name() const;
  // Writes the image of a render: to file() when `complete` or for standard output (copied there
  // then), else beside the -o file as NAME.partial.EXT, so an interrupted render never replaces a
  // finished image. Returns the file written.
  std::filesystem::path write(const Image& image, bool complete, const ImageWriteOptions& options) const;

 private:
  // For a stdout target, copies the written file to standard output; otherwise nothing.
  void deliver() const;

  std::filesystem::path file_;
  bool to_stdout_ = false;
  std::optional<TemporaryFolder> stdout_folder_;  // holds file_ for a stdout target
};

// A file a command reads or writes, and how the command line names it ("-o", "--stats-json",
// "the reference").
struct NamedPath {
  std::string what;
  std::string path;
};

// Throws InputError naming both when `output` is the same file as one of `others` (the same path
// once '..' and symbolic links are resolved, or one existing file under two names): writing it
// would replace an input, or one output would replace another. `-` (standard output) and empty
// paths are never the same as anything. A check before anything is rendered.
void check_output_is_distinct(const NamedPath& output, const std::vector<NamedPath>& others);

// Throws InputError unless stops is within ±64 (a check before the render).
void check_exposure(double stops);
// --exposure: multiplies the colour channels (R, G, B; not the AOVs) by 2^stops. Throws
// InputError unless stops is within ±64.
void apply_exposure(Image& image, double stops);

}  // namespace rtpro::cli
