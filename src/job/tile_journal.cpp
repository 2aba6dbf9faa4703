#include "rtpro/job/tile_journal.h"

#include "rtpro/core/error.h"
#include "rtpro/core/special_file_kind.h"
#include "rtpro/core/stale_temporaries.h"
#include "rtpro/job/tile_codec.h"

#include <xxhash.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace rtpro {

namespace {

constexpr std::string_view kJournalMagic = "RTPRO-JOURNAL 2\n";  // records of work items (tile_codec.h)
constexpr std::string_view kOldJournalMagic = "RTPRO-JOURNAL 1\n";
// A job description is a few hundred bytes per file it names; a header claiming more is damage.
constexpr std::uint64_t kMaxIdentityBytes = 16u << 20;

bool write_all(int descriptor, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t wrote = ::write(descriptor, bytes, size);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return false;
    bytes += wrote;
    size -= static_cast<std::size_t>(wrote);
  }
  return true;
}

// "JOURNAL.tmp-": a new journal is written under a temporary name of its own
// (stale_temporaries.h), so that two renders of one output never write into each other's file.
std::string temporary_prefix(const std::filesystem::path& file) { return file.filename().string() + ".tmp-"; }

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

std::vector<std::byte> header_bytes(const JobIdentity& identity) {
  const std::string text = identity.text();
  const std::uint64_t length = text.size();
  const std::uint64_t checksum = XXH3_64bits(text.data(), text.size());
  std::vector<std::byte> bytes(kJournalMagic.size() + 2 * sizeof(std::uint64_t) + text.size());
  std::byte* out = bytes.data();
  std::memcpy(out, kJournalMagic.data(), kJournalMagic.size());
  out += kJournalMagic.size();
  std::memcpy(out, &length, sizeof length);
  out += sizeof length;
  std::memcpy(out, text.data(), text.size());
  out += text.size();
  std::memcpy(out, &checksum, sizeof checksum);
  return bytes;
}

