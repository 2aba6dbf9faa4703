// Image textures in scene descriptions: `color: {texture: ...}` and MTL map_Kd, their colour
// spaces and wrap modes, and missing files refused where they are named (an MTL's: a warning).
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/mesh_loader.h"
#include "rtpro/scene/scene_parser.h"
#include "test_paths.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace image_texture_test {

std::string scene_with(const std::string& material) {
  return "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n  m: " + material +
         "\nworld:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: m}\n";
}

TEST(ImageTexture, SceneTextureIsRegisteredOnceWithItsColourSpaceAndWrap) {
  const auto image = test::write_file("maps/wood.png", "not read until rendering");
  const auto scene_file = test::write_file("s.yaml", "");
  const std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nmaterials:\n"
      "  a: {color: {texture: maps/wood.png}}\n"
      "  b: {color: {texture: maps/wood.png, wrap: clamp, tint: [1, 0.5, 0.5]}}\n"
      "  c: {color: {texture: maps/wood.png, colorspace: linear}}\n"
      "world:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: a}\n";
  const RenderScene scene = build_render_scene(parse_scene_text(text, scene_file));
  ASSERT_EQ(scene.textures.size(), 2u);  // a and b share the file and colour space
  EXPECT_EQ(scene.textures[0].file, image);
  EXPECT_EQ(scene.textures[0].colorspace, "sRGB - Texture");
  EXPECT_EQ(scene.textures[1].colorspace, "Linear Rec.709 (sRGB)");
  const auto& a = std::get<ImageTexture>(scene.materials[1].base_color);
  const auto& b = std::get<ImageTexture>(scene.materials[2].base_color);
  EXPECT_EQ(a.image, 0u);
  EXPECT_EQ(a.sampling, TextureSampling{});
  EXPECT_EQ(a.tint.x, 1.0f);
  EXPECT_EQ(b.image, 0u);
  EXPECT_EQ(b.sampling, (TextureSampling{TextureWrap::kClamp, TextureWrap::kClamp, TextureFilter::kLinear}));
  EXPECT_EQ(b.tint.y, 0.5f);
}

// `wrap:` takes one mode or one per axis ([across, down]); `filter:` nearest or linear.
TEST(ImageTexture, WrapPerAxisAndFilterAreRead) {
  test::write_file("maps/wood.png", "not read until rendering");
  const auto scene_file = test::write_file("s.yaml", "");
  const auto sampling = [&](const std::string& keys) {
    const RenderScene scene =
        build_render_scene(parse_scene_text(scene_with("{color: {texture: maps/wood.png, " + keys + "}}"), scene_file));
    return std::get<ImageTexture>(scene.materials[1].base_color).sampling;
  };
  EXPECT_EQ(sampling("wrap: [mirror, clamp], filter: nearest"),
            (TextureSampling{TextureWrap::kMirror, TextureWrap::kClamp, TextureFilter::kNearest}));
  EXPECT_EQ(sampling("wrap: black, filter: linear"),
            (TextureSampling{TextureWrap::kBlack, TextureWrap::kBlack, TextureFilter::kLinear}));
  EXPECT_THROW(sampling("wrap: [mirror]"), InputError);
  EXPECT_THROW(sampling("filter: cubic"), InputError);
}

TEST(ImageTexture, MissingSceneTextureIsRefusedAtItsKey) {
  const auto scene_file = test::write_file("s.yaml", "");
  try {
    parse_scene_text(scene_with("{color: {texture: missing.png}}"), scene_file);
    FAIL() << "a missing texture was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4) << e.what();
    EXPECT_GT(e.where().column, 0) << e.what();
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_scene_text(scene_with("{color: {texture: x.png, wrap: tile}}"), scene_file), InputError);
  EXPECT_THROW(parse_scene_text(scene_with("{color: {texture: ''}}"), scene_file), InputError);
}

// An MTL names its textures for another machine's folders more often than not (assimp-testmodels'
// spider.mtl names five, one present): a missing map_Kd is a warning and the material keeps its
// Kd, unlike a texture in rtpro's own scene file.
TEST(ImageTexture, MissingMapKdIsAWarningAtItsMtlLineAndTheMaterialKeepsKd) {
  test::scratch_dir();  // empty: wood.png is written below
  test::write_file("box.obj",
                   "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl wood\nf 1/1 2/2 3/3\n");
  const auto mtl = test::write_file("box.mtl", "newmtl wood\nKd 0.5 0.25 1\nmap_Kd wood.png\n");
  const auto scene_file = test::write_file("s.yaml", "");
  const std::string text =
      "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0]}\nworld:\n  - {type: mesh, file: box.obj}\n";
  const RenderScene untextured = build_render_scene(parse_scene_text(text, scene_file));
  EXPECT_TRUE(untextured.textures.empty());
  const LoadedMesh loaded = load_mesh_file(mtl.parent_path() / "box.obj");
  ASSERT_EQ(loaded.materials.size(), 1u);
  EXPECT_TRUE(loaded.materials[0].color_texture.empty());
  EXPECT_EQ(loaded.materials[0].color, Color(0.5f, 0.25f, 1.0f));
  bool warned = false;
  for (const std::string& w : loaded.stats.warnings)
    warned |= w.find(mtl.string() + ":3: texture 'wood.png' not found; material 'wood' uses its Kd colour") !=
              std::string::npos;
  EXPECT_TRUE(warned);
  test::write_file("wood.png", "present");
  const RenderScene scene = build_render_scene(parse_scene_text(text, scene_file));
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(scene.textures[0].file.filename(), "wood.png");
}

}  // namespace image_texture_test
}  // namespace rtpro
