// The up-front memory estimate of mesh files (render_cost.h): a binary PLY holds a triangle in
// about half the bytes of text, so each of its bytes counts for twice as much.
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rtpro {
namespace {

std::uint64_t estimated_mesh_bytes(const std::string& mesh_file) {
  const auto scene =
      test::write_file("scene.yaml",
                       "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], resolution: [4, 4]}\n"
                       "world:\n  - {type: mesh, file: " +
                           mesh_file + "}\n");
  return estimate_render_cost(parse_scene_file(scene)).mesh_bytes;
}

TEST(RenderCost, ABinaryPlyCountsMoreBytesPerFileByteThanText) {
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  binary.append(3 * 12 + 13, '\0');
  const auto binary_file = test::write_file("binary.ply", binary);
  const auto text_file = test::write_file("text.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(estimated_mesh_bytes("binary.ply"), std::filesystem::file_size(binary_file) * kMeshBytesPerBinaryFileByte);
  EXPECT_EQ(estimated_mesh_bytes("text.obj"), std::filesystem::file_size(text_file) * kMeshBytesPerFileByte);
  EXPECT_GT(kMeshBytesPerBinaryFileByte, kMeshBytesPerFileByte);
}

}  // namespace
}  // namespace rtpro
