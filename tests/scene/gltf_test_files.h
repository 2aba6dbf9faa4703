#pragma once
// Hand-made glTF files for the glTF tests: geometry in a buffer (external .bin or a data: URI),
// JSON assembled with nlohmann-json and written next to it.
#include "test_paths.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::test {

class GltfFile {
 public:
  GltfFile() {
    json["asset"] = {{"version", "2.0"}};
    json["buffers"] = nlohmann::json::array();
    json["bufferViews"] = nlohmann::json::array();
    json["accessors"] = nlohmann::json::array();
  }

  // An accessor over new bytes of the buffer; returns its index.
  int floats(const std::vector<float>& values, const char* type) {
    const int count = int(values.size()) / components(type);
    return accessor(append(values.data(), values.size() * 4), 5126, count, type);
  }
  int indices(const std::vector<std::uint16_t>& values) { return ushorts(values, "SCALAR"); }
  int ushorts(const std::vector<std::uint16_t>& values, const char* type) {
    return accessor(append(values.data(), values.size() * 2), 5123, int(values.size()) / components(type), type);
  }

  // A mesh of one primitive; returns the mesh index.
  int mesh(int positions, int index_accessor = -1, int mode = 4) {
    nlohmann::json primitive = {{"attributes", {{"POSITION", positions}}}, {"mode", mode}};
    if (index_accessor >= 0) primitive["indices"] = index_accessor;
    json["meshes"].push_back({{"primitives", {primitive}}});
    return int(json["meshes"].size()) - 1;
  }

  int node(nlohmann::json node) {
    json["nodes"].push_back(std::move(node));
    return int(json["nodes"].size()) - 1;
  }

  void scene(std::vector<int> roots) { json["scenes"] = {{{"nodes", roots}}}; }

  // Writes NAME.gltf and NAME.bin (or embeds the buffer as base64) into the test's scratch folder.
  std::filesystem::path write(const std::string& name, bool embed = false) {
    nlohmann::json out = json;
    const std::string uri = embed ? "data:application/octet-stream;base64," + base64(bin) : name + ".bin";
    out["buffers"] = {{{"byteLength", bin.size()}, {"uri", uri}}};
    if (!embed) write_file(name + ".bin", bin);
    return write_file(name + ".gltf", out.dump(1));
  }

  nlohmann::json json;
  std::string bin;

 private:
  static int components(const std::string& type) {
    return type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "MAT4" ? 16 : 4;
  }

  int append(const void* data, std::size_t bytes) {
    while (bin.size() % 4) bin += '\0';
    const std::size_t offset = bin.size();
    bin.append(static_cast<const char*>(data), bytes);
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    return int(json["bufferViews"].size()) - 1;
  }

  int accessor(int view, int component_type, int count, const char* type) {
    json["accessors"].push_back(
        {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}});
    return int(json["accessors"].size()) - 1;
  }

  static std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
      std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16;
      if (i + 1 < bytes.size()) n |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
      if (i + 2 < bytes.size()) n |= std::uint8_t(bytes[i + 2]);
      out += table[n >> 18 & 63];
      out += table[n >> 12 & 63];
      out += i + 1 < bytes.size() ? table[n >> 6 & 63] : '=';
      out += i + 2 < bytes.size() ? table[n & 63] : '=';
    }
    return out;
  }
};

}  // namespace rtpro::test
