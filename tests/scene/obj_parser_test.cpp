// Reading OBJ statements: indices, numbers, faces and their errors, and the chunked parallel parse.
#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"
#include "obj_fixtures.h"
#include "obj_parser.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <string>

namespace rtpro {
namespace obj_parser_test {

using test::mesh_load_error;
using test::write_file;

std::string ErrorOf(const std::string& obj_text) { return mesh_load_error(write_file("bad.obj", obj_text)).what(); }

TEST(ObjLoader, CubeOfQuadsWithoutSmoothingGroupsIsFlat) {
  const LoadedMesh loaded =
      load_mesh_file(write_file("cube.obj", std::string(test::kCubePositions) + test::kCubeFaces));
  EXPECT_EQ(loaded.mesh.vertices.size(), 8u);
  EXPECT_EQ(loaded.mesh.triangles.size(), 12u);
  EXPECT_EQ(loaded.stats.faces, 6u);
  EXPECT_EQ(loaded.stats.triangles, 12u);
  EXPECT_EQ(loaded.stats.vertices, 8u);
  // No `s` statement means no smoothing group: flat faces, as Blender and 3ds Max read it. A
  // mesh without normals is shaded with each triangle's own face normal.
  EXPECT_FALSE(loaded.stats.normals_generated);
  EXPECT_TRUE(loaded.mesh.normals.empty());
  EXPECT_TRUE(loaded.materials.empty());
  EXPECT_EQ(loaded.mesh.material, kNoMaterial);
  EXPECT_TRUE(loaded.mesh.triangle_materials.empty());
  EXPECT_EQ(loaded.mesh.name, "cube");
}

TEST(ObjLoader, NegativeIndicesCountBackFromTheirLine) {
  const LoadedMesh loaded = load_mesh_file(write_file("relative.obj",
                                                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                                                      "v 1 1 0\nf -3 -1 -2\n"));
  ASSERT_EQ(loaded.mesh.triangles.size(), 2u);
  const TriangleIndices& first = loaded.mesh.triangles[0];
  const TriangleIndices& second = loaded.mesh.triangles[1];
  EXPECT_EQ((std::array{first.v0, first.v1, first.v2}), (std::array{0u, 1u, 2u}));
  EXPECT_EQ((std::array{second.v0, second.v1, second.v2}), (std::array{1u, 3u, 2u}));
}

TEST(ObjLoader, ReadsTheSameNumbersNearTheEndOfTheFile) {
  // Numbers close to the end of the buffer take the general (not the 8-byte-load) path.
  const std::string lines = "v 0.0503644 -1.5 7\nv 1 0 0\nv 0 1 0\n";
  const LoadedMesh early = load_mesh_file(write_file("early.obj", lines + "f 1 2 3\n# padding for the fast paths\n"));
  const LoadedMesh late = load_mesh_file(write_file("late.obj", "# the same mesh\n" + lines + "f 1 2 3"));
  ASSERT_EQ(late.mesh.triangles.size(), 1u);
  EXPECT_EQ(late.mesh.vertex(0), Vec3(0.0503644f, -1.5f, 7.0f));
  EXPECT_EQ(late.mesh.vertex(0), early.mesh.vertex(0));
  EXPECT_EQ(late.mesh.triangles[0].v2, 2u);
}

TEST(ObjLoader, ZeroIndexIsAnErrorNamingItsLine) {
  const InputError e = mesh_load_error(write_file("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
  EXPECT_EQ(e.where().line, 4);
  EXPECT_EQ(e.where().column, 3);
  EXPECT_NE(std::string(e.what()).find("zero.obj:4:3"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("index 0"), std::string::npos) << e.message();
}

TEST(ObjLoader, OutOfRangeIndicesAreErrorsNamingTheirLine) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const InputError past_end = mesh_load_error(write_file("past.obj", vertices + "f 1 2 3\nf 1 2 4\n"));
  EXPECT_EQ(past_end.where().line, 5);
  EXPECT_NE(past_end.message().find("out of range"), std::string::npos) << past_end.message();

  const InputError before_start = mesh_load_error(write_file("before.obj", vertices + "f -1 -2 -4\n"));
  EXPECT_EQ(before_start.where().line, 4);
  EXPECT_NE(before_start.message().find("-4"), std::string::npos) << before_start.message();

  // Relative indices count only what precedes their line, even when more vertices follow.
  const InputError not_yet = mesh_load_error(write_file("ahead.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n"));
  EXPECT_EQ(not_yet.where().line, 3);

  const InputError normal = mesh_load_error(write_file("normal.obj", vertices + "vn 0 0 1\nf 1//1 2//2 3//1\n"));
  EXPECT_EQ(normal.where().line, 5);
  EXPECT_NE(normal.message().find("normal index 2"), std::string::npos) << normal.message();

  const InputError texcoord = mesh_load_error(write_file("texcoord.obj", vertices + "vt 0 0\nf 1/1 2/2 3/1\n"));
  EXPECT_EQ(texcoord.where().line, 5);
}

TEST(ObjLoader, MalformedAndNonFiniteNumbersAreErrorsNamingLineAndColumn) {
  struct Case {
    const char* line;
    int column;
    const char* says;
  };
  const Case cases[] = {
      {"v abc 0 0", 3, "'abc' is not a number"},
      {"v 1,5 0 0", 3, "'1,5' is not a number"},
      {"v 1 0", 6, "needs 3 coordinates, found 2"},
      {"v nan 0 0", 3, "not a finite number"},
      {"v 0 -inf 0", 5, "not a finite number"},
      {"v 0 0 1e999", 7, "not a finite number"},
      {"v 0 0 1e20", 7, "beyond the supported magnitude"},
      {"vn 0 0 x", 8, "'x' is not a number"},
      {"vt 0.5 1..0", 8, "is not a number"},
      {"v 1 2 3 4 5 6 7", 15, "unexpected '7'"},
  };
  for (const Case& c : cases) {
    const InputError e = mesh_load_error(write_file("numbers.obj", std::string("v 0 0 0\n") + c.line + "\n"));
    EXPECT_EQ(e.where().line, 2) << c.line;
    EXPECT_EQ(e.where().column, c.column) << c.line;
    EXPECT_NE(e.message().find(c.says), std::string::npos) << c.line << ": " << e.message();
  }
}

TEST(ObjLoader, MalformedFacesAreErrors) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_NE(ErrorOf(vertices + "f 1 2\n").find("at least 3 vertices"), std::string::npos);
  EXPECT_NE(ErrorOf(vertices + "f 1 2 x\n").find("bad.obj:4:7: expected a vertex index"), std::string::npos);
  EXPECT_NE(ErrorOf(vertices + "f 1 2 3/\n").find("expected a texture coordinate index"), std::string::npos);
  EXPECT_NE(ErrorOf(vertices + "f 1 2 3.5\n").find("malformed face vertex '3.5'"), std::string::npos);
  EXPECT_NE(ErrorOf(vertices + "f 1 2 99999999999999999999\n").find("expected a vertex index"), std::string::npos);
}

TEST(ObjLoader, DegenerateTrianglesAreDroppedAndCounted) {
  const LoadedMesh loaded = load_mesh_file(write_file("degenerate.obj",
                                                      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                      "f 1 1 2\nf 1 2 2 3\nf 1 2 3\n"));
  EXPECT_EQ(loaded.stats.faces, 3u);
  EXPECT_EQ(loaded.mesh.triangles.size(), 2u);
  EXPECT_EQ(loaded.stats.dropped_degenerate, 2u);
}

TEST(ObjLoader, UnknownStatementsWarnOncePerKeyword) {
  const LoadedMesh loaded = load_mesh_file(write_file("unknown.obj",
                                                      "o thing\ng part\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                      "l 1 2\nl 2 3\ncstype bspline\nf 1 2 3\n"));
  ASSERT_EQ(loaded.stats.warnings.size(), 2u);
  EXPECT_NE(loaded.stats.warnings[0].find("unknown.obj:6: ignored 'l' statements (2 in total)"), std::string::npos);
  EXPECT_NE(loaded.stats.warnings[1].find(":8: ignored 'cstype' statements (1 in total)"), std::string::npos);
  EXPECT_EQ(loaded.mesh.name, "thing");
}

TEST(ObjLoader, MissingFileAndUnknownExtensionAreInputErrors) {
  EXPECT_THROW(load_mesh_file(test::scratch_dir() / "absent.obj"), InputError);
  EXPECT_THROW(load_mesh_file(write_file("mesh.stl", "solid x\n")), InputError);
}

// A mesh exercising every statement, long enough to span many small chunks.
std::string varied_obj(int rows) {
  std::ostringstream obj;
  obj << "mtllib varied.mtl\n# a grid of quads and triangles\n";
  for (int y = 0; y <= rows; ++y)
    for (int x = 0; x <= rows; ++x) obj << "v " << x * 0.25 << ' ' << y * 0.5 << ' ' << (x * y % 7) * 0.1 << "\n";
  obj << "vn 0 0 1\nvn 0 1 1\nvt 0 0\n";
  const int row = rows + 1;
  for (int y = 0; y < rows; ++y) {
    if (y % 5 == 0) obj << "usemtl " << (y % 2 ? "a" : "b") << "\n";
    if (y % 3 == 0) obj << (y % 2 ? "s off\n" : "s 4\n");
    for (int x = 0; x < rows; ++x) {
      const int i = y * row + x + 1;
      if (x % 4 == 0) obj << "f " << i << ' ' << i + 1 << ' ' << i + row + 1 << ' ' << i + row << "\n";
      else if (x % 4 == 1)
        obj << "f " << i << ' ' << i + 1 << ' ' << i + row << "\nf " << i + 1 << ' ' << i + row + 1 << ' ' << i + row
            << "\n";
      else if (x % 4 == 2)
        obj << "f " << i - (row * (rows + 1) + 1) << " " << i + 1 << ' ' << i + row << "\n";  // relative
      else obj << "f " << i << ' ' << i << ' ' << i + row << "\nl 1 2\n";  // degenerate, then an ignored line
    }
  }
  return obj.str();
}

TEST(ObjLoader, ParallelChunkedParseEqualsSerialParse) {
  write_file("varied.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
  const std::string text = varied_obj(50);
  const auto file = write_file("varied.obj", text);
  const LoadedMesh serial = load_obj_file(file, {}, text.size() + 1);
  ASSERT_GT(serial.mesh.triangles.size(), 3000u);
  ASSERT_EQ(serial.materials.size(), 2u);
  for (std::size_t chunk_bytes : {std::size_t(1), std::size_t(64), std::size_t(1000), std::size_t(4096)}) {
    SCOPED_TRACE(chunk_bytes);
    const LoadedMesh chunked = load_obj_file(file, {}, chunk_bytes);
    ASSERT_EQ(chunked.mesh.vertices.size(), serial.mesh.vertices.size());
    for (std::size_t i = 0; i < serial.mesh.vertices.size(); ++i)
      ASSERT_EQ(chunked.mesh.vertices[i].position(), serial.mesh.vertices[i].position()) << i;
    ASSERT_EQ(chunked.mesh.triangles.size(), serial.mesh.triangles.size());
    for (std::size_t i = 0; i < serial.mesh.triangles.size(); ++i) {
      const TriangleIndices &a = chunked.mesh.triangles[i], &b = serial.mesh.triangles[i];
      ASSERT_TRUE(a.v0 == b.v0 && a.v1 == b.v1 && a.v2 == b.v2) << i;
    }
    EXPECT_EQ(chunked.mesh.normals, serial.mesh.normals);
    EXPECT_EQ(chunked.mesh.triangle_materials, serial.mesh.triangle_materials);
    EXPECT_EQ(chunked.stats.dropped_degenerate, serial.stats.dropped_degenerate);
    EXPECT_EQ(chunked.stats.faces, serial.stats.faces);
    EXPECT_EQ(chunked.stats.warnings, serial.stats.warnings);
  }
}

TEST(ObjLoader, ResultsDoNotDependOnTheThreadCount) {
  write_file("varied.mtl", "newmtl a\nnewmtl b\n");
  const auto file = write_file("threads.obj", varied_obj(30));
  const LoadedMesh parallel = load_obj_file(file, {}, 512);
  const LoadedMesh serial = [&] {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    return load_obj_file(file, {}, 512);
  }();
  ASSERT_FALSE(serial.mesh.normals.empty());
  EXPECT_EQ(parallel.mesh.normals, serial.mesh.normals);
  EXPECT_EQ(parallel.mesh.triangle_materials, serial.mesh.triangle_materials);
}

TEST(ObjLoader, ChunkedParseReportsTheFirstErrorWithItsFileLine) {
  std::string text = varied_obj(20);
  const auto lines_before = std::count(text.begin(), text.end(), '\n');
  text += "f 1 2 0\nv bad 0 0\n";
  const auto file = write_file("late_error.obj", text);
  for (std::size_t chunk_bytes : {std::size_t(7), std::size_t(500), text.size()}) {
    try {
      load_obj_file(file, {}, chunk_bytes);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, lines_before + 1) << chunk_bytes;
      EXPECT_NE(e.message().find("index 0"), std::string::npos) << e.message();
    }
  }
}

}  // namespace obj_parser_test
}  // namespace rtpro
