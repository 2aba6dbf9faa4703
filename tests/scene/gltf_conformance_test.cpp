// glTF files that tinygltf reads without a word but rtpro would have rendered wrong (issue 28):
// required extensions it lacks, mistyped properties tinygltf skips, truncated triangle arrays,
// texture coordinate sets and KHR_texture_transform, images reached through symbolic links.
#include "rtpro/core/error.h"
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_load_error.h"
#include "gltf_test_files.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace rtpro {
namespace gltf_conformance_test {

using test::GltfFile;

using test::kTriangle;
const auto error_of = test::gltf_error_of;

bool warned(const GltfAsset& asset, const std::string& text) {
  for (const std::string& w : asset.stats.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

// One textured triangle: TEXCOORD_0 (0,0) (1,0) (0,1) and TEXCOORD_1 (0.5,0.5) everywhere, one
// material whose base colour texture is `texture_info`.
GltfFile textured_triangle(const nlohmann::json& texture_info) {
  GltfFile gltf;
  const int mesh = gltf.mesh(gltf.floats(kTriangle, "VEC3"));
  gltf.json["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_0"] = gltf.floats({0, 0, 1, 0, 0, 1}, "VEC2");
  gltf.json["meshes"][mesh]["primitives"][0]["attributes"]["TEXCOORD_1"] =
      gltf.floats({0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}, "VEC2");
  gltf.json["meshes"][mesh]["primitives"][0]["material"] = 0;
  gltf.json["images"] = {{{"uri", "tex.png"}}};
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", texture_info}}}}};
  gltf.scene({gltf.node({{"mesh", mesh}})});
  return gltf;
}

GltfFile plain_triangle() {
  GltfFile gltf;
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(kTriangle, "VEC3"))}})});
  return gltf;
}

TEST(GltfExtensions, ARequiredExtensionRtproLacksRefusesTheFileByName) {
  GltfFile gltf = plain_triangle();
  gltf.json["extensionsUsed"] = {"KHR_materials_unlit"};
  gltf.json["extensionsRequired"] = {"KHR_materials_unlit"};
  EXPECT_NE(error_of(gltf.write("unlit"))
                .find("extensionsRequired[0]: the file needs 'KHR_materials_unlit', which rtpro does not support"),
            std::string::npos);
  gltf.json["extensionsRequired"] = {"KHR_lights_punctual", "EXT_\x1b[31mevil"};
  EXPECT_NE(error_of(gltf.write("evil")).find("extensionsRequired[1]: the file needs 'EXT_\\x1b[31mevil'"),
            std::string::npos)
      << "control characters from the file reach the terminal";
  gltf.json["extensionsRequired"] = {"KHR_texture_transform"};  // read by rtpro: fine
  EXPECT_NO_THROW(load_gltf_file(gltf.write("supported")));
}

TEST(GltfExtensions, AnUsedExtensionRtproLacksIsAWarningByName) {
  GltfFile gltf = plain_triangle();
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_iridescence"};
  const GltfAsset asset = load_gltf_file(gltf.write("used"));
  EXPECT_TRUE(warned(asset, "extensionsUsed[1]: 'KHR_materials_iridescence' is not supported"));
  EXPECT_FALSE(warned(asset, "KHR_lights_punctual"));
}

TEST(GltfJsonTypes, PropertiesTinygltfSkipsWhenMistypedAreRefusedAtTheirPath) {
  {  // wrongTypes/badArray: primitives an object, the mesh rendered empty with exit 0
    GltfFile gltf = plain_triangle();
    gltf.json["meshes"][0]["primitives"] = {{"not an array", gltf.json["meshes"][0]["primitives"][0]}};
    EXPECT_NE(error_of(gltf.write("bad_array")).find("meshes[0].primitives: an array expected, found an object"),
              std::string::npos);
  }
  {  // wrongTypes/badObject: pbrMetallicRoughness an array, the texture lost
    GltfFile gltf = textured_triangle({{"index", 0}});
    gltf.json["materials"][0]["pbrMetallicRoughness"] = {"not an object"};
    EXPECT_NE(error_of(gltf.write("bad_object"))
                  .find("materials[0].pbrMetallicRoughness: an object expected, found an array"),
              std::string::npos);
  }
  {  // wrongTypes/badUint: a texture index of -1, the texture lost
    GltfFile gltf = textured_triangle({{"index", -1}});
    EXPECT_NE(
        error_of(gltf.write("bad_uint"))
            .find(
                "materials[0].pbrMetallicRoughness.baseColorTexture.index: a non-negative integer expected, found -1"),
        std::string::npos);
  }
  {  // wrongTypes/badExtension and badNumber
    GltfFile gltf = textured_triangle({{"index", 0}, {"extensions", {{"KHR_texture_transform", "Not an object"}}}});
    EXPECT_NE(error_of(gltf.write("bad_extension"))
                  .find("baseColorTexture.extensions.KHR_texture_transform: an object expected, found the string 'Not "
                        "an object'"),
              std::string::npos);
    GltfFile number = textured_triangle({{"index", 0}});
    number.json["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", "not a number"}};
    EXPECT_NE(error_of(number.write("bad_number")).find("materials[0].normalTexture.scale: a number expected"),
              std::string::npos);
  }
  {  // an attribute's accessor as a string
    GltfFile gltf = plain_triangle();
    gltf.json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = "0";
    EXPECT_NE(error_of(gltf.write("bad_attribute"))
                  .find("meshes[0].primitives[0].attributes.POSITION: a non-negative integer expected"),
              std::string::npos);
  }
}

