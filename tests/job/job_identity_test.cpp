// Job identities: text round trip, readable differences, and digests that follow file contents.
#include "rtpro/core/error.h"
#include "rtpro/job/job_identity.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>

namespace rtpro {
namespace job_identity_test {

TEST(JobIdentity, TextRoundTripsAndDifferencesNameKeyAndBothValues) {
  JobIdentity a;
  a.set("rtpro", "0.1.0");
  a.set("spp", "16");
  a.set("mesh dragon.ply", "00ff");
  EXPECT_EQ(JobIdentity::parse(a.text(), "test"), a);
  EXPECT_TRUE(a.differences(a, "b").empty());

  JobIdentity b = a;
  b.set("spp", "64");  // replaces, keeps the order
  b.set("region", "0,0,8,8");
  EXPECT_EQ(b.entries()[1].second, "64");
  const std::vector<std::string> d = a.differences(b, "the journal");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], "spp: 16 here, 64 in the journal");
  EXPECT_EQ(d[1], "region: absent here, 0,0,8,8 in the journal");
}

TEST(JobIdentity, MalformedTextIsAnInputError) {
  EXPECT_THROW(JobIdentity::parse("spp 16\n", "j"), InputError);
  EXPECT_THROW(JobIdentity::parse("spp: 16", "j"), InputError);
  EXPECT_THROW(JobIdentity::parse(": 16\n", "j"), InputError);
  EXPECT_EQ(JobIdentity::parse("", "j").entries().size(), 0u);
}

TEST(JobIdentity, FileDigestFollowsContentsNotNames) {
  const auto a = test::write_file("a.obj", "v 0 0 0\n");
  const auto b = test::write_file("b.obj", "v 0 0 0\n");
  const auto c = test::write_file("c.obj", "v 0 0 1\n");
  EXPECT_EQ(file_digest(a), file_digest(b));
  EXPECT_NE(file_digest(a), file_digest(c));
  EXPECT_EQ(file_digest(a), text_digest("v 0 0 0\n"));
  EXPECT_EQ(file_digest(a).size(), 16u);
  EXPECT_THROW(file_digest(a.parent_path() / "absent.obj"), InputError);
}

TEST(JobIdentity, SceneIdentityCoversSourcesMeshesAndWhatTheyRead) {
  SceneDescription description;
  description.source_files = {test::write_file("scene.yaml", "rtpro: 1\n"), test::write_file("inc.yaml", "{}\n")};
  SceneBuildReport report;
  report.meshes.push_back({test::write_file("m.obj", "mtllib m.mtl\n").string(), {}, 0.0});
  report.meshes.back().stats.files_read.push_back(test::write_file("m.mtl", "newmtl a\n"));
  RenderScene scene;
  scene.textures.push_back({test::write_file("wood.png", "pixels"), "sRGB - Texture", nullptr});
  scene.textures.push_back({"m.glb#images[0].png", "sRGB - Texture",
                            std::make_shared<const std::vector<unsigned char>>(4, 0)});  // inside a glTF
  scene.environment = Environment{test::write_file("sky.exr", "sky"), Color(1.0f), Affine::identity(), true};
  const JobIdentity before = scene_identity(description, report, scene);
  EXPECT_EQ(before.entries().size(), 7u);  // rtpro version + 4 files + the environment + the texture file
  test::write_file("m.mtl", "newmtl b\n");
  test::write_file("wood.png", "other pixels");
  test::write_file("sky.exr", "another sky");
  const std::vector<std::string> d = scene_identity(description, report, scene).differences(before, "the journal");
  ASSERT_EQ(d.size(), 3u);
  std::string all;
  for (const std::string& line : d) all += line + "\n";
  for (const char* file : {"m.mtl", "wood.png", "sky.exr"}) EXPECT_NE(all.find(file), std::string::npos) << all;
}

// Issue 28: a journal's or another rank's identity is read from outside; an escape sequence or a
// newline in it reaches the terminal escaped.
TEST(JobIdentity, DifferencesShowControlCharactersEscaped) {
  JobIdentity ours;
  ours.set("scene a.yaml", "1111");
  const JobIdentity theirs =
      JobIdentity::parse("scene a.yaml: \x1b[2J\x1b]0;owned\x07\r\n\xc2\x9bhidden\x1b[0m: x\n", "journal");
  const std::vector<std::string> d = ours.differences(theirs, "the journal");
  ASSERT_EQ(d.size(), 2u);
  for (const std::string& line : d)
    for (const char c : line) EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << line;
  EXPECT_EQ(d[0], "scene a.yaml: 1111 here, \\x1b[2J\\x1b]0;owned\\x07\\x0d in the journal");
  EXPECT_EQ(d[1], "\\xc2\\x9bhidden\\x1b[0m: absent here, x in the journal");
}

}  // namespace job_identity_test
}  // namespace rtpro
