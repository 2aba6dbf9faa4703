#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace rtpro {
namespace ply_parser_test {

using test::mesh_load_error;
using test::write_file;

struct Vertex {
  float x, y, z;
  unsigned char red;
};

// Five vertices (with an extra colour property to skip), a quad and a triangle (with an extra
// property after the index list), and an element rtpro does not know.
const std::vector<Vertex> kVertices = {{0, 0, 0, 1}, {1, 0, 0, 2}, {1, 1, 0.5f, 3}, {0, 1, 0, 4}, {2, 0.25f, -1, 5}};
const std::vector<std::vector<int>> kFaces = {{0, 1, 2, 3}, {1, 4, 2}};

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

template <typename T>
void put(std::string& out, T value, Encoding encoding) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (encoding == Encoding::kBigEndian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string sample_ply(Encoding encoding, const std::string& coordinate_type = "float") {
  const char* format = encoding == Encoding::kAscii          ? "ascii"
                       : encoding == Encoding::kLittleEndian ? "binary_little_endian"
                                                             : "binary_big_endian";
  std::string ply = std::string("ply\nformat ") + format + " 1.0\ncomment made by a test\n" +
                    "element vertex 5\nproperty " + coordinate_type + " x\nproperty " + coordinate_type + " y\n" +
                    "property " + coordinate_type + " z\nproperty uchar red\n" +
                    "element face 2\nproperty list uchar int vertex_indices\nproperty int flags\n" +
                    "element extra 1\nproperty list uchar float weights\nend_header\n";
  for (const Vertex& v : kVertices) {
    if (encoding == Encoding::kAscii) {
      ply += std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + " " + std::to_string(v.red) +
             "\n";
    } else if (coordinate_type == "double") {
      for (float c : {v.x, v.y, v.z}) put<double>(ply, c, encoding);
      put<unsigned char>(ply, v.red, encoding);
    } else {
      for (float c : {v.x, v.y, v.z}) put<float>(ply, c, encoding);
      put<unsigned char>(ply, v.red, encoding);
    }
  }
  for (const std::vector<int>& face : kFaces) {
    if (encoding == Encoding::kAscii) {
      ply += std::to_string(face.size());
      for (int i : face) ply.append(" ").append(std::to_string(i));
      ply += " 7\n";
    } else {
      put<unsigned char>(ply, static_cast<unsigned char>(face.size()), encoding);
      for (int i : face) put<int>(ply, i, encoding);
      put<int>(ply, 7, encoding);
    }
  }
  if (encoding == Encoding::kAscii) {
    ply += "2 0.5 0.25\n";
  } else {
    put<unsigned char>(ply, 2, encoding);
    put<float>(ply, 0.5f, encoding);
    put<float>(ply, 0.25f, encoding);
  }
  return ply;
}

void expect_same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    EXPECT_EQ(a.vertices[i].position(), b.vertices[i].position()) << i;
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t i = 0; i < a.triangles.size(); ++i) {
    EXPECT_EQ(a.triangles[i].v0, b.triangles[i].v0);
    EXPECT_EQ(a.triangles[i].v1, b.triangles[i].v1);
    EXPECT_EQ(a.triangles[i].v2, b.triangles[i].v2);
  }
  EXPECT_EQ(a.normals, b.normals);
}

TEST(PlyLoader, AsciiAndBothBinaryEncodingsGiveIdenticalMeshes) {
  const LoadedMesh ascii = load_mesh_file(write_file("ascii.ply", sample_ply(Encoding::kAscii)));
  const LoadedMesh little = load_mesh_file(write_file("little.ply", sample_ply(Encoding::kLittleEndian)));
  const LoadedMesh big = load_mesh_file(write_file("big.ply", sample_ply(Encoding::kBigEndian)));
  const LoadedMesh doubles = load_mesh_file(write_file("doubles.ply", sample_ply(Encoding::kBigEndian, "double")));
  ASSERT_EQ(ascii.mesh.vertices.size(), 5u);
  EXPECT_EQ(ascii.mesh.vertex(4), Vec3(2, 0.25f, -1));
  ASSERT_EQ(ascii.mesh.triangles.size(), 3u);  // the quad becomes two
  EXPECT_EQ(ascii.stats.faces, 2u);
  EXPECT_EQ(ascii.stats.triangles, 3u);
  // No normals in the file: flat, as other PLY readers show it.
  EXPECT_FALSE(ascii.stats.normals_generated);
  EXPECT_TRUE(ascii.mesh.normals.empty());
  expect_same_mesh(ascii.mesh, little.mesh);
  expect_same_mesh(ascii.mesh, big.mesh);
  expect_same_mesh(ascii.mesh, doubles.mesh);
}

