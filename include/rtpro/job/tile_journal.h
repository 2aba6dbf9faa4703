#pragma once
// The resume journal kept beside an image while it renders (OUT.rtpro-journal): a header naming
// the job (its JobIdentity) and then one record (tile_codec.h) per finished work item (a tile in
// a pass), each appended with a single write(2) as the item finishes, so a killed process loses
// at most the items in flight. Between passes the journal may be rewritten whole with the sums of
// the passes so far as one cumulative record per tile (rewrite), so it stays a few times the
// film's size however many passes the render takes. Records are not fsync'ed: they survive the death of the process, not of the
// machine. `rtpro render --resume` reads the journal back, keeps the intact records of the same
// job and renders only the other tiles; the image is then bit-identical to an uninterrupted one.
#include "rtpro/job/job_identity.h"
#include "rtpro/render/tiles.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace rtpro {

// "out.exr" → "out.exr.rtpro-journal".
std::filesystem::path journal_path(const std::filesystem::path& output);

// Throws InputError naming `file` when something other than a regular file is there (a FIFO, a
// device, a directory or a symbolic link): rtpro never reads, replaces or deletes such a thing.
void check_journal_file(const std::filesystem::path& file);

struct JournalContents {
  JobIdentity identity;
  std::vector<TileResult> tiles;    // intact records of work items of `grid`, each once
  std::size_t dropped_records = 0;  // torn, corrupt or repeated records, and a torn tail
};

// Throws InputError naming the file when it cannot be read, is not a regular file (checked without
// following a link or opening a FIFO for good) or does not start with an intact journal header.
// Reads records one at a time. Records are checked against `grid` and `channel_count`; compare the identity
// before trusting them.
JournalContents read_journal(const std::filesystem::path& file, const TileGrid& grid, int channel_count);

class TileJournal {
 public:
  // Writes a new journal at `file` holding `identity` and the `kept` tiles (to a temporary file
  // renamed into place, so an earlier journal is replaced only by a whole one). Throws
  // RuntimeError when it cannot be written.
  TileJournal(std::filesystem::path file, const JobIdentity& identity, int channel_count,
              std::span<const TileResult> kept);
  ~TileJournal();
  TileJournal(const TileJournal&) = delete;
  TileJournal& operator=(const TileJournal&) = delete;

  // Appends one record; safe to call from several threads. A failed write (a full disk) stops
  // the journal without failing the render: error() says why, and resume then renders more.
  void append(const TileResult& tile);
  std::string error() const;

  // The items of a journal's records, handed to `write` one at a time (ProgressiveFilm::
  // visit_journal_items): a rewrite holds one record at a time, not a copy of the film.
  using Items = std::function<void(const std::function<void(const TileResult&)>& write)>;
  // Replaces the journal (through a temporary file, as the constructor does) with one holding
  // `items`. A failure leaves the journal as it was and sets error().
  void rewrite(const Items& items);
  // Bytes in the journal: its header and records.
  std::size_t bytes() const;

  // Closes and deletes the file (only if it is still the one this journal wrote): the image it
  // was for is written.
  void remove();
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  void write_new(const Items& items);

  int channel_count_;
  std::vector<std::byte> header_;
  int descriptor_ = -1;
  std::size_t bytes_ = 0;
  mutable std::mutex mutex_;
  std::string error_;
};

}  // namespace rtpro
