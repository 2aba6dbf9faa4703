// OBJ materials from MTL libraries, and the lenient and hardened edges of OBJ reading
// (obj_materials.h, mtl_parser.h).
#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"
#include "ascii_scan.h"
#include "mtl_parser.h"
#include "obj_fixtures.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rtpro {
namespace obj_materials_test {

using test::has_warning_containing;
using test::mesh_load_error;
using test::write_file;

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

MaterialDesc only_material(const std::string& mtl) {
  const MaterialLibrary library = parse_mtl_file(write_file("one.mtl", mtl));
  EXPECT_EQ(library.materials.size(), 1u);
  return library.materials.empty() ? MaterialDesc{} : library.materials.front();
}

// An MTL material is the Phong kind: its highlight is there.
const PhongParams& phong(const MaterialDesc& m) { return std::get<PhongParams>(m.params); }

TEST(MtlMapping, KsNsAndTheirDefaults) {
  const MaterialDesc m = only_material("newmtl m\nKd 0.5 0.25 1\nKs 0.3 0.6 0.9\nNs 50\n");
  EXPECT_EQ(m.color, Color(0.5f, 0.25f, 1.0f));
  EXPECT_FLOAT_EQ(phong(m).specular, 0.6f);
  EXPECT_FLOAT_EQ(phong(m).shininess, 50.0f);
  const MaterialDesc plain = only_material("newmtl m\nKd 1 1 1\n");
  EXPECT_EQ(phong(plain).specular, PhongParams{}.specular);
  EXPECT_EQ(phong(plain).shininess, PhongParams{}.shininess);
}

TEST(MtlMapping, NsZeroWithStrongKsGivesNoHighlightInsteadOfAWhiteDisc) {
  // 3ds Max writes this; a Phong exponent of 0 would add Ks everywhere the light reaches.
  const MaterialDesc zero = only_material("newmtl m\nKs 0.9 0.9 0.9\nNs 0\n");
  EXPECT_EQ(phong(zero).specular, 0.0f);
  EXPECT_GE(phong(zero).shininess, 1.0f);
  const MaterialDesc two = only_material("newmtl m\nKs 0.9 0.9 0.9\nNs 2\n");
  EXPECT_NEAR(phong(two).specular, 0.9f * 2.0f / kFullHighlightNs, 1e-6f);
  const MaterialDesc eight = only_material("newmtl m\nKs 0.9 0.9 0.9\nNs 8\n");
  EXPECT_FLOAT_EQ(phong(eight).specular, 0.9f);  // from kFullHighlightNs on, untouched
}

TEST(MtlMapping, DissolveTransparencyAndDiffuseTextureAreKept) {
  write_file("tex/maps/wood.png", "present");
  const std::filesystem::path file = write_file("tex/lib.mtl",
                                                "newmtl a\nd 0.25\nmap_Kd -s 1 1 1 maps/wood.png\n"
                                                "newmtl b\nTr 0.75\nmap_Kd /etc/secret.png\n");
  const MaterialLibrary library = parse_mtl_file(file);
  ASSERT_EQ(library.materials.size(), 2u);
  EXPECT_FLOAT_EQ(library.materials[0].opacity, 0.25f);
  EXPECT_EQ(library.materials[0].color_texture, file.parent_path() / "maps" / "wood.png");
  EXPECT_FLOAT_EQ(library.materials[1].opacity, 0.25f);
  EXPECT_TRUE(library.materials[1].color_texture.empty());
  bool warned_transparent = false, warned_outside = false;
  for (const std::string& w : library.warnings) {
    warned_transparent |= w.find("partly transparent") != std::string::npos;
    warned_outside |= w.find("not inside") != std::string::npos;
  }
  EXPECT_TRUE(warned_transparent);
  EXPECT_TRUE(warned_outside);
  EXPECT_THROW(parse_mtl_file(write_file("bad.mtl", "newmtl a\nd 2\n")), InputError);
}

// assimp-testmodels' spider.mtl says `map_Kd .\SpiderTex.jpg` (written on Windows): rtpro
// refused the scene when it opened the texture; `\` is a folder separator as in Blender and assimp.
TEST(MtlMapping, BackslashesInATexturePathSeparateFolders) {
  const std::filesystem::path texture = write_file("win/maps/SpiderTex.jpg", "present");
  const std::filesystem::path file = write_file("win/lib.mtl", "newmtl a\nmap_Kd .\\maps\\SpiderTex.jpg\n");
  const MaterialLibrary library = parse_mtl_file(file);
  ASSERT_EQ(library.materials.size(), 1u);
  EXPECT_EQ(library.materials[0].color_texture, file.parent_path() / "maps" / "SpiderTex.jpg");
  EXPECT_TRUE(std::filesystem::equivalent(library.materials[0].color_texture, texture));
}

TEST(MtlMapping, ATextureThroughASymbolicLinkOutsideTheFolderIsRefusedAtItsLine) {
  const std::filesystem::path secret = write_file("secret.png", "not for the MTL");
  const std::filesystem::path file = write_file("lib/escape.mtl", "newmtl a\nKd 1 1 1\nmap_Kd link.png\n");
  std::filesystem::remove(file.parent_path() / "link.png");
  std::filesystem::create_symlink(secret, file.parent_path() / "link.png");
  try {
    parse_mtl_file(file);
    FAIL() << "a texture outside the folder was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(e.message().find("texture 'link.png' leads outside the material library's folder"), std::string::npos)
        << e.message();
  }
}

TEST(ObjLenience, BareUsemtlAndNewmtlMeanTheDefaultMaterial) {
  write_file("blender.mtl", "newmtl \nKd 0.1 0.1 0.1\nnewmtl red\nKd 1 0 0\n");
  const LoadedMesh loaded = load_mesh_file(write_file(
      "blender.obj", std::string("mtllib blender.mtl\n") + kTriangle + "usemtl red\nf 1 2 3\nusemtl \nf 1 3 2\n"));
  ASSERT_EQ(loaded.materials.size(), 2u);
  EXPECT_EQ(loaded.materials[0].name, "red");
  EXPECT_EQ(loaded.materials[1].name, "default");
  EXPECT_EQ(loaded.materials[1].color, MaterialDesc{}.color);
  EXPECT_EQ(loaded.mesh.triangle_materials, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "usemtl without a material name"));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "newmtl without a name"));
}