TEST(PlyLoader, ReadsTheSameMeshAsTheEquivalentObj) {
  const LoadedMesh ply = load_mesh_file(write_file("same.ply", sample_ply(Encoding::kAscii)));
  const LoadedMesh obj = load_mesh_file(write_file("same.obj",
                                                   "v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nv 2 0.25 -1\n"
                                                   "f 1 2 3 4\nf 2 5 3\n"));
  expect_same_mesh(ply.mesh, obj.mesh);
}

TEST(PlyLoader, FileNormalsAreNormalised) {
  const LoadedMesh loaded =
      load_mesh_file(write_file("normals.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\n"
                                "property float x\nproperty float y\nproperty float z\n"
                                "property float nx\nproperty float ny\nproperty float nz\n"
                                "element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
                                "0 0 0 0 0 2\n1 0 0 0 3 0\n0 1 0 4 0 0\n3 0 1 2\n"));
  EXPECT_FALSE(loaded.stats.normals_generated);
  EXPECT_EQ(loaded.mesh.normals, (std::vector<Vec3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}}));
}

TEST(PlyLoader, HugeDeclaredCountsInATinyFileAreRejectedBeforeAllocating) {
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  header.resize(200, '\0');
  const InputError e = mesh_load_error(write_file("huge.ply", header));
  EXPECT_EQ(e.where().line, 3);
  EXPECT_NE(e.message().find("declares 1099511627776"), std::string::npos) << e.message();

  std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 18446744073709551615\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_THROW(load_mesh_file(write_file("huge_ascii.ply", ascii + "0 0 0\n")), InputError);
}

TEST(PlyLoader, TruncatedBinaryBodyIsAnErrorNamingTheByteOffset) {
  std::string ply = sample_ply(Encoding::kLittleEndian);
  ply.resize(ply.size() - 3);
  const InputError e = mesh_load_error(write_file("truncated.ply", ply));
  EXPECT_NE(e.message().find("truncated"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("byte offset " + std::to_string(ply.size() - 1)), std::string::npos) << e.message();
}

TEST(PlyLoader, NonFiniteBinaryCoordinateIsAnError) {
  std::string ply = sample_ply(Encoding::kLittleEndian);
  const std::size_t body = ply.find("end_header\n") + 11;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&ply[body + 13 + 4], &nan, sizeof nan);  // vertex 1, y
  const InputError e = mesh_load_error(write_file("nan.ply", ply));
  EXPECT_NE(e.message().find("not a finite number (at byte offset " + std::to_string(body + 17) + ")"),
            std::string::npos)
      << e.message();
}

std::string ascii_ply(const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
         body;
}

