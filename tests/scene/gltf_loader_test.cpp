#include "rtpro/core/error.h"
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_load_error.h"
#include "gltf_test_files.h"
#include "mtl_parser.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace rtpro {
namespace gltf_loader_test {

using test::GltfFile;

using test::kTriangle;
const auto error_of = test::gltf_error_of;

void expect_near(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(GltfLoader, HierarchyTransformsMatchHandComputedPositions) {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  const float s = std::sqrt(0.5f);
  // child: a column-major matrix translating by (0, 1, 0), drawing the mesh; root: TRS.
  const int child = gltf.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1}}});
  const int root =
      gltf.node({{"children", {child}}, {"translation", {1, 0, 0}}, {"rotation", {0, s, 0, s}}, {"scale", {2, 2, 2}}});
  gltf.node({{"mesh", mesh}, {"translation", {0, 0, 5}}});  // not in the scene: not placed
  gltf.scene({root});
  const GltfAsset asset = load_gltf_file(gltf.write("tree"));
  ASSERT_EQ(asset.placements.size(), 1u);
  const Affine& t = asset.placements[0].transform;
  // By hand: p + (0,1,0), times 2, rotated 90 degrees about +y ((x,y,z) -> (z,y,-x)), + (1,0,0).
  expect_near(t.apply_point(Vec3(1, 0, 0)), Vec3(1, 2, -2));
  expect_near(t.apply_point(Vec3(0, 1, 0)), Vec3(1, 4, 0));
  expect_near(t.apply_point(Vec3(0, 0, 1)), Vec3(3, 2, 0));
  EXPECT_EQ(asset.stats.triangles, 1u);
}

