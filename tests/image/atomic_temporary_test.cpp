// The atomic writer's temporary files have predictable names (".NAME.rtpro-tmp-PID-N"): symbolic
// links planted there by someone sharing the folder must never be followed (issue 28: a TIFF or
// SGI image was written through the link into its target, and the output ended as that link).
#include "rtpro/core/error.h"
#include "rtpro/core/stale_temporaries.h"
#include "rtpro/image/atomic_file_replacement.h"
#include "rtpro/image/image_io.h"

#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace rtpro {
namespace atomic_temporary_test {

namespace fs = std::filesystem;

// Links at the next `count` temporary names of `target` in this process, all to `victim`.
std::vector<fs::path> plant_links(const fs::path& target, const fs::path& victim, int count) {
  // The counter is shared by every temporary of the process: the name it gives now tells the next.
  const std::string taken = owned_temporary_name(temporary_prefix(target));
  const std::string stem = taken.substr(0, taken.rfind('-') + 1);
  const unsigned next = unsigned(std::stoul(taken.substr(taken.rfind('-') + 1))) + 1;
  std::vector<fs::path> links;
  for (int i = 0; i < count; ++i) {
    links.push_back(target.parent_path() / (stem + std::to_string(next + unsigned(i))));
    fs::remove(links.back());
    fs::create_symlink(victim, links.back());
  }
  return links;
}

void expect_untouched(const fs::path& victim, const fs::path& output, const std::vector<fs::path>& links) {
  EXPECT_EQ(test::read_file(victim), "precious") << "the planted link was followed";
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(output))) << output << " is not a regular file of its own";
  for (const fs::path& link : links)
    EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link))) << link << " was replaced or removed";
}

TEST(AtomicTemporary, LinksPlantedAtTheTemporaryNamesOfATiffAreNotFollowed) {
  const fs::path output = test::scratch_dir() / "out.tif";  // emptied: victim.txt comes after
  const fs::path victim = test::write_file("victim.txt", "precious");
  const std::vector<fs::path> links = plant_links(output, victim, 3);
  write_image(output, test::uniform_image(4, 4, 0.5f), ImageWriteOptions{});
  expect_untouched(victim, output, links);
  EXPECT_EQ(read_image(output).width, 4);
}

TEST(AtomicTemporary, LinksPlantedAtTheTemporaryNamesOfABufferedWriteAreNotFollowed) {
  const fs::path output = test::scratch_dir() / "stats.json";
  const fs::path victim = test::write_file("victim.txt", "precious");
  const std::vector<fs::path> links = plant_links(output, victim, 2);
  write_file_atomically(output, "{}\n");
  expect_untouched(victim, output, links);
  EXPECT_EQ(test::read_file(output), "{}\n");
}

TEST(AtomicTemporary, AReplacedTemporaryIsNotRenamedOverTheTarget) {
  const fs::path victim = test::write_file("victim.txt", "precious");
  const fs::path output = test::write_file("kept.txt", "old");
  {
    AtomicFileReplacement replacement(output);
    fs::remove(replacement.temporary_path());
    fs::create_symlink(victim, replacement.temporary_path());
    EXPECT_THROW(replacement.commit(), RuntimeError);
  }
  EXPECT_EQ(test::read_file(output), "old");
  EXPECT_EQ(test::read_file(victim), "precious");
}

}  // namespace atomic_temporary_test
}  // namespace rtpro
