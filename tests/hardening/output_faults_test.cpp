// What happens to outputs when things go wrong: full disks, targets that are not regular files,
// processes killed mid-write, two renders writing one file. The rule throughout: the target holds
// the old contents or complete new ones, and rtpro's temporary files do not pile up.
#include "capped_run.h"
#include "rtpro/core/error.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <random>
#include <thread>

namespace rtpro::test {
namespace output_faults_test {

// rtpro rendering the shipped demo scene into `target` at one sample a pixel, then `options`: the
// arguments for run_capped.
std::vector<std::string> demo_render(const std::filesystem::path& target, const std::vector<std::string>& options) {
  std::vector<std::string> argv = {rtpro_executable().string(),
                                   "render",
                                   (scenes_dir() / "demo.yaml").string(),
                                   "-o",
                                   target.string(),
                                   "--spp",
                                   "1"};
  argv.insert(argv.end(), options.begin(), options.end());
  return argv;
}

std::vector<std::string> temporaries_in(const std::filesystem::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().find(".rtpro-tmp-") != std::string::npos)
      found.push_back(entry.path().filename().string());
  return found;
}

TEST(AtomicWrite, RefusesToReplaceSymlinksAndDevices) {
  const auto dir = scratch_dir();
  const auto victim = write_file("victim.txt", "precious");
  const auto link = dir / "link.json";
  std::filesystem::create_symlink(victim, link);
  EXPECT_THROW(write_file_atomically(link, "new"), RuntimeError);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read_file(victim), "precious");
  EXPECT_THROW(write_file_atomically("/dev/null", "new"), RuntimeError);
  struct stat status {};
  ASSERT_EQ(::stat("/dev/null", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
  EXPECT_THROW(write_file_atomically(dir, "new"), RuntimeError);
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(AtomicWrite, RemovesStaleTemporariesOfDeadProcessesOnly) {
  const auto dir = scratch_dir();
  const auto target = dir / "out.json";
  const auto stale = write_file(".out.json.rtpro-tmp-" + std::to_string(dead_pid()) + "-0", "half");
  const auto live = write_file(".out.json.rtpro-tmp-" + std::to_string(::getppid()) + "-3", "in progress");
  const auto other = write_file(".other.json.rtpro-tmp-" + std::to_string(dead_pid()) + "-0", "not ours");
  write_file_atomically(target, "done");
  EXPECT_EQ(read_file(target), "done");
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(live));   // its process may still be writing
  EXPECT_TRUE(std::filesystem::exists(other));  // another target's business
}

// A file-size limit makes write(2) fail with EFBIG exactly as a full disk fails with ENOSPC;
// unlike mounting a small file system it needs no privileges. Run in a child so the limit dies
// with it.
int write_in_child_with_size_limit(const std::filesystem::path& target, std::size_t bytes, rlim_t limit) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    rlimit cap{limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &cap);
    try {
      write_file_atomically(target, std::string(bytes, 'x'));
    } catch (const RuntimeError&) {
      ::_exit(1);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(AtomicWrite, AFullDiskKeepsTheOldFileAndLeavesNoTemporary) {
  const auto dir = scratch_dir();
  const auto target = write_file("stats.json", "old and good");
  EXPECT_EQ(write_in_child_with_size_limit(target, 1 << 20, 64 << 10), 1);
  EXPECT_EQ(read_file(target), "old and good");
  EXPECT_TRUE(temporaries_in(dir).empty());
  EXPECT_EQ(write_in_child_with_size_limit(target, 1000, 64 << 10), 0);
  EXPECT_EQ(read_file(target), std::string(1000, 'x'));
}

// A real full file system where the test may mount one (root, outside most containers).
TEST(AtomicWrite, ARealFullTmpfsKeepsTheOldImage) {
  const auto dir = scratch_dir() / "small";
  std::filesystem::create_directories(dir);
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=256k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
  struct Unmount {
    std::filesystem::path dir;
    ~Unmount() { ::umount(dir.c_str()); }
  } unmount{dir};
  const auto good = dir / "render.exr";
  const CappedRun first = run_capped(demo_render(good, {"--size", "32x32", "-q"}));
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const std::string before = read_file(good);
  // Fill what is left, then ask for an image that cannot fit.
  std::ofstream(dir / "filler", std::ios::binary) << std::string(256 << 10, 'f');
  const CappedRun full = run_capped(demo_render(good, {"--size", "256x256", "-q"}));
  EXPECT_EQ(full.exit_code, 1) << full.output;
  EXPECT_EQ(read_file(good), before);
  EXPECT_TRUE(temporaries_in(dir).empty());
}

TEST(OutputFaults, AFullDiskDuringAnImageWriteIsExitOneAndKeepsTheOldImage) {
  const auto dir = scratch_dir();
  for (const char* name : {"out.exr", "out.png", "out.tif"}) {
    const auto target = dir / name;
    const std::vector<std::string> render = demo_render(target, {"-q"});
    ASSERT_EQ(run_capped(demo_render(target, {"-q", "--size", "16x16"})).exit_code, 0);
    const std::string before = read_file(target);
    // 64 KiB of file size allowed: the 640x480 image does not fit.
    const CappedRun full = run_capped(render, 60, "trap '' XFSZ; ulimit -f 64;");
    EXPECT_EQ(full.exit_code, 1) << name << ": " << full.output;
    EXPECT_NE(full.output.find("cannot write"), std::string::npos) << full.output;
    EXPECT_EQ(read_file(target), before) << name;
    EXPECT_TRUE(temporaries_in(dir).empty()) << name;
  }
}

TEST(OutputFaults, StatsJsonNeverReplacesADeviceOrASymlink) {
  const auto dir = scratch_dir();
  const auto victim = write_file("victim.txt", "precious");
  const auto link = dir / "stats.json";
  std::filesystem::create_symlink(victim, link);
  for (const std::string& target : {link.string(), std::string("/dev/null")}) {
    const CappedRun run = run_capped(demo_render(dir / "x.png", {"--size", "8x8", "--stats-json", target}));
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("rtpro replaces only regular files"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << "refused before rendering";
  }
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read_file(victim), "precious");
}

// --stats-json naming the image (under another spelling) or the scene: refused before rendering,
// both names in the message, every file as it was.
TEST(OutputFaults, AnOutputThatIsTheImageOrTheSceneIsRefusedBeforeRendering) {
  const auto dir = scratch_dir();
  const auto scene = write_file("scene.yaml", read_file(scenes_dir() / "demo.yaml"));
  const auto image = dir / "x.png";
  std::ofstream(image) << "a previous good image";
  const std::string same_image = (dir / "." / "x.png").string();
  for (const auto& [target, other] :
       {std::pair{same_image, std::string("-o")}, std::pair{scene.string(), std::string("the scene")}}) {
    const CappedRun run = run_capped({rtpro_executable().string(), "render", scene.string(), "--size", "8x8", "--spp",
                                      "1", "-o", image.string(), "--stats-json", target});
    EXPECT_EQ(run.exit_code, 2) << target << ": " << run.output;
    EXPECT_NE(run.output.find("--stats-json"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(other), std::string::npos) << run.output;
  }
  EXPECT_EQ(read_file(image), "a previous good image");
  EXPECT_EQ(read_file(scene), read_file(scenes_dir() / "demo.yaml"));
}

// Files planted at the names of every temporary a render creates (the resume journal's, the
// image's, the statistics') and at the journal's lock: the render takes other names, and every
// planted file is still there with its bytes. The shell's PID is rtpro's once it execs.
TEST(OutputFaults, FilesPlantedAtTheTemporaryNamesAreNeitherUsedNorRemoved) {
  const auto dir = scratch_dir();
  std::vector<std::string> prefixes = {"out.exr.rtpro-journal.tmp-", ".out.exr.rtpro-tmp-", ".stats.json.rtpro-tmp-"};
  std::string plant = "for n in 0 1 2 3 4 5 6 7; do";
  for (const std::string& prefix : prefixes) plant += " echo planted > " + prefix + "$$-$n;";
  plant += " done; echo mine > out.exr.rtpro-journal.lock; exec " +
           rtpro_command(
               render_args(scenes_dir() / "demo.yaml", "out.exr", "--size 8x8 --spp 1 -q --stats-json stats.json"));
  std::string out;
  EXPECT_EQ(run_command("cd " + dir.string() + " && sh -c '" + plant + "'", &out), 0) << out;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "out.exr"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "stats.json"));
  int planted = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    for (const std::string& prefix : prefixes)
      if (entry.path().filename().string().rfind(prefix, 0) == 0) {
        EXPECT_EQ(read_file(entry.path()), "planted\n") << entry.path();
        ++planted;
      }
  EXPECT_EQ(planted, 24);
  EXPECT_EQ(read_file(dir / "out.exr.rtpro-journal.lock"), "mine\n");
}

// SIGKILL at random moments of a render that replaces a good image: the target is always the
// old image or a complete new one, and the temporaries the killed runs left are gone after the
// next run that writes the same target.
TEST(OutputFaults, SigkillDuringARenderNeverLeavesABrokenImage) {
  const auto dir = scratch_dir();
  const auto target = dir / "out.exr";
  const std::vector<std::string> render = demo_render(target, {"--size", "512x384", "-q"});
  const CappedRun reference = run_capped(render, 120);
  ASSERT_EQ(reference.exit_code, 0) << reference.output;
  const std::string good = read_file(target);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> moment(0.0, reference.seconds * 1.1);
  int killed = 0;
  for (int trial = 0; trial < 30; ++trial) {
    std::filesystem::remove(target);
    std::ofstream(target, std::ios::binary) << good;
    const pid_t child = start_program(render);
    std::this_thread::sleep_for(std::chrono::duration<double>(moment(rng)));
    if (::kill(child, SIGKILL) == 0) ++killed;
    int status = 0;
    ::waitpid(child, &status, 0);
    // Old or new: both are complete images of the same size.
    const Image image = read_image(target);
    EXPECT_EQ(image.width, 512) << "trial " << trial;
    EXPECT_EQ(image.height, 384) << "trial " << trial;
  }
  EXPECT_GT(killed, 20);
  ASSERT_EQ(run_capped(render, 120).exit_code, 0);
  EXPECT_TRUE(temporaries_in(dir).empty()) << temporaries_in(dir).size() << " left, e.g. " << temporaries_in(dir)[0];
}

TEST(OutputFaults, TwoRendersWritingOneFileEndWithOneCompleteImageOrTheSecondRefused) {
  const auto dir = scratch_dir();
  const auto target = dir / "out.png";
  const std::vector<std::string> a = demo_render(target, {"--size", "320x240", "-q", "--threads", "1"});
  const std::vector<std::string> b = demo_render(target, {"--size", "320x240", "-q", "--threads", "1", "--seed", "7"});
  CappedRun first, second;
  std::thread one([&] { first = run_capped(a, 120); });
  std::thread two([&] { second = run_capped(b, 120); });
  one.join();
  two.join();
  // One render at a time owns the output's journal (issue 28): one that starts while the other
  // runs is refused, saying so, and leaves the other's files alone.
  for (const CappedRun* run : {&first, &second})
    if (run->exit_code != 0) {
      EXPECT_EQ(run->exit_code, 2) << run->output;
      EXPECT_NE(run->output.find("another render of the same output owns this resume journal"), std::string::npos)
          << run->output;
    }
  EXPECT_TRUE(first.exit_code == 0 || second.exit_code == 0) << first.output << second.output;
  const Image image = read_image(target);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 240);
  EXPECT_TRUE(temporaries_in(dir).empty());
}

}  // namespace output_faults_test
}  // namespace rtpro::test
