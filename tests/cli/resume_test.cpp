// `rtpro render --resume` through the real binary: a render killed at any moment and resumed gives
// the image of an uninterrupted render, bit for bit (the path integrator's with the red sphere
// blurred by an open shutter); a journal of another job is refused.
#include "rtpro/image/image_io.h"
#include "test_fixtures.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace rtpro {
namespace resume_test {

using test::expect_rtpro_answer;
using test::expect_same_pixels;
using test::render_args;
using test::rtpro_command;
using test::rtpro_executable;
using test::run_command;
using test::run_rtpro;

const char* kScene = R"(rtpro: 1
camera: {position: [0, 1.5, 6], look_at: [0, 0.5, 0], fov: 40, resolution: [96, 64]}
render: {spp: 64, max_depth: 3, seed: 3}
materials:
  red: {color: [0.9, 0.2, 0.2], reflectivity: 0.3}
  glass: {color: [1, 1, 1], ior: 1.5, specular: 0.5}
lights:
  - {type: point, position: [4, 6, 5], color: [1, 1, 1], intensity: 1}
world:
  - {type: sphere, center: [0, -1000, 0], radius: 1000}
  - {type: sphere, center: {keyframes: {1: [-1, 0.7, 0], 2: [-0.2, 0.7, 0]}}, radius: 0.7, material: red}
  - {type: sphere, center: [1, 0.6, 0], radius: 0.6, material: glass}
)";

// 6 × 4 tiles of 16 × 16 pixels; beauty plus the albedo AOV, so AOVs are journaled too. A record
// (tile_codec.h) is an 80-byte header, a pass's sums of each pixel (7 floats: colour, sample count
// and albedo, pixel_sums.h) and a checksum. Whitted's stratified samples render in one pass; the
// path integrator's Sobol samples in 20 (1, 1, 2, 4, 8, then 16 at a time), and the journal is
// compacted every few passes. Every tile is journaled as it finishes (--journal-after 0), so that
// the tests can stop a render between any two.
const std::vector<std::string> kOptions = {"--tile-size", "16",  "--aov",           "albedo",
                                           "--spp",       "256", "--journal-after", "0"};
constexpr std::size_t kTiles = 24;
constexpr std::size_t kRecordBytes = 80 + 16 * 16 * 7 * 4 + 8;

// The arguments of this test's render of `scene` into `out`, with `extra` options after kOptions.
std::string render_of(const std::filesystem::path& scene, const std::filesystem::path& out,
                      const std::string& extra = "") {
  std::string options;
  for (const std::string& option : kOptions) options += option + " ";
  return render_args(scene, out, options + extra);
}

// Starts a single-threaded, quiet render of `scene` into `out` (`path`: with --integrator path
// and the shutter open over half a frame).
pid_t start_render(const std::filesystem::path& scene, const std::filesystem::path& out, bool path = false) {
  std::vector<std::string> argv = {
      rtpro_executable().string(), "render", scene.string(), "-o", out.string(), "--threads", "1", "-q"};
  argv.insert(argv.end(), kOptions.begin(), kOptions.end());
  if (path) argv.insert(argv.end(), {"--integrator", "path", "--shutter", "0,0.5"});
  return test::start_program(argv);
}

std::uintmax_t file_size_or_zero(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  return error ? 0 : size;
}

// Tiles recorded so far: (size − header) / record size; the header states its own length.
std::size_t recorded_tiles(const std::filesystem::path& journal) {
  std::ifstream in(journal, std::ios::binary);
  char magic[16];
  std::uint64_t length = 0;
  if (!in.read(magic, sizeof magic) || !in.read(reinterpret_cast<char*>(&length), sizeof length)) return 0;
  const std::uintmax_t header = sizeof magic + 2 * sizeof length + length;
  const std::uintmax_t size = file_size_or_zero(journal);
  return size > header ? static_cast<std::size_t>((size - header) / kRecordBytes) : 0;
}

// Starts a single-threaded render (`path`: with --integrator path), SIGKILLs it once its journal
// was compacted (shrank) `compactions` times and then holds `tiles` records.
void kill_after(const std::filesystem::path& scene, const std::filesystem::path& out, std::size_t tiles,
                bool path = false, int compactions = 0) {
  const std::filesystem::path journal = out.string() + ".rtpro-journal";
  const pid_t pid = start_render(scene, out, path);
  ASSERT_GE(pid, 0);
  int status = 0;
  std::size_t last = 0;
  int shrank = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    const std::size_t recorded = std::filesystem::exists(journal) ? recorded_tiles(journal) : 0;
    if (recorded < last) ++shrank;
    last = recorded;
    if (std::filesystem::exists(journal) && shrank >= compactions && recorded >= tiles) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  ASSERT_TRUE(WIFSIGNALED(status)) << "the render finished before it could be killed after " << tiles << " tiles";
}