TEST(ObjLenience, Utf16FilesAreRefusedWithoutPrintingNulBytes) {
  std::string utf16 = "\xFF\xFE";
  for (const char c : std::string(kTriangle) + "f 1 2 3\n") {
    utf16 += c;
    utf16 += '\0';
  }
  const InputError e = mesh_load_error(write_file("wide.obj", utf16));
  EXPECT_NE(e.message().find("UTF-16 (little-endian)"), std::string::npos) << e.message();
  EXPECT_EQ(std::string(e.what()).find('\0'), std::string::npos);
  // Without a byte order mark (assimp's box_UTF16BE.obj has none).
  std::string big_endian;
  for (const char c : std::string(kTriangle)) {
    big_endian += '\0';
    big_endian += c;
  }
  EXPECT_NE(mesh_load_error(write_file("wide_be.obj", big_endian)).message().find("UTF-16 (big-endian)"),
            std::string::npos);
  // A UTF-8 byte order mark is skipped, not read as part of the first keyword.
  EXPECT_EQ(load_mesh_file(write_file("bom.obj", "\xEF\xBB\xBF" + std::string(kTriangle) + "f 1 2 3\n"))
                .mesh.triangles.size(),
            1u);
}

TEST(ObjHardening, ManyDistinctUnknownKeywordsGiveAFewWarningLines) {
  std::string text = kTriangle;
  for (int i = 0; i < 20000; ++i) text += "kw" + std::to_string(i) + " 1\n";
  text += "f 1 2 3\n";
  const LoadedMesh loaded = load_mesh_file(write_file("keywords.obj", text));
  EXPECT_EQ(loaded.mesh.triangles.size(), 1u);
  ASSERT_EQ(loaded.stats.warnings.size(), 9u);
  EXPECT_NE(loaded.stats.warnings[0].find(":4: ignored 'kw0' statements (1 in total)"), std::string::npos);
  EXPECT_NE(loaded.stats.warnings[8].find("19992 more statements with 19992 other unknown keywords"), std::string::npos)
      << loaded.stats.warnings[8];
}

