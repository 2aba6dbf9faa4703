#include "image_format_sniff.h"

#include "pixel_encoding.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>

namespace rtpro {

namespace {

struct Signature {
  std::string_view bytes;
  std::size_t offset;
  std::string_view format;
};

using namespace std::string_view_literals;

// The formats rtpro writes and the common ones a user hands to `rtpro compare`, by signatures that
// no text file or other format starts with by chance. Every other format (Targa, DPX, PSD, WebP,
// camera raw, ...) is read by its extension alone, so that a hostile file reaches one of the less
// hardened readers only when it is named for it.
constexpr std::array kSignatures = {
    Signature{"\x76\x2f\x31\x01"sv, 0, "openexr"},
    Signature{"\x89PNG\r\n\x1a\n"sv, 0, "png"},
    Signature{"\xff\xd8\xff"sv, 0, "jpeg"},
    Signature{"II*\0"sv, 0, "tiff"},
    Signature{"MM\0*"sv, 0, "tiff"},
    Signature{"II+\0"sv, 0, "tiff"},
    Signature{"MM\0+"sv, 0, "tiff"},
    Signature{"#?RADIANCE"sv, 0, "hdr"},
    Signature{"#?RGBE"sv, 0, "hdr"},
    Signature{"GIF87a"sv, 0, "gif"},
    Signature{"GIF89a"sv, 0, "gif"},
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

std::string_view image_format_from_signature(std::string_view head) {
  for (const Signature& signature : kSignatures)
    if (head.size() >= signature.offset + signature.bytes.size() &&
        head.substr(signature.offset, signature.bytes.size()) == signature.bytes)
      return signature.format;
  // Netpbm (P1-P6) and PFM (PF, Pf): a letter and a digit alone are too common to trust, so the
  // header's separator must follow.
  if (head.size() >= 3 && head[0] == 'P' && is_space(head[2])) {
    if (head[1] >= '1' && head[1] <= '6') return "pnm";
    if (head[1] == 'F' || head[1] == 'f') return "pnm";
  }
  if (head.size() >= 2 && head[0] == 'B' && head[1] == 'M') return "bmp";
  return {};
}

std::string image_reader_name(const std::filesystem::path& file) {
  std::array<char, 16> head{};
  std::size_t count = 0;
  if (std::ifstream in{file, std::ios::binary}) {
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    count = static_cast<std::size_t>(in.gcount());
  }
  if (const std::string_view format = image_format_from_signature({head.data(), count}); !format.empty())
    return std::string(format);
  std::string extension = lowercase_extension(file);
  if (!extension.empty()) extension.erase(0, 1);
  return extension;
}

}  // namespace rtpro