TEST(Resume, KilledRenderResumesBitIdenticallyAtEveryMoment) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto whole = dir / "whole.exr";
  run_rtpro(render_of(scene, whole, "-q"), 0);
  EXPECT_FALSE(std::filesystem::exists(whole.string() + ".rtpro-journal")) << "a finished render keeps no journal";

  for (std::size_t tiles : {std::size_t(0), std::size_t(5), kTiles - 3}) {
    SCOPED_TRACE("killed after " + std::to_string(tiles) + " tiles");
    const auto out = dir / ("resumed" + std::to_string(tiles) + ".exr");
    std::ofstream(out) << "a previous good image";
    kill_after(scene, out, tiles);
    EXPECT_EQ(test::read_file(out), "a previous good image");
    ASSERT_TRUE(std::filesystem::exists(out.string() + ".rtpro-journal"));

    // Resumed with another thread count: only the pixels' own inputs matter.
    run_rtpro(render_of(scene, out, "--resume --threads 2 -q"), 0);
    expect_same_pixels(whole, out);
    EXPECT_FALSE(std::filesystem::exists(out.string() + ".rtpro-journal"));
  }
}

// Killed in the first passes, after a compaction, and in a later pass: every resume finishes the
// image of the uninterrupted render, bit for bit.
TEST(Resume, KilledProgressiveRenderResumesBitIdenticallyBetweenAndWithinPasses) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto whole = dir / "whole.exr";
  run_rtpro(render_of(scene, whole, "--integrator path --shutter 0,0.5 -q"), 0);
  // A compaction leaves one cumulative record per tile (24) and comes once a journal holds about 48.
  for (const auto& [records, compactions] : {std::pair{10, 0}, std::pair{30, 0}, std::pair{30, 1}, std::pair{40, 3}}) {
    SCOPED_TRACE("killed when the journal held " + std::to_string(records) + " records after " +
                 std::to_string(compactions) + " compactions");
    const auto out = dir / ("resumed" + std::to_string(records) + "_" + std::to_string(compactions) + ".exr");
    kill_after(scene, out, static_cast<std::size_t>(records), true, compactions);
    ASSERT_TRUE(std::filesystem::exists(out.string() + ".rtpro-journal"));
    run_rtpro(render_of(scene, out, "--integrator path --shutter 0,0.5 --resume --threads 2 -q"), 0);
    expect_same_pixels(whole, out);
  }
}

TEST(Resume, CorruptRecordIsRenderedAgainAndTheImageStaysExact) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto whole = dir / "whole.exr", out = dir / "out.exr";
  run_rtpro(render_of(scene, whole, "-q"), 0);
  kill_after(scene, out, 8);
  const std::filesystem::path journal = out.string() + ".rtpro-journal";
  {
    std::fstream f(journal, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(0, std::ios::end);
    const auto size = static_cast<long>(f.tellg());
    f.seekp(size - static_cast<long>(kRecordBytes) * 2 + 200);  // a pixel byte of the second-to-last record
    char byte = 0;
    f.seekg(f.tellp());
    f.read(&byte, 1);
    byte = static_cast<char>(byte ^ 0x21);
    f.seekp(size - static_cast<long>(kRecordBytes) * 2 + 200);
    f.write(&byte, 1);
  }
  expect_rtpro_answer(render_of(scene, out, "--resume"), 0, "1 damaged records dropped");
  expect_same_pixels(whole, out);
}

