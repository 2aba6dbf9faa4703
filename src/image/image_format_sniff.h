#pragma once
// Which OpenImageIO reader opens a file. OpenImageIO's own choice is the reader the extension names
// and, when that one fails, every reader it has, in turn: LibRaw, FFmpeg, OpenVDB, DICOM and a
// dozen more parse bytes that were never meant for them. That is slow (a few hundred bad files a
// second, most of it LibRaw clearing megabytes) and it hands hostile input to libraries rtpro
// never meant to expose. rtpro instead picks one reader: by the file's signature when it has one
// of the signatures below, else by its extension, and never tries the others.
#include <filesystem>
#include <string>
#include <string_view>

namespace rtpro {

// The OpenImageIO format name ("openexr", "png", "jpeg", "tiff", "hdr", "gif", "pnm", "bmp") whose
// signature `head` (the first bytes of a file, at least 16 when the file has them) starts with, or
// an empty view.
std::string_view image_format_from_signature(std::string_view head);

// The format name for `file`: from its signature when it has a known one, else its lower-case
// extension without the dot (which OpenImageIO maps to a reader), else empty. Reads at most 16
// bytes; an unreadable file gives the extension.
std::string image_reader_name(const std::filesystem::path& file);

}  // namespace rtpro
