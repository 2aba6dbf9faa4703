#pragma once
// A guard in front of OpenVDB's reader. OpenVDB 10 trusts every size and count a .vdb file
// states: a string's length becomes a std::string of that many bytes, filled before it is read
// (readString, StringMetadata), a metadata map's count and a root node's tile count become loops
// that go on reading after the file has ended (and a failed read leaves readString's length
// uninitialised). A 74 KB file with one length changed to 0xffffffff cost 47 s and 19 GB before
// OpenVDB gave up; one with the root's tile count changed never finished.
//
// This walks what OpenVDB reads before any voxel, as io::File reads it: the header, the file's
// metadata, each grid descriptor and its offsets, each grid's metadata (the delayed-load table
// included) and transform, and the root node of every float or double tree. Every length and
// count must fit in the bytes of its section, every fixed-size value must state its own size.
// What lies below the root (internal nodes, leaves, compressed value blocks) is left to OpenVDB:
// each node is read from bytes of the file, so a hostile file costs at most a few tens of times
// its own size there (third_party_notes/openvdb.md).
#include <filesystem>
#include <optional>
#include <string>

namespace rtpro {

// What is wrong with the file's layout, naming the byte and the field; nothing for a file whose
// header, metadata, descriptors, transforms and root nodes OpenVDB can read within the file.
std::optional<std::string> vdb_layout_problem(const std::filesystem::path& file);

}  // namespace rtpro
