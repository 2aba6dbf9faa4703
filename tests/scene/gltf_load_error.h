#pragma once
// For the scene module's glTF tests: what loading a broken glTF file says.
#include "gltf_loader.h"
#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rtpro::test {

// One triangle's positions: (1,0,0), (0,1,0), (0,0,1).
inline const std::vector<float> kTriangle = {1, 0, 0, 0, 1, 0, 0, 0, 1};

// The message of the InputError loading `file` throws (which must name the file); a test failure
// when it loads.
inline std::string gltf_error_of(const std::filesystem::path& file) {
  try {
    load_gltf_file(file);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
    return e.message();
  }
  ADD_FAILURE() << file << " loaded";
  return {};
}

}  // namespace rtpro::test
