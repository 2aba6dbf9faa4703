#pragma once
// tev's IPC packets (tev's include/tev/Ipc.h and src/Ipc.cpp): each packet is a little-endian
// uint32 byte count that includes itself, a type byte, then fields: bool as one byte, strings
// NUL-terminated, lists without a count (the count came earlier), integers and floats as their
// little-endian bytes. The two rtpro sends:
//   CreateImage (4):   grab_focus, name, int32 width, int32 height, int32 channels, channel names
//   UpdateImageV3 (6): grab_focus, name, int32 channels, channel names, int32 x, y, width, height,
//                      int64 offsets[channels], int64 strides[channels], float data[]
// where channel c of pixel p (row-major in the x, y, width, height rectangle) is
// data[offsets[c] + p * strides[c]].
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro::cli::tev {

enum PacketType : char { kCreateImage = 4, kUpdateImageV3 = 6 };

class PacketWriter {
 public:
  explicit PacketWriter(PacketType type) : bytes_(4, '\0') { bytes_.push_back(type); }

  PacketWriter& boolean(bool value) {
    bytes_.push_back(value ? 1 : 0);
    return *this;
  }
  PacketWriter& text(std::string_view value) {
    bytes_.append(value);
    bytes_.push_back('\0');
    return *this;
  }
  template <typename T>
  PacketWriter& number(T value) {  // x86-64 and ARM64 Linux are little-endian, as tev's wire is
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes_.append(raw, sizeof(T));
    return *this;
  }
  PacketWriter& floats(const std::vector<float>& values) {
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
    return *this;
  }

  std::string finish() {
    const auto size = static_cast<std::uint32_t>(bytes_.size());
    std::memcpy(bytes_.data(), &size, sizeof size);
    return std::move(bytes_);
  }

 private:
  std::string bytes_;
};

}  // namespace rtpro::cli::tev