TEST(PlyLoader, AsciiErrorsNameLineAndColumn) {
  struct Case {
    const char* body;
    int line, column;
    const char* says;
  };
  const Case cases[] = {
      {"0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", 11, 3, "'abc' is not a number"},
      {"0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n", 12, 5, "not a finite number"},
      {"0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13, 7, "vertex index 3 is out of range"},
      {"0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 13, 5, "vertex index -1 is out of range"},
      {"0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, 1, "at least 3 vertices"},
      {"0 0 0\n1 0 0 9\n0 1 0\n3 0 1 2\n", 11, 7, "more values than the header declares"},
      {"0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 11, 4, "too few values"},
      {"0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n", 13, 1, "out of range for its property type"},
      {"0 0 0\n1 0 0\n\n\n\n\n\n\n\n\n\n", 21, 1, "ends before the elements"},  // blank lines hold no element
  };
  for (const Case& c : cases) {
    const InputError e = mesh_load_error(write_file("bad.ply", ascii_ply(c.body)));
    EXPECT_EQ(e.where().line, c.line) << c.body;
    EXPECT_EQ(e.where().column, c.column) << c.body;
    EXPECT_NE(e.message().find(c.says), std::string::npos) << c.body << ": " << e.message();
  }
}

TEST(PlyLoader, MalformedHeadersAreErrors) {
  EXPECT_NE(mesh_load_error(write_file("a.ply", "solid\n")).message().find("not a PLY file"), std::string::npos);
  EXPECT_NE(
      mesh_load_error(write_file("b.ply", "ply\nformat ascii 1.0\nelement vertex 0\n")).message().find("no end_header"),
      std::string::npos);
  EXPECT_NE(
      mesh_load_error(write_file("c.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n"))
          .message()
          .find("unknown property type 'quad'"),
      std::string::npos);
  EXPECT_NE(
      mesh_load_error(write_file("d.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n"))
          .message()
          .find("needs properties x, y and z"),
      std::string::npos);
  const InputError e = mesh_load_error(write_file("e.ply", "ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"));
  EXPECT_EQ(e.where().line, 3);
}

TEST(PlyLoader, DegenerateFacesAreDroppedAndCounted) {
  const LoadedMesh loaded = load_mesh_file(write_file("degenerate.ply", ascii_ply("0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n")));
  EXPECT_EQ(loaded.mesh.triangles.size(), 0u);
  EXPECT_EQ(loaded.stats.dropped_degenerate, 1u);
  EXPECT_EQ(loaded.stats.faces, 1u);
}

TEST(PlyLoader, UnknownHeaderLinesAreOneWarning) {
  // Blender 2.47 wrote its credit line into the header without `comment`.
  const std::string ply =
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org\nsome other line\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const LoadedMesh loaded = load_mesh_file(write_file("blender.ply", ply));
  EXPECT_EQ(loaded.mesh.triangles.size(), 1u);
  ASSERT_EQ(loaded.stats.warnings.size(), 1u);
  EXPECT_NE(
      loaded.stats.warnings[0].find("blender.ply:3: ignored 2 unknown header line(s), the first starting 'Created'"),
      std::string::npos)
      << loaded.stats.warnings[0];
}

TEST(PlyLoader, TextureCoordinatesAndColoursAreKept) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float s\nproperty float t\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 0 0 255 0 0\n1 0 0 1 0 0 255 0\n0 1 0 0 1 0 0 0\n3 0 1 2\n";
  const LoadedMesh loaded = load_mesh_file(write_file("attributes.ply", ply));
  ASSERT_EQ(loaded.mesh.uvs.size(), 3u);
  EXPECT_EQ(loaded.mesh.uvs[1].u, 1.0f);
  EXPECT_EQ(loaded.mesh.uvs[2].v, 1.0f);
  ASSERT_EQ(loaded.mesh.colors.size(), 3u);
  EXPECT_EQ(loaded.mesh.colors[0], Color(1, 0, 0));
  EXPECT_EQ(loaded.mesh.colors[1], Color(0, 1, 0));
  EXPECT_EQ(loaded.mesh.colors[2], Color(0, 0, 0));
}

TEST(PlyLoader, NormalsModes) {
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n1 1 1\n4 0 1 3 2\n";
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n" +
      body;
  const auto file = write_file("modes.ply", ply);
  EXPECT_TRUE(load_mesh_file(file).mesh.normals.empty());
  const LoadedMesh smooth = load_mesh_file(file, {NormalsMode::kSmooth});
  EXPECT_EQ(smooth.mesh.normals.size(), 4u);
  EXPECT_TRUE(smooth.stats.normals_generated);
  EXPECT_THROW(load_mesh_file(file, {NormalsMode::kFile}), InputError);
}

TEST(PlyLoader, EmptyAndWideFilesAreRefusedClearly) {
  EXPECT_NE(mesh_load_error(write_file("empty.ply", "")).message().find("the file is empty"), std::string::npos);
  std::string wide;
  for (const char c : std::string("ply\nformat ascii 1.0\n")) {
    wide += c;
    wide += '\0';
  }
  EXPECT_NE(mesh_load_error(write_file("wide.ply", wide)).message().find("UTF-16"), std::string::npos);
}

}  // namespace ply_parser_test
}  // namespace rtpro
