// The resume journal on disk: what is appended is read back; damage costs only the damaged tiles.
#include "rtpro/core/error.h"
#include "rtpro/job/tile_codec.h"
#include "rtpro/job/tile_journal.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>

#include <atomic>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <string>
#include <thread>

namespace rtpro {
namespace tile_journal_test {

constexpr int kChannels = 3;

TileResult tile_of(const TileGrid& grid, std::size_t index) {
  TileResult tile;
  tile.index = index;
  tile.region = grid.tile(index);
  tile.rays[RayKind::kCamera] = index + 1;
  tile.pixels.assign(tile.region.pixel_count() * kChannels, 0.25f * float(index));
  return tile;
}

JobIdentity identity_of(const std::string& spp) {
  JobIdentity identity;
  identity.set("rtpro", "test");
  identity.set("spp", spp);
  return identity;
}

// Writes a journal of a 4-spp job at `file` holding the tiles `indices` of `grid`, and closes it.
void write_journal(const std::filesystem::path& file, const TileGrid& grid,
                   std::initializer_list<std::size_t> indices) {
  TileJournal journal(file, identity_of("4"), kChannels, {});
  for (const std::size_t index : indices) journal.append(tile_of(grid, index));
}

std::ptrdiff_t entries_in(const std::filesystem::path& folder) {
  return std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator());
}

void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(TileJournal, AppendedTilesFromSeveralThreadsAreReadBack) {
  const TileGrid grid({0, 0, 40, 30}, 8);
  const auto file = test::scratch_dir() / "out.exr.rtpro-journal";
  const std::vector<TileResult> kept{tile_of(grid, 7)};
  {
    TileJournal journal(file, identity_of("16"), kChannels, kept);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&, t] {
        for (std::size_t i = std::size_t(t); i < 12; i += 4)
          if (i != 7) journal.append(tile_of(grid, i));
      });
    for (auto& thread : threads) thread.join();
    EXPECT_EQ(journal.error(), "");
  }
  const JournalContents contents = read_journal(file, grid, kChannels);
  EXPECT_EQ(contents.identity, identity_of("16"));
  EXPECT_EQ(contents.dropped_records, 0u);
  ASSERT_EQ(contents.tiles.size(), 12u);
  EXPECT_EQ(contents.tiles.front().index, 7u);  // the kept tiles come first
  std::vector<bool> seen(12, false);
  for (const TileResult& tile : contents.tiles) {
    seen[tile.index] = true;
    EXPECT_EQ(tile.pixels, tile_of(grid, tile.index).pixels);
    EXPECT_EQ(tile.rays[RayKind::kCamera], tile.index + 1);
  }
  for (bool s : seen) EXPECT_TRUE(s);
}

// A rewrite takes its records one at a time, each handed over in the same refilled item (as
// ProgressiveFilm::visit_journal_items does), and replaces every record appended before it; what
// is appended after it follows the new records.
TEST(TileJournal, RewriteReplacesTheRecordsWithItemsHandedOverOneAtATime) {
  const TileGrid grid({0, 0, 40, 30}, 8);
  const auto file = test::scratch_dir() / "out.exr.rtpro-journal";
  {
    TileJournal journal(file, identity_of("4"), kChannels, {});
    for (std::size_t i = 0; i < 6; ++i) journal.append(tile_of(grid, i));
    journal.rewrite([&](const auto& write) {
      TileResult item;
      for (const std::size_t index : {9u, 3u, 11u}) {
        item = tile_of(grid, index);
        write(item);
      }
    });
    journal.append(tile_of(grid, 5));
    EXPECT_EQ(journal.error(), "");
    EXPECT_EQ(journal.bytes(), std::filesystem::file_size(file));
  }
  const JournalContents contents = read_journal(file, grid, kChannels);
  EXPECT_EQ(contents.identity, identity_of("4"));
  EXPECT_EQ(contents.dropped_records, 0u);
  ASSERT_EQ(contents.tiles.size(), 4u);
  const std::size_t expected[] = {9, 3, 11, 5};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(contents.tiles[k].index, expected[k]);
    EXPECT_EQ(contents.tiles[k].pixels, tile_of(grid, expected[k]).pixels);
  }
}