TEST(GltfLoader, IndexedStripsAndFansKeepTheirWinding) {
  GltfFile gltf;
  const int positions = gltf.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3");
  const int triangles = gltf.mesh(positions, gltf.indices({0, 1, 2, 2, 1, 3}));
  const int strip = gltf.mesh(positions, gltf.indices({0, 1, 2, 3}), 5);
  const int fan = gltf.mesh(gltf.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3"), -1, 6);
  gltf.scene({gltf.node({{"mesh", triangles}}), gltf.node({{"mesh", strip}}), gltf.node({{"mesh", fan}})});
  const GltfAsset asset = load_gltf_file(gltf.write("modes"));
  ASSERT_EQ(asset.meshes.size(), 3u);
  for (const TriangleMesh& mesh : asset.meshes) {
    ASSERT_EQ(mesh.triangles.size(), 2u);
    for (std::uint32_t t = 0; t < 2; ++t) {
      const TriangleIndices& tri = mesh.triangles[t];
      EXPECT_GT(cross(mesh.vertex(tri.v1) - mesh.vertex(tri.v0), mesh.vertex(tri.v2) - mesh.vertex(tri.v0)).z, 0.0f)
          << mesh.name;
    }
    EXPECT_TRUE(mesh.normals.empty());  // no NORMAL: flat, as the specification says
  }
}

// glTF's v runs down the image from its top edge; rtpro's, like OBJ's and PLY's, runs up from the
// bottom edge, which the texture lookup turns back: the loader flips v exactly once.
TEST(GltfLoader, TexcoordsHaveTheirVFlippedOnce) {
  GltfFile gltf;
  const int positions = gltf.floats(kTriangle, "VEC3");
  const int uvs = gltf.floats({0, 0, 1, 0.25f, 0.5f, 1}, "VEC2");
  const int mesh = gltf.mesh(positions);
  gltf.json["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = uvs;
  gltf.scene({gltf.node({{"mesh", mesh}})});
  const GltfAsset asset = load_gltf_file(gltf.write("uvs"));
  ASSERT_EQ(asset.meshes.size(), 1u);
  const std::vector<TexCoord>& loaded = asset.meshes[0].uvs;
  ASSERT_EQ(loaded.size(), 3u);
  EXPECT_EQ(loaded[0].u, 0.0f);
  EXPECT_EQ(loaded[0].v, 1.0f);
  EXPECT_EQ(loaded[1].u, 1.0f);
  EXPECT_EQ(loaded[1].v, 0.75f);
  EXPECT_EQ(loaded[2].u, 0.5f);
  EXPECT_EQ(loaded[2].v, 0.0f);
}

TEST(GltfLoader, LinesAreSkippedWithAWarningNamingThePrimitive) {
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"), -1, 1)}})});
  const GltfAsset asset = load_gltf_file(gltf.write("lines"));
  EXPECT_EQ(asset.stats.triangles, 0u);
  ASSERT_FALSE(asset.stats.warnings.empty());
  EXPECT_NE(asset.stats.warnings[0].find("meshes[0].primitives[0].mode: 1 (LINES) skipped"), std::string::npos);
}

TEST(GltfLoader, MaterialsAreThePrincipledModelWithAPhongAndMirrorViewForWhitted) {
  GltfFile gltf;
  gltf.json["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_clearcoat", "KHR_materials_sheen",
                                 "KHR_materials_specular", "KHR_materials_transmission"};
  gltf.json["materials"] = {
      {{"name", "chrome"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.9, 0.9, 0.9, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0}}}},
      {{"name", "clay"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.8, 0.4, 0.2, 0.5}},
         {"metallicFactor", 0},
         {"roughnessFactor", 1},
         {"baseColorTexture", {{"index", 0}}}}}},
      {{"name", "coated"},
       {"extensions",
        {{"KHR_materials_ior", {{"ior", 1.33}}},
         {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.7}, {"clearcoatRoughnessFactor", 0.2}}},
         {"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 0.25, 1.5}}, {"sheenRoughnessFactor", 0.3}}},
         {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {1, 0.5, 0.25}}}},
         {"KHR_materials_transmission", {{"transmissionFactor", 0.25}}}}}}};
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["images"] = {{{"uri", "textures/clay.png"}}};
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"))}})});
  const std::filesystem::path file = gltf.write("materials");
  std::filesystem::create_directories(file.parent_path() / "textures");
  std::filesystem::copy_file(test::source_dir() / "scenes" / "textures" / "uv_grid.png",
                             file.parent_path() / "textures" / "clay.png",
                             std::filesystem::copy_options::overwrite_existing);
  const GltfAsset asset = load_gltf_file(file);
  ASSERT_EQ(asset.materials.size(), 3u);
  const MaterialDesc& chrome = asset.materials[0];
  ASSERT_TRUE(std::holds_alternative<PrincipledParams>(chrome.params));
  EXPECT_EQ(chrome.color, Color(0.9f, 0.9f, 0.9f));
  EXPECT_EQ(std::get<PrincipledParams>(chrome.params).metalness, 1.0f);
  EXPECT_EQ(std::get<PrincipledParams>(chrome.params).roughness, 0.0f);
  const MaterialDesc& clay = asset.materials[1];
  EXPECT_EQ(clay.color, Color(0.8f, 0.4f, 0.2f));
  EXPECT_EQ(clay.opacity, 0.5f);
  EXPECT_EQ(clay.color_texture.filename(), "clay.png");
  EXPECT_EQ(clay.color_texture.parent_path().filename(), "textures");
  const PrincipledParams& coated = std::get<PrincipledParams>(asset.materials[2].params);
  EXPECT_FLOAT_EQ(coated.ior, 1.33f);
  EXPECT_FLOAT_EQ(coated.coat_weight, 0.7f);
  EXPECT_FLOAT_EQ(coated.coat_roughness, 0.2f);
  EXPECT_EQ(coated.fuzz_color, Color(0.5f, 0.25f, 1.0f));  // clamped to 1
  EXPECT_FLOAT_EQ(coated.fuzz_roughness, 0.3f);
  EXPECT_FLOAT_EQ(coated.specular_weight, 0.5f);
  EXPECT_EQ(coated.specular_color, Color(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(coated.transmission_weight, 0.25f);
  for (const std::string& warning : asset.stats.warnings) ADD_FAILURE() << warning;  // every extension is read

  // The Whitted view (FORMAT.md, "glTF files"): a polished metal mirrors, a rough one does not.
  const RenderScene scene = build_render_scene(parse_scene_file(file));
  const auto material = [&](const std::string& name) -> const Material& {
    for (std::size_t i = 0; i < scene.material_names.size(); ++i)
      if (scene.material_names[i].ends_with(":" + name)) return scene.materials[i];
    ADD_FAILURE() << "no material " << name;
    return scene.materials[0];
  };
  EXPECT_NEAR(material("chrome").whitted.reflectivity, 0.9f, 1e-6f);
  EXPECT_NEAR(std::get<Color>(material("chrome").whitted.color).x, 0.09f, 1e-6f);
  EXPECT_EQ(material("chrome").whitted.shininess, 10000.0f);
  // The mirror darkens the Whitted colour alone: the model's base colour is the file's.
  EXPECT_EQ(std::get<Color>(material("chrome").base_color), Color(0.9f, 0.9f, 0.9f));
  EXPECT_EQ(material("clay").whitted.reflectivity, 0.0f);  // rough: no mirror
  EXPECT_EQ(std::get<ImageTexture>(material("clay").whitted.color).tint, Color(0.8f, 0.4f, 0.2f));
  EXPECT_EQ(std::get<ImageTexture>(material("clay").base_color).tint, Color(0.8f, 0.4f, 0.2f));
  EXPECT_EQ(material("clay").whitted.shininess, 1.0f);
  EXPECT_EQ(material("clay").whitted.specular, 0.04f * 1.5f / kFullHighlightNs);
  EXPECT_TRUE(std::holds_alternative<PrincipledSurface>(material("clay").model));
}

// Hostile and broken files: each refused with the JSON path of the element at fault.
TEST(GltfHostile, OutOfRangeIndicesNameTheirAccessor) {
  GltfFile gltf;
  const int positions = gltf.floats(kTriangle, "VEC3");
  gltf.scene({gltf.node({{"mesh", gltf.mesh(positions, gltf.indices({0, 1, 7}))}})});
  const std::string error = error_of(gltf.write("indices"));
  EXPECT_NE(error.find("accessors[1]: index 7 (element 2) is out of range"), std::string::npos) << error;
}

TEST(GltfHostile, InfinitiesAndHugeCoordinatesAreRefused) {
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats({0, 0, 0, 1, INFINITY, 0, 0, 1, 0}, "VEC3"))}})});
  EXPECT_NE(error_of(gltf.write("infinite")).find("accessors[0]: element 1 is not a finite number"), std::string::npos);
  GltfFile huge;
  huge.scene({huge.node({{"mesh", huge.mesh(huge.floats({0, 0, 0, 1e30f, 0, 0, 0, 1, 0}, "VEC3"))}})});
  EXPECT_NE(error_of(huge.write("huge")).find("beyond the supported magnitude"), std::string::npos);
  GltfFile nan;  // a NaN beside a larger coordinate must not hide behind it
  nan.scene({nan.node({{"mesh", nan.mesh(nan.floats({0, 0, 0, 1, 0, 0, 5, NAN, 0}, "VEC3"))}})});
  EXPECT_NE(error_of(nan.write("nan")).find("accessors[0]: element 2 is not a finite number"), std::string::npos);
}