// Reads up to `size` bytes (fewer only at the end of the file).
std::size_t read_up_to(int descriptor, std::byte* out, std::size_t size, const std::filesystem::path& file) {
  std::size_t got = 0;
  while (got < size) {
    const ssize_t n = ::read(descriptor, out + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(file.string() + ": cannot read the resume journal: " + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  return got;
}

// The journal opened for reading without following a link or waiting on a FIFO, and only if it is
// a regular file: a /dev/zero or FIFO planted there must be refused, not read for ever.
int open_journal_for_reading(const std::filesystem::path& file) {
  check_journal_file(file);
  const int descriptor = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (descriptor < 0) throw InputError(file.string() + ": cannot read the resume journal: " + std::strerror(errno));
  struct stat status {};
  if (::fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(descriptor);
    throw InputError(file.string() + ": the resume journal is not a regular file; rtpro does not read it");
  }
  return descriptor;
}

}  // namespace

std::filesystem::path journal_path(const std::filesystem::path& output) {
  std::filesystem::path journal = output;
  journal += ".rtpro-journal";
  return journal;
}

void check_journal_file(const std::filesystem::path& file) {
  struct stat status {};
  if (::lstat(file.c_str(), &status) != 0) {
    if (errno == ENOENT) return;
    throw InputError(file.string() + ": cannot look at the resume journal: " + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode))
    throw InputError(file.string() + " is " + special_file_kind(status.st_mode) +
                     ", not a resume journal: rtpro neither reads, replaces nor deletes it; move it away or "
                     "choose another output");
}

JournalContents read_journal(const std::filesystem::path& file, const TileGrid& grid, int channel_count) {
  const int descriptor = open_journal_for_reading(file);
  // Read as a stream, a record at a time: what a journal holds is bounded by its grid, not by
  // the size the file claims (a sparse 20 GB file costs one record's memory and stops at its
  // first hole).
  struct Closer {
    int descriptor;
    ~Closer() { ::close(descriptor); }
  } const closer{descriptor};
  const auto not_a_journal = [&](const std::string& why) {
    return InputError(file.string() + ": not an intact rtpro resume journal (" + why +
                      "); delete it to render from the start");
  };
  const auto read = [&](std::byte* out, std::size_t size) { return read_up_to(descriptor, out, size, file); };
  std::vector<std::byte> buffer(kJournalMagic.size() + sizeof(std::uint64_t));
  const std::size_t opening = read(buffer.data(), buffer.size());
  if (opening >= kOldJournalMagic.size() &&
      std::memcmp(buffer.data(), kOldJournalMagic.data(), kOldJournalMagic.size()) == 0)
    throw not_a_journal("written by an older rtpro, which rendered tiles without passes");
  if (opening < kJournalMagic.size() || std::memcmp(buffer.data(), kJournalMagic.data(), kJournalMagic.size()) != 0)
    throw not_a_journal("no journal header");
  std::uint64_t length = 0;
  if (opening < buffer.size()) throw not_a_journal("the header is cut short");
  std::memcpy(&length, buffer.data() + kJournalMagic.size(), sizeof length);
  if (length > kMaxIdentityBytes) throw not_a_journal("the header is cut short or damaged");
  buffer.resize(length + sizeof(std::uint64_t));
  if (read(buffer.data(), buffer.size()) < buffer.size()) throw not_a_journal("the header is cut short or damaged");
  const std::string_view text(reinterpret_cast<const char*>(buffer.data()), length);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, buffer.data() + length, sizeof checksum);
  if (XXH3_64bits(text.data(), text.size()) != checksum) throw not_a_journal("the header's checksum does not match");
  JournalContents contents;
  contents.identity = JobIdentity::parse(text, file.string());

  // A record whose header is damaged gives no trustworthy length: the records after it are lost
  // too (their tiles are rendered again). A record with an intact header but a bad checksum is
  // skipped by its length.
  std::vector<bool> seen(2 * grid.count(), false);  // by index, partial and cumulative
  while (true) {
    buffer.resize(kTileRecordHeaderBytes);
    const std::size_t got = read(buffer.data(), buffer.size());
    if (got == 0) break;
    const std::optional<std::size_t> size =
        tile_record_size_from_header(std::span(buffer).first(got), grid, channel_count);
    if (!size) {
      ++contents.dropped_records;
      break;
    }
    buffer.resize(*size);
    if (read(buffer.data() + kTileRecordHeaderBytes, *size - kTileRecordHeaderBytes) < *size - kTileRecordHeaderBytes) {
      ++contents.dropped_records;  // a torn tail
      break;
    }
    std::optional<TileResult> tile = decode_tile(buffer, grid, channel_count);
    const std::size_t key = tile ? 2 * tile->index + (tile->cumulative ? 1 : 0) : 0;
    if (!tile || seen[key]) {
      ++contents.dropped_records;
      continue;
    }
    seen[key] = true;
    contents.tiles.push_back(std::move(*tile));
  }
  return contents;
}

TileJournal::TileJournal(std::filesystem::path file, const JobIdentity& identity, int channel_count,
                         std::span<const TileResult> kept)
    : file_(std::move(file)), channel_count_(channel_count), header_(header_bytes(identity)) {
  const std::lock_guard lock(mutex_);
  write_new([kept](const std::function<void(const TileResult&)>& write) {
    for (const TileResult& tile : kept) write(tile);
  });
}

void TileJournal::write_new(const Items& items) {
  std::filesystem::path temporary;
  // A file or link planted at a temporary name is skipped, never written through or removed.
  int descriptor = create_owned_temporary(folder_of(file_), temporary_prefix(file_), temporary);
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    if (descriptor >= 0) {
      ::close(descriptor);
      ::unlink(temporary.c_str());
    }
    return RuntimeError(file_.string() + ": cannot " + what + " the resume journal: " + reason);
  };
  if (descriptor < 0) throw fail("create");
  std::size_t bytes = header_.size();
  if (!write_all(descriptor, header_.data(), header_.size())) throw fail("write");
  int write_error = 0;  // errno of the failed write, kept past the items still handed over
  items([&](const TileResult& tile) {
    if (write_error != 0) return;
    const std::vector<std::byte> record = encode_tile(tile, channel_count_);
    if (write_all(descriptor, record.data(), record.size())) bytes += record.size();
    else write_error = errno != 0 ? errno : EIO;
  });
  if (write_error != 0) {
    errno = write_error;
    throw fail("write");
  }
  // Only a journal is ever replaced: a FIFO, device or link put there meanwhile stays.
  try {
    check_journal_file(file_);
  } catch (const InputError& error) {
    ::close(descriptor);
    ::unlink(temporary.c_str());
    throw RuntimeError(error.what());
  }
  if (::rename(temporary.c_str(), file_.c_str()) != 0) throw fail("rename");
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = descriptor;
  bytes_ = bytes;
  // What a render killed while it wrote its new journal left behind.
  remove_stale_temporaries(folder_of(file_), temporary_prefix(file_));
}

void TileJournal::rewrite(const Items& items) {
  const std::lock_guard lock(mutex_);
  if (descriptor_ < 0 || !error_.empty()) return;
  try {
    write_new(items);
  } catch (const RuntimeError& error) {
    error_ = std::string(error.what()) + ": the journal keeps its records so far";
  }
}

std::size_t TileJournal::bytes() const {
  const std::lock_guard lock(mutex_);
  return bytes_;
}

TileJournal::~TileJournal() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

void TileJournal::append(const TileResult& tile) {
  const std::vector<std::byte> record = encode_tile(tile, channel_count_);
  const std::lock_guard lock(mutex_);
  if (descriptor_ < 0 || !error_.empty()) return;
  if (!write_all(descriptor_, record.data(), record.size()))
    error_ = file_.string() + ": cannot write the resume journal (" + std::strerror(errno) +
             "): tiles finished from now on are not recorded";
  else bytes_ += record.size();
}

std::string TileJournal::error() const {
  const std::lock_guard lock(mutex_);
  return error_;
}

void TileJournal::remove() {
  const std::lock_guard lock(mutex_);
  if (descriptor_ < 0) return;
  // Deletes the journal this object wrote, and nothing put in its place since.
  struct stat ours {
  }, there{};
  const bool same = ::fstat(descriptor_, &ours) == 0 && ::lstat(file_.c_str(), &there) == 0 && S_ISREG(there.st_mode) &&
                    ours.st_dev == there.st_dev && ours.st_ino == there.st_ino;
  ::close(descriptor_);
  descriptor_ = -1;
  if (same) ::unlink(file_.c_str());
}

}  // namespace rtpro
