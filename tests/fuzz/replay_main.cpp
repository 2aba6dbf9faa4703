// main() for fuzz targets built without libFuzzer (gcc, or clang without RTPRO_FUZZ): runs the
// target once on every file named on the command line or found in a named folder, so the corpus
// and the regression inputs are replayed as an ordinary test in every build.
//
// It keeps libFuzzer's meaning for the two limits that turn a slow or fat input into a failure:
// -timeout=SECONDS per input and -rss_limit_mb=MB for the peak resident memory of the process.
// Other -flags (libFuzzer's) are accepted and ignored, so one command line serves both builds.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

long peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;  // Linux reports kilobytes
}

std::vector<std::filesystem::path> inputs_in(const std::filesystem::path& path) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(path)) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // a stable order makes a failure easy to reproduce
  } else {
    files.push_back(path);
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  double timeout_seconds = 1200;
  long rss_limit_mb = 2048;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind("-timeout=", 0) == 0) timeout_seconds = std::atof(argument.c_str() + 9);
    else if (argument.rfind("-rss_limit_mb=", 0) == 0) rss_limit_mb = std::atol(argument.c_str() + 14);
    else if (argument.rfind("-", 0) == 0) continue;
    else
      for (auto& file : inputs_in(argument)) files.push_back(std::move(file));
  }
  int failures = 0;
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto start = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > timeout_seconds) {
      std::fprintf(stderr, "SLOW INPUT: %s took %.2f s (limit %.2f s)\n", file.c_str(), seconds, timeout_seconds);
      ++failures;
    }
    if (peak_rss_mb() > rss_limit_mb) {
      std::fprintf(stderr, "FAT INPUT: after %s the peak RSS is %ld MB (limit %ld MB)\n", file.c_str(), peak_rss_mb(),
                   rss_limit_mb);
      return 1;  // the peak cannot go down again: later inputs would all be blamed
    }
  }
  std::fprintf(stderr, "replayed %zu inputs, %d over the time limit, peak RSS %ld MB\n", files.size(), failures,
               peak_rss_mb());
  return failures == 0 ? 0 : 1;
}