TEST(ObjHardening, HugeOrBinaryTokensAreCutAndEscapedInMessages) {
  const std::string token(10'000'000, 'x');
  const LoadedMesh loaded =
      load_mesh_file(write_file("token.obj", std::string(kTriangle) + token + "\n\x01\x1b[31m 2\nf 1 2 3\n"));
  ASSERT_EQ(loaded.stats.warnings.size(), 2u);
  EXPECT_EQ(loaded.stats.warnings[0].find(std::string(ascii::kMaxQuotedBytes + 1, 'x')), std::string::npos);
  EXPECT_NE(loaded.stats.warnings[0].find("(cut: 10000000 bytes)"), std::string::npos);
  EXPECT_NE(loaded.stats.warnings[1].find("'\\x01\\x1b[31m'"), std::string::npos) << loaded.stats.warnings[1];
  const InputError e = mesh_load_error(write_file("bad_number.obj", "v 0 0 " + token + "\n"));
  EXPECT_EQ(e.message().find(std::string(ascii::kMaxQuotedBytes + 1, 'x')), std::string::npos);
}

TEST(ObjHardening, MaterialLibraryBehindASymlinkMustStayInsideTheFolder) {
  const std::filesystem::path outside = write_file("outside/secret.mtl", "newmtl s\nKd 1 0 0\n");
  const std::filesystem::path model = write_file("model/keep", "").parent_path();
  for (const char* link : {"linked.mtl", "linked_dir", "inside.mtl"})
    std::filesystem::remove(model / link);  // from an earlier run
  std::filesystem::create_symlink(outside, model / "linked.mtl");
  std::filesystem::create_directory_symlink(outside.parent_path(), model / "linked_dir");
  const InputError file_link =
      mesh_load_error(write_file("model/a.obj", std::string("mtllib linked.mtl\n") + kTriangle));
  EXPECT_NE(file_link.message().find("outside the OBJ's folder"), std::string::npos) << file_link.message();
  const InputError dir_link =
      mesh_load_error(write_file("model/b.obj", std::string("mtllib linked_dir/secret.mtl\n") + kTriangle));
  EXPECT_NE(dir_link.message().find("outside the OBJ's folder"), std::string::npos) << dir_link.message();
  // A link that stays inside is fine.
  write_file("model/real.mtl", "newmtl r\n");
  std::filesystem::create_symlink(model / "real.mtl", model / "inside.mtl");
  EXPECT_NO_THROW(load_mesh_file(write_file("model/c.obj", std::string("mtllib inside.mtl\n") + kTriangle)));
}

TEST(ObjLoader, MaterialsComeFromTheLibraryPerTriangle) {
  write_file("two.mtl",
             "# colours\nnewmtl red\nKd 1 0 0\nKs 0.3 0.6 0.9\nNs 50\nillum 2\n"
             "newmtl grey\nKd 0.25\nKa 0 0 0\n");
  const LoadedMesh loaded = load_mesh_file(write_file("two.obj", R"(mtllib two.mtl
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
usemtl grey
f 1 2 3
usemtl red
f 2 4 3
f 1 2 4
usemtl grey
f 1 4 3
)"));
  ASSERT_EQ(loaded.materials.size(), 2u);
  EXPECT_EQ(loaded.materials[0].name, "grey");
  EXPECT_EQ(loaded.materials[0].color, Color(0.25f, 0.25f, 0.25f));
  EXPECT_EQ(loaded.materials[1].name, "red");
  EXPECT_EQ(loaded.materials[1].color, Color(1, 0, 0));
  EXPECT_NEAR(std::get<PhongParams>(loaded.materials[1].params).specular, 0.6f, 1e-6f);
  EXPECT_EQ(std::get<PhongParams>(loaded.materials[1].params).shininess, 50.0f);
  EXPECT_EQ(loaded.mesh.triangle_materials, (std::vector<std::uint32_t>{0, 1, 1, 0}));
  EXPECT_EQ(loaded.stats.materials, 2u);
  // Unused MTL statements are reported once per keyword, with their count.
  EXPECT_TRUE(has_warning_containing(loaded.stats, "two.mtl:6: ignored 'illum' (1 in total)"));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "two.mtl:9: ignored 'Ka' (1 in total)"));
}