TEST(GltfHostile, AccessorsMustFitTheirBufferView) {
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"))}})});
  gltf.json["accessors"][0]["count"] = 1000000000;  // a 4-byte file claiming 12 GB
  EXPECT_NE(error_of(gltf.write("count"))
                .find("accessors[0].count: 1000000000 elements from byte 0 do not fit in bufferViews[0]"),
            std::string::npos);
  gltf.json["accessors"][0]["count"] = 3;
  gltf.json["accessors"][0]["bufferView"] = 9;
  EXPECT_NE(error_of(gltf.write("view")).find("accessors[0].bufferView: bufferView 9 does not exist"),
            std::string::npos);
  gltf.json["accessors"][0]["bufferView"] = 0;
  gltf.json["bufferViews"][0]["byteLength"] = 400;
  EXPECT_NE(error_of(gltf.write("length")).find("bufferViews[0].byteLength"), std::string::npos);
  gltf.json["bufferViews"][0]["byteLength"] = 36;
  gltf.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 4;
  EXPECT_NE(
      error_of(gltf.write("reference")).find("meshes[0].primitives[0].attributes.POSITION: accessor 4 does not exist"),
      std::string::npos);
}

TEST(GltfHostile, EmptyAccessorsAreReadWithoutTouchingTheirMissingStorage) {
  // A fuzz finding: an accessor of count 0 reached memcpy with a null destination (UBSan).
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"), gltf.indices({0, 1, 2}))}})});
  gltf.json["accessors"][0]["count"] = 0;
  gltf.json["accessors"][1]["count"] = 0;
  const std::filesystem::path file = gltf.write("empty_accessors");
  const GltfAsset asset = load_gltf_file(file);
  EXPECT_EQ(asset.stats.triangles, 0u);
  for (const TriangleMesh& mesh : asset.meshes) {
    EXPECT_TRUE(mesh.vertices.empty());
    EXPECT_TRUE(mesh.triangles.empty());
  }
}

