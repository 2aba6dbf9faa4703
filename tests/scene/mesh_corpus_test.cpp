// Every OBJ, PLY and glTF file of Debian's assimp-testmodels (files from many exporters that
// nobody on this project wrote), when the package is installed: each loads with the triangle
// count recorded here or is refused with the message recorded here. Beside each, what
// `assimp info` (assimp-utils 5.2.5) reports, and why the two differ. A file added to the package
// and missing from the table fails the test, so the table stays complete.
#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"
#include "gltf_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>

namespace rtpro {
namespace mesh_corpus_test {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models";  // dpkg -L assimp-testmodels
constexpr long kRefused = -1;

struct CorpusFile {
  const char* path;        // under kCorpus
  long triangles;          // stored triangles (glTF: over all meshes), or kRefused
  const char* refusal;     // a part of the InputError's message when refused
  const char* assimp;      // `assimp info`: faces and primitive types, or "refused"
  const char* difference;  // why rtpro differs from assimp, where it does
};

const CorpusFile kFiles[] = {
    {"OBJ/WusonOBJ.obj", 3732, "", "3732 triangles", ""},
    {"OBJ/box.obj", 12, "", "12 triangles", ""},
    {"OBJ/box_UTF16BE.obj", kRefused, "the file is encoded as UTF-16 (big-endian); rtpro reads OBJ files as A",
     "refused", "assimp loads nothing either"},
    {"OBJ/box_longline.obj", 478, "", "944 linestriangles",
     "a 936-corner face repeating one square 234 times: 934 fan triangles, 466 with a repeated corner dropped; assimp "
     "keeps all"},
    {"OBJ/box_mat_with_spaces.obj", 12, "", "12 triangles", ""},
    {"OBJ/box_without_lineending.obj", 12, "", "12 triangles", ""},
    {"OBJ/concave_polygon.obj", 64, "", "64 triangles", ""},
    {"OBJ/cube_mtllib_after_g.obj", 12, "", "12 triangles", ""},
    {"OBJ/cube_usemtl.obj", 12, "", "12 triangles", ""},
    {"OBJ/cube_with_vertexcolors.obj", 12, "", "12 triangles", ""},
    {"OBJ/cube_with_vertexcolors_uni.obj", 12, "", "12 triangles", ""},
    {"OBJ/empty_mat.obj", 256, "", "256 triangles", "bare newmtl/usemtl (Blender): default material, warning"},
    {"OBJ/multiple_spaces.obj", 1, "", "1 triangles", ""},
    {"OBJ/number_formats.obj", kRefused, "'3.1+e2' is not a number", "1 triangles",
     "'3.1+e2' is malformed: rtpro is strict on numbers, assimp reads 3.1"},
    {"OBJ/point_cloud.obj", 0, "", "refused", "vertices only: empty mesh, warning"},
    {"OBJ/regr01.obj", 2710, "", "2710 triangles", ""},
    {"OBJ/regr_3429812.obj", 4, "", "4 triangles", ""},
    {"OBJ/space_in_material_name.obj", 64, "", "64 triangles", ""},
    {"OBJ/spider.obj", 1368, "", "1340 linestriangles",
     "assimp turns 28 zero-area triangles into lines; rtpro keeps them (never hit)"},
    {"OBJ/testline.obj", 0, "", "18 lines", "only l statements: no triangles (warning)"},
    {"OBJ/testmixed.obj", 12, "", "54 pointslinestriangles", "assimp also counts its points and lines"},
    {"OBJ/testpoints.obj", 0, "", "24 points", "only p statements: no triangles (warning)"},
    {"PLY/Wuson.ply", 3732, "", "3732 triangles", ""},
    {"PLY/cube.ply", 12, "", "12 triangles", ""},
    {"PLY/cube_binary.ply", 12, "", "12 triangles", ""},
    {"PLY/cube_uv.ply", 12, "", "12 triangles", ""},
    {"PLY/float-color.ply", 1, "", "1 triangles", ""},
    {"PLY/issue623.ply", kRefused, "too few values on this line for the header's properties", "refused",
     "the header puts a list in each vertex that the data lacks; assimp reads points"},
    {"PLY/points.ply", 0, "", "refused", "vertices only: empty mesh, warning"},
    {"PLY/pond.0.ply", kRefused, "element 'vertex' declares 70051 instances, more than the 2171512 bytes", "refused",
     "binary body 69 bytes short of what the header declares; assimp reads points"},
    {"glTF/BoxTextured-glTF/BoxTextured.gltf", kRefused, "asset.version: '1.0': rtpro reads glTF 2.0 files only",
     "12 triangles", "glTF 1.0: not read"},
    {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", kRefused,
     "GLB container version 1: rtpro reads glTF 2.0 files only", "refused", "glTF 1.0: not read"},
    {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", kRefused,
     "asset.version: '1.0': rtpro reads glTF 2.0 files only", "12 triangles", "glTF 1.0: not read"},
    {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", kRefused,
     "asset.version: '1.0': rtpro reads glTF 2.0 files only", "12 triangles", "glTF 1.0: not read"},
    {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", kRefused,
     "asset.version: 1 (a number, as glTF 1.0 exporters wrote it): rtpro reads glTF 2.0 files only", "2856 triangles",
     "glTF 1.0: not read"},
    {"glTF/IncorrectVertexArrays/Cube_v1.gltf", kRefused, "asset.version: '1.0': rtpro reads glTF 2.0 files only",
     "58 linestriangles", "glTF 1.0: not read"},
    {"glTF/TwoBoxes/TwoBoxes.gltf", kRefused, "asset.version: '1.0': rtpro reads glTF 2.0 files only", "12 triangles",
     "glTF 1.0: not read"},
    {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 65317, "", "75730 linestriangles",
     "10,413 triangles with a repeated index dropped; assimp keeps them as lines"},
    {"glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12, "", "12 triangles", ""},
    {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", 12, "", "12 triangles", ""},
    {"glTF2/BoxTextured-glTF/BoxTextured.gltf", 12, "", "12 triangles", ""},
    {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", 12, "", "12 triangles", ""},
    {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", 12, "", "12 triangles", ""},
    {"glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12, "", "12 triangles", ""},
    {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", kRefused,
     "extensionsRequired[0]: the file needs 'KHR_technique_webgl', which rtpro does not support", "12 triangles",
     "a required extension rtpro lacks: refused, as the glTF specification asks"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", kRefused,
     "accessors[2]: element 0 is not a finite number", "refused", ""},
    {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", 37116, "", "30936 triangles",
     "assimp merges 3 identical 2,060-triangle meshes (FindInstances)"},
    {"glTF2/IncorrectVertexArrays/Cube.gltf", kRefused,
     "meshes[1].primitives[0].attributes.POSITION: 35 corners for TRIANGLES, not a multiple of 3", "58 linestriangles",
     "a TRIANGLES primitive of 35 vertices: truncated, refused; assimp drops the last two"},
    {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", kRefused,
     "accessors[0]: index 65535 (element 0) is out of range: the primitive h", "refused", ""},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", kRefused,
     "accessors[0]: index 255 (element 0) is out of range: the primitive has", "11 triangles",
     "strict on indices; assimp drops the triangle"},
    {"glTF2/MissingBin/BoxTextured.gltf", kRefused, "buffers[0].uri: 'BoxTextured0.bin' not found", "refused", ""},
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", kRefused,
     "nodes[0]: is its own ancestor (a cycle: nodes[0] -> nodes[1] -> nodes[", "refused", ""},
    {"glTF2/SchemaFailures/sceneWrongType.gltf", kRefused,
     "scene: a non-negative integer expected, found the string 'hello'", "refused", ""},
    {"glTF2/TestNoRootNode/NoScene.gltf", 0, "", "refused", ""},
    {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", 0, "", "refused", ""},
    {"glTF2/cameras/Cameras.gltf", 2, "", "2 triangles", ""},
    {"glTF2/draco/2CylinderEngine.gltf", kRefused,
     "extensionsRequired[0]: the file needs 'KHR_draco_mesh_compression', which", "65311 linestriangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", 0, "", "1024 points",
     "POINTS skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", 0, "", "1024 points",
     "POINTS skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", 0, "", "4 lines",
     "lines skipped (warning)"},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_11.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_15.gltf", 2, "", "2 triangles", ""},
    {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12, "", "12 triangles", ""},
    {"glTF2/issue_3269/texcoord_crash.gltf", 10, "", "refused", "assimp refuses an attribute name rtpro does not read"},
    {"glTF2/simple_skin/simple_skin.gltf", 8, "", "8 triangles", ""},
    {"glTF2/textureTransform/TextureTransformTest.gltf", 18, "", "18 triangles", ""},
    {"glTF2/wrongTypes/badArray.gltf", kRefused, "meshes[0].primitives: an array expected, found an object", "refused",
     ""},
    {"glTF2/wrongTypes/badExtension.gltf", kRefused,
     "baseColorTexture.extensions.KHR_texture_transform: an object expected", "refused", ""},
    {"glTF2/wrongTypes/badNumber.gltf", kRefused, "materials[0].normalTexture.index: missing", "refused",
     "a normalTexture without index (its scale a string)"},
    {"glTF2/wrongTypes/badObject.gltf", kRefused,
     "materials[0].pbrMetallicRoughness: an object expected, found an array", "refused", ""},
    {"glTF2/wrongTypes/badString.gltf", 12, "", "refused", "a scene's name is a number: names are not read"},
    {"glTF2/wrongTypes/badUint.gltf", kRefused, "baseColorTexture.index: a non-negative integer expected, found -1",
     "refused", ""},
    {"invalid/empty.obj", 0, "", "refused", ""},
    {"invalid/empty.ply", kRefused, "the file is empty", "refused", ""},
    {"invalid/malformed.obj", kRefused, "vertex index 12 is out of range: the file has 8", "refused", ""},
    {"invalid/malformed2.obj", kRefused, "face needs at least 3 vertices, found 0", "10 triangles",
     "a bare 'f' line: strict on faces; assimp skips it"},
};

std::string lowercase_extension(const fs::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// The triangle count, or the InputError, of loading `file` as rtpro does.
struct Outcome {
  long triangles = kRefused;
  std::string error;
  std::string error_file;
};

Outcome load(const fs::path& file) {
  Outcome outcome;
  try {
    if (is_gltf_file(file)) outcome.triangles = long(load_gltf_file(file).stats.triangles);
    else outcome.triangles = long(load_mesh_file(file).stats.triangles);
  } catch (const InputError& e) {
    outcome.error = e.message();
    outcome.error_file = e.where().file;
  }
  return outcome;
}

class AssimpCorpus : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_directory(kCorpus))
      GTEST_SKIP() << kCorpus << " is missing: install assimp-testmodels (scripts/install-deps.sh)";
  }
};

TEST_F(AssimpCorpus, EveryFileLoadsWithItsRecordedCountOrIsRefusedAsRecorded) {
  for (const CorpusFile& entry : kFiles) {
    const fs::path file = kCorpus / entry.path;
    SCOPED_TRACE(entry.path);
    ASSERT_TRUE(fs::is_regular_file(file));
    const Outcome outcome = load(file);
    if (entry.triangles == kRefused) {
      EXPECT_EQ(outcome.triangles, kRefused) << "loaded, expected the refusal " << entry.refusal;
      EXPECT_NE(outcome.error.find(entry.refusal), std::string::npos) << outcome.error;
      EXPECT_EQ(outcome.error_file, file.string()) << "the message must name the file";
    } else {
      EXPECT_EQ(outcome.triangles, entry.triangles) << outcome.error;
    }
  }
}

// spider.mtl names its textures as Windows paths (`map_Kd .\SpiderTex.jpg`): each is found
// beside it (the render was refused at the first, '.\SpiderTex.jpg' not found).
TEST_F(AssimpCorpus, SpiderFindsItsTexturesThroughWindowsPaths) {
  const LoadedMesh spider = load_mesh_file(kCorpus / "OBJ/spider.obj");
  int textured = 0;
  for (const MaterialDesc& m : spider.materials)
    if (!m.color_texture.empty()) {
      ++textured;
      EXPECT_EQ(m.color_texture.parent_path(), kCorpus / "OBJ");
      EXPECT_TRUE(fs::is_regular_file(m.color_texture)) << m.color_texture;
    }
  EXPECT_EQ(textured, 4);  // the four materials its faces use
  for (const std::string& w : spider.stats.warnings) EXPECT_EQ(w.find("not found"), std::string::npos) << w;
}

TEST_F(AssimpCorpus, TheTableListsEveryObjPlyAndGltfFile) {
  std::set<std::string> listed;
  for (const CorpusFile& entry : kFiles) listed.insert(entry.path);
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(kCorpus)) {
    const std::string extension = lowercase_extension(e.path());
    if (extension != ".obj" && extension != ".ply" && extension != ".gltf" && extension != ".glb") continue;
    EXPECT_TRUE(listed.count(fs::relative(e.path(), kCorpus).string())) << e.path() << " is not in the table";
  }
}

}  // namespace mesh_corpus_test
}  // namespace rtpro