TEST(TileJournal, TornTailAndCorruptRecordLoseOnlyTheirTiles) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto file = test::scratch_dir() / "j";
  write_journal(file, grid, {0, 1, 2, 3});
  const std::string whole = test::read_file(file);
  const std::size_t record = tile_record_size(grid.tile(0), kChannels);
  const std::size_t header = whole.size() - 4 * record;

  // Cut inside the last record, as a kill during its write would.
  write_bytes(file, whole.substr(0, whole.size() - 10));
  JournalContents torn = read_journal(file, grid, kChannels);
  EXPECT_EQ(torn.tiles.size(), 3u);
  EXPECT_EQ(torn.dropped_records, 1u);

  // A flipped pixel byte in record 1: that tile alone is dropped.
  std::string flipped = whole;
  flipped[header + record + kTileRecordHeaderBytes + 5] ^= 0x40;
  write_bytes(file, flipped);
  JournalContents corrupt = read_journal(file, grid, kChannels);
  ASSERT_EQ(corrupt.tiles.size(), 3u);
  EXPECT_EQ(corrupt.dropped_records, 1u);
  for (const TileResult& tile : corrupt.tiles) EXPECT_NE(tile.index, 1u);

  // A damaged record header gives no length to skip by: the records after it are lost too.
  std::string bad_header = whole;
  bad_header[header + 2 * record] ^= 0x01;
  write_bytes(file, bad_header);
  EXPECT_EQ(read_journal(file, grid, kChannels).tiles.size(), 2u);
}

TEST(TileJournal, DamagedHeaderOrForeignFileIsAnInputError) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto file = test::scratch_dir() / "j";
  write_journal(file, grid, {});
  std::string bytes = test::read_file(file);
  bytes[30] ^= 0x01;  // inside the identity text: its checksum no longer matches
  write_bytes(file, bytes);
  try {
    read_journal(file, grid, kChannels);
    FAIL() << "a damaged header was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
  }
  write_bytes(file, {'P', '6', '\n'});
  EXPECT_THROW(read_journal(file, grid, kChannels), InputError);
  write_bytes(file, {});
  EXPECT_THROW(read_journal(file, grid, kChannels), InputError);
  EXPECT_THROW(read_journal(file.parent_path() / "absent", grid, kChannels), InputError);
}

TEST(TileJournal, NewJournalReplacesTheOldOneWholeAndRemoveDeletesIt) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto file = test::scratch_dir() / "j";
  write_journal(file, grid, {0, 1});
  const std::vector<TileResult> kept{tile_of(grid, 1)};
  TileJournal replaced(file, identity_of("4"), kChannels, kept);
  const JournalContents contents = read_journal(file, grid, kChannels);
  ASSERT_EQ(contents.tiles.size(), 1u);
  EXPECT_EQ(contents.tiles[0].index, 1u);
  EXPECT_EQ(entries_in(file.parent_path()), 1);  // the journal alone: no temporary left
  replaced.remove();
  EXPECT_FALSE(std::filesystem::exists(file));
}

// Two renders of one output each write a new journal at once (and then replace each other's):
// each writes its own temporary file, so both succeed and the journal left is one of theirs, whole.
TEST(TileJournal, JournalsCreatedAtOnceForOneFileAllSucceed) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto file = test::scratch_dir() / "j";
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::thread> writers;
    std::atomic<int> failures{0};
    for (int w = 0; w < 4; ++w)
      writers.emplace_back([&, w] {
        try {
          const std::vector<TileResult> kept{tile_of(grid, static_cast<std::size_t>(w))};
          TileJournal journal(file, identity_of("4"), kChannels, kept);
        } catch (const RuntimeError&) {
          ++failures;
        }
      });
    for (std::thread& writer : writers) writer.join();
    ASSERT_EQ(failures.load(), 0) << "trial " << trial;
    ASSERT_EQ(read_journal(file, grid, kChannels).tiles.size(), 1u) << "trial " << trial;
  }
  EXPECT_EQ(entries_in(file.parent_path()), 1);
}