// "light -2 does not exist": a negative index is a type error at its JSON path.
TEST(GltfJsonTypes, ANegativeLightIndexIsRefusedAtItsPath) {
  GltfFile gltf = plain_triangle();
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}}};
  gltf.json["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", -2}}}}}});
  gltf.json["scenes"][0]["nodes"] = {0, 1};
  EXPECT_NE(error_of(gltf.write("negative_light"))
                .find("nodes[1].extensions.KHR_lights_punctual.light: a non-negative integer expected, found -2"),
            std::string::npos);
}

TEST(GltfMesh, TruncatedTriangleArraysAreRefused) {
  GltfFile indexed;
  indexed.scene(
      {indexed.node({{"mesh", indexed.mesh(indexed.floats(kTriangle, "VEC3"), indexed.indices({0, 1, 2, 0}))}})});
  EXPECT_NE(error_of(indexed.write("four_indices"))
                .find("meshes[0].primitives[0].indices: 4 corners for TRIANGLES, not a multiple of 3"),
            std::string::npos);
  GltfFile unindexed;
  unindexed.scene(
      {unindexed.node({{"mesh", unindexed.mesh(unindexed.floats({1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, "VEC3"))}})});
  EXPECT_NE(error_of(unindexed.write("four_vertices"))
                .find("meshes[0].primitives[0].attributes.POSITION: 4 corners for TRIANGLES"),
            std::string::npos);
  GltfFile fan;
  fan.scene({fan.node({{"mesh", fan.mesh(fan.floats(kTriangle, "VEC3"), fan.indices({0, 1}), 6)}})});
  EXPECT_NE(error_of(fan.write("short_fan")).find("2 corners for a strip or fan, which needs at least 3"),
            std::string::npos);
}

void expect_uv(const TexCoord& uv, float u, float v) {
  EXPECT_NEAR(uv.u, u, 1e-6f);
  EXPECT_NEAR(uv.v, v, 1e-6f);
}

TEST(GltfTextureTransform, TheTransformIsAppliedToTheTextureCoordinatesInGltfSpace) {
  // offset (0.5, 0.25), scale (2, 3), rotation π/2: u' = 3 v + 0.5, v' = -2 u + 0.25 (glTF's v,
  // down); rtpro keeps v up, 1 - v'.
  const GltfAsset asset = load_gltf_file(
      textured_triangle(
          {{"index", 0},
           {"extensions",
            {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"scale", {2, 3}}, {"rotation", M_PI / 2}}}}}})
          .write("transformed"));
  ASSERT_EQ(asset.meshes.size(), 1u);
  const std::vector<TexCoord>& uvs = asset.meshes[0].uvs;
  ASSERT_EQ(uvs.size(), 3u);
  expect_uv(uvs[0], 0.5f, 0.75f);  // (0, 0)
  expect_uv(uvs[1], 0.5f, 2.75f);  // (1, 0): v' = -1.75
  expect_uv(uvs[2], 3.5f, 0.75f);  // (0, 1)
}

TEST(GltfTextureTransform, TexCoordOneReadsTheSecondSetAndTheExtensionMayOverrideIt) {
  const GltfAsset second = load_gltf_file(textured_triangle({{"index", 0}, {"texCoord", 1}}).write("second_set"));
  ASSERT_EQ(second.meshes[0].uvs.size(), 3u);
  for (const TexCoord& uv : second.meshes[0].uvs) expect_uv(uv, 0.5f, 0.5f);
  const GltfAsset overridden = load_gltf_file(
      textured_triangle({{"index", 0}, {"texCoord", 1}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 0}}}}}})
          .write("overridden"));
  expect_uv(overridden.meshes[0].uvs[1], 1.0f, 1.0f);
}

TEST(GltfTextureTransform, SlotsThatDisagreeWithTheBaseColourAreAWarning) {
  GltfFile gltf = textured_triangle({{"index", 0}});
  gltf.json["materials"][0]["normalTexture"] = {{"index", 0}, {"texCoord", 1}};
  const GltfAsset asset = load_gltf_file(gltf.write("disagree"));
  EXPECT_TRUE(warned(asset, "materials[0].normalTexture uses other texture coordinates"));
  expect_uv(asset.meshes[0].uvs[1], 1.0f, 1.0f);  // the base colour's TEXCOORD_0
}

// assimp's texcoord_crash.gltf: a textured material on a primitive that has TEXCOORD_1 but not
// the TEXCOORD_0 its textures read rendered the texture's corner without a word.
TEST(GltfTextureTransform, APrimitiveLackingTheSetItsTexturesReadIsAWarningWithItsVertexCount) {
  GltfFile gltf = textured_triangle({{"index", 0}});
  gltf.json["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
  const GltfAsset asset = load_gltf_file(gltf.write("second_only"));
  EXPECT_TRUE(warned(asset,
                     "second_only.gltf: meshes[0].primitives[0]: its material's textures read TEXCOORD_0, "
                     "which the primitive lacks; its 3 vertices show the textures' corner (0, 0)"));
  const GltfAsset untextured = load_gltf_file(plain_triangle().write("untextured"));
  EXPECT_TRUE(untextured.stats.warnings.empty());
}

TEST(GltfHostile, AnImageThroughASymbolicLinkOutsideTheFolderIsRefused) {
  const auto outside = test::write_file("secret.png", "not for the glTF");
  GltfFile gltf = textured_triangle({{"index", 0}});
  gltf.json["images"][0]["uri"] = "link.png";
  const auto file = gltf.write("inner/linked", /*embed=*/true);
  std::filesystem::remove(file.parent_path() / "link.png");
  std::filesystem::create_symlink(outside, file.parent_path() / "link.png");
  EXPECT_NE(error_of(file).find("images[0].uri: 'link.png' leads outside the glTF's folder (through a symbolic link)"),
            std::string::npos);
}

}  // namespace gltf_conformance_test
}  // namespace rtpro
