#pragma once
// A whole input file as read-only bytes, memory-mapped so a large mesh costs no copy and no heap.
#include <cstddef>
#include <filesystem>
#include <string_view>

namespace rtpro {

class MappedFile {
 public:
  // Throws InputError naming the file when it cannot be opened or is not a regular file.
  explicit MappedFile(const std::filesystem::path& file);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view text() const { return {data_, size_}; }
  const char* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace rtpro