// A render killed while it wrote its new journal leaves a temporary; the next journal of the
// same file removes it, and leaves those of live processes and other files alone.
TEST(TileJournal, TemporariesOfDeadProcessesAreRemoved) {
  const auto folder = test::scratch_dir();
  const auto file = folder / "j";
  const std::string dead = std::to_string(test::dead_pid());
  const std::string live = std::to_string(::getppid());
  const std::vector<std::string> left = {"j.tmp-" + dead + "-0", "j.tmp-" + live + "-2", "k.tmp-" + dead + "-0",
                                         "j.tmp-x-1"};
  for (const std::string& name : left) std::ofstream(folder / name) << "half a journal";
  TileJournal journal(file, identity_of("4"), kChannels, {});
  EXPECT_FALSE(std::filesystem::exists(folder / ("j.tmp-" + dead + "-0")));
  EXPECT_TRUE(std::filesystem::exists(folder / ("j.tmp-" + live + "-2")));
  EXPECT_TRUE(std::filesystem::exists(folder / ("k.tmp-" + dead + "-0")));
  EXPECT_TRUE(std::filesystem::exists(folder / "j.tmp-x-1"));
}

TEST(TileJournal, UnwritableFolderIsARuntimeErrorNamingTheFile) {
  const auto file = test::scratch_dir() / "missing-folder" / "j";
  try {
    TileJournal journal(file, identity_of("4"), kChannels, {});
    FAIL() << "a journal was created in a missing folder";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

// Issue 28: a FIFO, device, directory or link at the journal's name is never read (a FIFO would
// block for ever, /dev/zero never ends), replaced or deleted.
TEST(TileJournal, FifoDeviceDirectoryOrLinkAtTheJournalIsRefusedAndLeftInPlace) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto folder = test::scratch_dir();
  const auto fifo = folder / "fifo", link = folder / "link", directory = folder / "dir", target = folder / "target";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::filesystem::create_symlink("/dev/zero", link);
  std::filesystem::create_directory(directory);
  for (const auto& [file, kind] :
       {std::pair{fifo, "a FIFO"}, std::pair{link, "a symbolic link"}, std::pair{directory, "a directory"}}) {
    SCOPED_TRACE(file.string());
    try {
      read_journal(file, grid, kChannels);
      FAIL() << "read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string() + " is " + kind), std::string::npos) << e.what();
    }
    EXPECT_THROW(TileJournal(file, identity_of("4"), kChannels, {}), RuntimeError);
  }
  EXPECT_EQ(std::filesystem::symlink_status(fifo).type(), std::filesystem::file_type::fifo);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_TRUE(std::filesystem::is_directory(directory));
  EXPECT_EQ(entries_in(folder), 3) << "no temporary left behind";

  // A link put in the journal's place during the render is not deleted with it.
  const auto file = folder / "j";
  TileJournal journal(file, identity_of("4"), kChannels, {});
  std::ofstream(target) << "kept";
  std::filesystem::remove(file);
  std::filesystem::create_symlink(target, file);
  journal.remove();
  EXPECT_TRUE(std::filesystem::is_symlink(file));
}

// A journal's records are read one at a time: a sparse 20 GB file (intact records, then a hole)
// costs a record's memory and stops at the hole, instead of being read whole into memory.
TEST(TileJournal, SparseHugeJournalIsReadAsAStream) {
  const TileGrid grid({0, 0, 16, 16}, 8);
  const auto file = test::scratch_dir() / "j";
  write_journal(file, grid, {0, 2});
  std::filesystem::resize_file(file, std::uintmax_t(20) << 30);
  const auto start = std::chrono::steady_clock::now();
  const JournalContents contents = read_journal(file, grid, kChannels);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  ASSERT_EQ(contents.tiles.size(), 2u);
  EXPECT_EQ(contents.tiles[1].index, 2u);
  EXPECT_EQ(contents.dropped_records, 1u);
  std::filesystem::remove(file);
}

}  // namespace tile_journal_test
}  // namespace rtpro