TEST(ObjLoader, OneMaterialNeedsNoPerTriangleList) {
  write_file("one.mtl", "newmtl blue\nKd 0 0 1\n");
  const LoadedMesh loaded = load_mesh_file(write_file("one.obj",
                                                      "mtllib one.mtl\nusemtl blue\n"
                                                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_EQ(loaded.materials.size(), 1u);
  EXPECT_EQ(loaded.materials[0].color, Color(0, 0, 1));
  EXPECT_EQ(loaded.mesh.material, 0u);
  EXPECT_TRUE(loaded.mesh.triangle_materials.empty());
}

TEST(ObjLoader, FacesBeforeAnyUsemtlShareADefaultMaterial) {
  write_file("one.mtl", "newmtl blue\nKd 0 0 1\n");
  const LoadedMesh loaded = load_mesh_file(write_file("mixed.obj",
                                                      "mtllib one.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                      "f 1 2 3\nusemtl blue\nf 1 3 2\n"));
  ASSERT_EQ(loaded.materials.size(), 2u);
  EXPECT_EQ(loaded.materials[0].name, "default");
  EXPECT_EQ(loaded.mesh.triangle_materials, (std::vector<std::uint32_t>{0, 1}));
}

TEST(ObjLoader, MissingMaterialLibraryIsAWarningAndMaterialsFallBack) {
  const LoadedMesh loaded = load_mesh_file(write_file("nolib.obj",
                                                      "mtllib absent.mtl\nusemtl shiny\n"
                                                      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "nolib.obj:1: material library 'absent.mtl' not found"));
  EXPECT_TRUE(has_warning_containing(loaded.stats, "nolib.obj:2: material 'shiny' is not defined"));
  ASSERT_EQ(loaded.materials.size(), 1u);
  EXPECT_EQ(loaded.materials[0].name, "shiny");
  EXPECT_EQ(loaded.materials[0].color, MaterialDesc{}.color);
}

TEST(ObjLoader, MaterialLibrariesOutsideTheObjFolderAreRejected) {
  write_file("x.mtl", "newmtl x\n");
  const InputError up = mesh_load_error(write_file("sub/escape.obj", "v 0 0 0\nmtllib ../x.mtl\n"));
  EXPECT_EQ(up.where().line, 2);
  EXPECT_NE(up.message().find("leaves the OBJ's folder"), std::string::npos) << up.message();
  const InputError sneaky = mesh_load_error(write_file("sub/sneaky.obj", "mtllib a/../../x.mtl\n"));
  EXPECT_NE(sneaky.message().find("leaves the OBJ's folder"), std::string::npos) << sneaky.message();
  const InputError absolute = mesh_load_error(write_file("absolute.obj", "mtllib /etc/passwd\n"));
  EXPECT_NE(absolute.message().find("must be relative"), std::string::npos) << absolute.message();
  // Going down and back up inside the folder is fine.
  write_file("sub/inner/y.mtl", "newmtl y\n");
  EXPECT_NO_THROW(load_mesh_file(write_file("sub/fine.obj", "mtllib inner/../inner/y.mtl\n")));
}

TEST(ObjLoader, MalformedMaterialLibraryNamesItsOwnLine) {
  write_file("bad.mtl", "newmtl a\nKd 1 abc 0\n");
  const InputError e = mesh_load_error(write_file("uses_bad.obj", "mtllib bad.mtl\n"));
  EXPECT_NE(std::string(e.what()).find("bad.mtl:2:6"), std::string::npos) << e.what();
  write_file("early.mtl", "Kd 1 1 1\n");
  EXPECT_NE(
      std::string(mesh_load_error(write_file("uses_early.obj", "mtllib early.mtl\n")).what()).find("before any newmtl"),
      std::string::npos);
}

}  // namespace obj_materials_test
}  // namespace rtpro