TEST(GltfHostile, CyclesSharedChildrenAndDeepTreesAreRefused) {
  GltfFile cycle;
  const int mesh = cycle.mesh(cycle.floats(kTriangle, "VEC3"));
  cycle.node({{"children", {1}}, {"mesh", mesh}});
  cycle.node({{"children", {0}}});
  cycle.scene({0});
  EXPECT_NE(error_of(cycle.write("cycle")).find("is its own ancestor (a cycle"), std::string::npos);

  GltfFile shared;
  const int leaf = shared.node({{"mesh", shared.mesh(shared.floats(kTriangle, "VEC3"))}});
  shared.scene({shared.node({{"children", {leaf}}}), shared.node({{"children", {leaf}}})});
  EXPECT_NE(error_of(shared.write("shared")).find("nodes[2].children[0]: node 0 already has a parent"),
            std::string::npos);

  GltfFile deep;  // a chain of 2,000 nodes: too deep, refused without recursion
  deep.mesh(deep.floats(kTriangle, "VEC3"));
  for (int i = 0; i < 2000; ++i)
    deep.node(i + 1 < 2000 ? nlohmann::json{{"children", {i + 1}}} : nlohmann::json{{"mesh", 0}});
  deep.scene({0});
  EXPECT_NE(error_of(deep.write("deep")).find("nodes nest deeper than 1024 levels"), std::string::npos);
}

TEST(GltfHostile, MissingOrEscapingBuffersNameTheBuffer) {
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"))}})});
  const auto file = gltf.write("missing");
  std::filesystem::remove(file.parent_path() / "missing.bin");
  EXPECT_NE(error_of(file).find("buffers[0].uri: 'missing.bin' not found"), std::string::npos);
  // A buffer outside the glTF's folder, by path or by symbolic link, is not read.
  const auto outside = gltf.write("sub/../outside");
  nlohmann::json escaping = nlohmann::json::parse(std::ifstream(outside));
  escaping["buffers"][0]["uri"] = "../outside.bin";
  const auto inner = test::write_file("sub/escape.gltf", escaping.dump());
  EXPECT_NE(error_of(inner).find("buffers[0].uri: '../outside.bin' leads outside the glTF's folder"),
            std::string::npos);
  std::filesystem::remove(inner.parent_path() / "link.bin");  // the scratch folder outlives a run
  std::filesystem::create_symlink(outside.parent_path() / "outside.bin", inner.parent_path() / "link.bin");
  escaping["buffers"][0]["uri"] = "link.bin";
  EXPECT_NE(error_of(test::write_file("sub/link.gltf", escaping.dump())).find("leads outside"), std::string::npos);
}

TEST(GltfHostile, DeepJsonAndForeignFilesAreRefusedBeforeParsing) {
  std::string deep = R"({"asset": {"version": "2.0"}, "extras": )";
  for (int i = 0; i < 100000; ++i) deep += '[';
  EXPECT_NE(error_of(test::write_file("deep.gltf", deep)).find("nests deeper than 128 levels"), std::string::npos);
  EXPECT_NE(error_of(test::write_file("old.gltf", R"({"asset": {"version": "1.0"}})")).find("glTF 2.0 files only"),
            std::string::npos);
  EXPECT_NE(error_of(test::write_file(
                         "draco.gltf",
                         R"({"asset": {"version": "2.0"}, "extensionsRequired": ["KHR_draco_mesh_compression"]})"))
                .find("KHR_draco_mesh_compression"),
            std::string::npos);
  EXPECT_FALSE(error_of(test::write_file("text.glb", "glTF\x01\0\0\0garbage")).empty());
}

// tinygltf reads a version that is not a string as missing: the message says what it is instead.
TEST(GltfHostile, AVersionThatIsNotAStringIsNamedAsWhatItIs) {
  const auto version = [](const std::string& name, const std::string& value) {
    return error_of(test::write_file(name + ".gltf", R"({"asset": {"version": )" + value + "}}"));
  };
  EXPECT_EQ(version("two", "2.0"), "asset.version must be a string, got a number (2.0); a glTF 2.0 file says \"2.0\"");
  EXPECT_EQ(version("one", "1"),
            "asset.version: 1 (a number, as glTF 1.0 exporters wrote it): rtpro reads glTF 2.0 "
            "files only");
  EXPECT_EQ(version("list", "[2]"), "asset.version must be a string, got an array; a glTF 2.0 file says \"2.0\"");
  EXPECT_NE(error_of(test::write_file("none.gltf", R"({"asset": {}})")).find("asset.version: missing"),
            std::string::npos);
  EXPECT_FALSE(error_of(test::write_file("broken.gltf", "{\"asset\": ")).empty());
}

}  // namespace gltf_loader_test
}  // namespace rtpro