TEST(Resume, JournalOfAnotherJobIsRefusedWithWhatDiffers) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = dir / "out.exr";
  kill_after(scene, out, 2);
  const std::filesystem::path journal = out.string() + ".rtpro-journal";

  std::string output = expect_rtpro_answer(render_of(scene, out, "--set render.spp=64 --resume"), 2, journal.string());
  EXPECT_NE(output.find("spp: 64 here, 256 in the journal"), std::string::npos) << output;
  // Compact normals change the image in its last bits: a journal of full normals is another job.
  output = expect_rtpro_answer(render_of(scene, out, "--compact-normals --resume"), 2, journal.string());
  EXPECT_NE(output.find("normals"), std::string::npos) << output;
  // So does another order of a mesh's triangles, where two lie at exactly the same distance.
  output = expect_rtpro_answer(render_of(scene, out, "--embree-pieces 4096 --resume"), 2, journal.string());
  EXPECT_NE(output.find("mesh pieces"), std::string::npos) << output;

  std::string changed = kScene;
  changed.replace(changed.find("intensity: 1"), 12, "intensity: 2");
  test::write_file("scene.yaml", changed);
  expect_rtpro_answer(render_of(scene, out, "--resume"), 2, "scene " + scene.string() + ": ");
  EXPECT_FALSE(std::filesystem::exists(out)) << "a refused resume writes no image";
  EXPECT_TRUE(std::filesystem::exists(journal)) << "and keeps the journal";

  std::ofstream(journal, std::ios::trunc) << "not a journal";
  expect_rtpro_answer(render_of(scene, out, "--resume"), 2, "not an intact rtpro resume journal");
}

TEST(Resume, WithoutAJournalRendersEverythingAndNoJournalKeepsNone) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  expect_rtpro_answer(render_of(scene, dir / "a.exr", "--resume"), 0, "no journal");
  expect_rtpro_answer(render_of(scene, dir / "b.exr", "--no-journal --resume"), 2, "--no-journal");
}

// Issue 28: a FIFO, device, directory or link at OUT.rtpro-journal is refused with exit 2 and a
// message naming it, before rendering and without blocking on it; it stays where it is.
TEST(Resume, FifoOrLinkAtTheJournalIsRefusedWithoutBlockingAndLeftInPlace) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto out = dir / "out.exr";
  const std::filesystem::path journal = out.string() + ".rtpro-journal";
  ASSERT_EQ(::mkfifo(journal.c_str(), 0600), 0);
  for (const std::string extra : {"", "--resume"}) {
    SCOPED_TRACE(extra);
    std::string output;
    // `timeout`: a render blocked on the FIFO fails the test instead of hanging it.
    EXPECT_EQ(run_command("timeout 60 " + rtpro_command(render_of(scene, out, extra)), &output), 2) << output;
    EXPECT_NE(output.find(journal.string() + " is a FIFO"), std::string::npos) << output;
    EXPECT_EQ(std::filesystem::symlink_status(journal).type(), std::filesystem::file_type::fifo);
  }
  std::filesystem::remove(journal);
  const auto target = test::write_file("precious.txt", "precious");
  std::filesystem::create_symlink(target, journal);
  expect_rtpro_answer(render_of(scene, out), 2, journal.string() + " is a symbolic link");
  EXPECT_TRUE(std::filesystem::is_symlink(journal));
  EXPECT_EQ(test::read_file(target), "precious");
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Issue 28: while one render of an output runs, a second is refused (it would replace the
// first's journal, and the first to finish would delete it); the first's journal survives and
// resumes exactly.
TEST(Resume, SecondRenderOfTheSameOutputIsRefusedWhileTheFirstRuns) {
  const auto dir = test::scratch_dir();
  const auto scene = test::write_file("scene.yaml", kScene);
  const auto whole = dir / "whole.exr", out = dir / "out.exr";
  run_rtpro(render_of(scene, whole, "-q"), 0);
  const std::filesystem::path journal = out.string() + ".rtpro-journal";
  const pid_t first = start_render(scene, out);
  ASSERT_GE(first, 0);
  int status = 0;
  while (waitpid(first, &status, WNOHANG) == 0 && recorded_tiles(journal) < 2)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  // Stopped, the first render holds its journal and lock however long the others take to start
  // (it finished first when the machine was busy); a killed render is what --resume continues.
  kill(first, SIGSTOP);
  ASSERT_EQ(waitpid(first, &status, WNOHANG), 0) << "the first render ended before the second started";
  expect_rtpro_answer(render_of(scene, out), 2, "another render of the same output owns this resume journal");
  run_rtpro(render_of(scene, out, "--resume"), 2);
  kill(first, SIGKILL);
  waitpid(first, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the first render finished before it could be killed";
  ASSERT_GE(recorded_tiles(journal), 2u) << "the first render's journal was lost";
  run_rtpro(render_of(scene, out, "--resume --threads 2 -q"), 0);
  expect_same_pixels(whole, out);
  EXPECT_FALSE(std::filesystem::exists(journal));
  EXPECT_FALSE(std::filesystem::exists(journal.string() + ".lock"));
}

}  // namespace resume_test
}  // namespace rtpro
