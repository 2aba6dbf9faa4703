#include "rtpro/distributed/distributed_render.h"

#include "follower_tiles.h"
#include "job_messages.h"
#include "rank_clock.h"
#include "rank_liveness.h"
#include "rtpro/core/error.h"
#include "rtpro/job/tile_codec.h"
#include "rtpro/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <ctime>
#include <cstring>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace rtpro {

namespace {

// The talking threads wake rarely: on a machine whose cores all render, every wake-up takes a core
// from a worker. Measured on 2 cores, 2 ranks x 1 thread: with pauses from 20 us up, each rank's
// talking thread woke ~800 times a second, its worker lost its core ~900 times a second (one
// process's two threads: ~40), and the two ranks rendered ~10% slower than one process with two
// threads. So rank 0 looks for messages every kLeaderPause, and a follower sleeps until its
// workers are about to run short of tiles or finish, polling only while it waits for a grant. To
// keep its workers fed across that latency a follower keeps kQueuedWork of rendering queued,
// counted in tiles of its own measured speed.
constexpr auto kLeaderPause = std::chrono::microseconds(3000);
constexpr auto kGrantPollPause = std::chrono::microseconds(1000);
constexpr auto kFollowerIdlePause = std::chrono::milliseconds(50);
constexpr double kQueuedWorkSeconds = 0.02;
constexpr std::size_t kMinTilesAheadPerThread = 2;
constexpr std::size_t kMaxTilesAheadPerThread = 64;

// CPU time of the calling thread: what handling messages costs rank 0, whatever else runs.
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + double(now.tv_nsec) * 1e-9;
}

template <class T>
std::vector<std::byte> bytes_of(const T& value) {
  std::vector<std::byte> bytes(sizeof value);
  std::memcpy(bytes.data(), &value, sizeof value);
  return bytes;
}

template <class T>
T value_of(const Message& message) {
  T value{};
  if (message.bytes.size() != sizeof value)
    throw RuntimeError("distributed render: a message from rank " + std::to_string(message.source) +
                       " has the wrong size");
  std::memcpy(&value, message.bytes.data(), sizeof value);
  return value;
}

struct DoneRecord {
  std::uint64_t tiles;
  RayCounts rays;  // by kind, in RayKind order (ray_counts.h)
  double busy_seconds, idle_seconds;
  std::uint64_t bytes_sent;
};

// Runs render_tiles on a thread of its own (a prestarted one when given) while the calling thread
// talks to the other ranks; rethrows what the render threw.
class BackgroundRender {
 public:
  BackgroundRender(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink,
                   std::function<void()> on_finish, PrestartedThread* prestarted = nullptr)
      : prestarted_(prestarted) {
    auto task = [this, &renderer, &grid, &source, &sink, on_finish] {
      try {
        render_tiles(renderer, grid, source, sink);
      } catch (...) {
        error_ = std::current_exception();
      }
      finished_ = true;
      on_finish();
    };
    if (prestarted_) prestarted_->run(std::move(task));
    else thread_ = std::thread(std::move(task));
  }
  ~BackgroundRender() { wait(); }
  bool finished() const { return finished_.load(); }
  void join() {
    wait();
    if (error_) std::rethrow_exception(error_);
  }

 private:
  void wait() {
    if (prestarted_) prestarted_->join();
    else if (thread_.joinable()) thread_.join();
  }

  PrestartedThread* prestarted_;
  std::atomic<bool> finished_{false};
  std::exception_ptr error_;
  std::thread thread_;
};

// Rank 0's own workers: timed like a follower's, tiles straight into the real sink.
class TimedSource final : public TileSource {
 public:
  TimedSource(TileSource& inner, RankClock& clock) : inner_(inner), clock_(clock) {}
  std::optional<std::size_t> next() override {
    const RankClock::Wait wait(clock_);
    if (stopped_) return std::nullopt;
    return inner_.next();
  }
  // The job is ending: the workers finish the tiles they hold and take no more.
  void stop() { stopped_ = true; }

 private:
  TileSource& inner_;
  RankClock& clock_;
  std::atomic<bool> stopped_{false};
};

class TimedSink final : public TileSink {
 public:
  TimedSink(TileSink& inner, RankClock& clock) : inner_(inner), clock_(clock) {}
  void put(TileResult&& tile) override {
    clock_.tile_done(tile);
    inner_.put(std::move(tile));
  }

 private:
  TileSink& inner_;
  RankClock& clock_;
};

// Tiles a follower keeps queued: kQueuedWorkSeconds of rendering at its mean tile time so far,
// per thread, within [kMinTilesAheadPerThread, kMaxTilesAheadPerThread].
std::size_t tiles_ahead(const RankClock& clock, int threads) {
  std::size_t per_thread = kMinTilesAheadPerThread;
  if (const std::uint64_t tiles = clock.tiles(); tiles > 0) {
    const double mean_seconds = clock.busy_seconds() / static_cast<double>(tiles);
    const double wanted = mean_seconds > 0.0 ? std::ceil(kQueuedWorkSeconds / mean_seconds)
                                             : static_cast<double>(kMaxTilesAheadPerThread);
    per_thread = static_cast<std::size_t>(
        std::clamp(wanted, static_cast<double>(kMinTilesAheadPerThread), static_cast<double>(kMaxTilesAheadPerThread)));
  }
  return per_thread * static_cast<std::size_t>(std::max(1, threads));
}

// The next message of the handshake, or an error saying who has not been heard from.
Message handshake_message(Communicator& communicator, std::chrono::milliseconds start_timeout,
                          std::chrono::steady_clock::time_point deadline, const std::vector<bool>& heard) {
  if (start_timeout.count() <= 0) return wait_for_message(communicator);
  if (std::optional<Message> message = wait_for_message_until(communicator, deadline)) return std::move(*message);
  const std::string waited = std::to_string(std::chrono::duration_cast<std::chrono::seconds>(start_timeout).count());
  if (communicator.rank() != 0)
    throw RuntimeError("distributed render: rank 0 did not answer the handshake within " + waited +
                       " s (--start-timeout): stopped, unreachable or still loading the scene");
  std::string silent;
  for (int r = 1; r < communicator.size(); ++r)
    if (!heard[std::size_t(r)]) silent += (silent.empty() ? "" : ", ") + std::to_string(r);
  throw RuntimeError("distributed render: rank " + silent + " did not reach the start of the job within " + waited +
                     " s of rank 0 (--start-timeout): stopped, unreachable or still loading the scene");
}

}  // namespace

void agree_on_job(Communicator& communicator, const JobIdentity& identity, std::chrono::milliseconds start_timeout) {
  const std::string text = identity.text();
  const auto deadline = std::chrono::steady_clock::now() + start_timeout;
  std::vector<bool> heard(std::size_t(communicator.size()), false);
  if (communicator.rank() != 0) {
    communicator.send(0, kHello, std::as_bytes(std::span(text)));
    const Message verdict = handshake_message(communicator, start_timeout, deadline, heard);
    if (verdict.tag != kVerdict) throw RuntimeError("distributed render: rank 0 did not answer the handshake");
    return;
  }
  for (int pending = communicator.size() - 1; pending > 0; --pending) {
    const Message hello = handshake_message(communicator, start_timeout, deadline, heard);
    if (hello.tag != kHello)
      throw RuntimeError("distributed render: rank " + std::to_string(hello.source) + " skipped the handshake");
    if (hello.source > 0 && hello.source < communicator.size()) heard[std::size_t(hello.source)] = true;
    const std::string_view theirs(reinterpret_cast<const char*>(hello.bytes.data()), hello.bytes.size());
    const std::string rank_name = "rank " + std::to_string(hello.source);
    const std::vector<std::string> differences = identity.differences(JobIdentity::parse(theirs, rank_name), rank_name);
    if (!differences.empty()) {
      throw InputError(
          rank_name + " would render another job than rank 0 (a different file, build or setting on its node):",
          differences);
    }
  }
  for (int rank = 1; rank < communicator.size(); ++rank) communicator.send(rank, kVerdict, {});
}

std::vector<RankStats> lead_distributed_render(Communicator& communicator, const TileRenderer& renderer,
                                               const TileGrid& grid, TileSource& source, TileSink& sink,
                                               PrestartedThread* render_thread,
                                               std::chrono::milliseconds rank_timeout) {
  const int channels = renderer.sums().floats();
  std::vector<RankStats> ranks(static_cast<std::size_t>(communicator.size()));
  for (int r = 0; r < communicator.size(); ++r) ranks[std::size_t(r)].rank = r;
  RankClock clock;
  TimedSource local_source(source, clock);
  TimedSink local_sink(sink, clock);
  BackgroundRender render(
      renderer, grid, local_source, local_sink, [] {}, render_thread);

  int following = communicator.size() - 1;
  std::vector<bool> done(ranks.size(), false);
  RankLiveness liveness(communicator.size(), rank_timeout);
  double handling_seconds = 0.0;
  std::uint64_t remote_tiles = 0;
  while (following > 0) {
    const double handling_start = thread_cpu_seconds();
    if (liveness.heartbeat_due())
      for (int rank = 1; rank < communicator.size(); ++rank) communicator.send(rank, kAlive, {});
    std::optional<Message> message = communicator.poll();
    if (!message) {
      for (int rank = 1; rank < communicator.size(); ++rank)
        if (!done[std::size_t(rank)] && liveness.silent_too_long(rank)) {
          local_source.stop();  // rank 0's workers end with their tiles in flight, into the journal
          render.join();
          throw RuntimeError(liveness.silence(rank));
        }
      handling_seconds += thread_cpu_seconds() - handling_start;
      std::this_thread::sleep_for(kLeaderPause);
      continue;
    }
    liveness.heard(message->source);
    RankStats& from = ranks[std::size_t(message->source)];
    switch (message->tag) {
      case kAlive: break;
      case kRequest: {
        // Guided hand-out: a follower gets what it asks for, but never more than half of its
        // share of what is left, so the pool's tail is spread over the ranks instead of sitting in
        // one follower's queue.
        std::uint64_t wanted = value_of<std::uint32_t>(*message);
        if (const std::optional<std::size_t> left = source.remaining())
          wanted = std::min<std::uint64_t>(
              wanted, std::max<std::uint64_t>(1, *left / (2 * static_cast<std::uint64_t>(communicator.size()))));
        std::vector<std::uint64_t> granted;
        for (std::uint64_t i = 0; i < wanted; ++i) {
          const std::optional<std::size_t> index = source.next();
          if (!index) break;
          granted.push_back(*index);
        }
        communicator.send(message->source, kGrant, std::as_bytes(std::span(granted)));
        ranks[0].bytes_sent += granted.size() * sizeof(std::uint64_t);
        break;
      }
      case kTile: {
        std::optional<TileResult> tile = decode_tile(message->bytes, grid, channels);
        if (!tile)
          throw RuntimeError("distributed render: rank " + std::to_string(message->source) + " sent a damaged tile");
        sink.put(std::move(*tile));
        ++remote_tiles;
        break;
      }
      case kDone: {
        const auto record = value_of<DoneRecord>(*message);
        from.tiles = record.tiles;
        from.rays = record.rays;
        from.busy_seconds = record.busy_seconds;
        from.idle_seconds = record.idle_seconds;
        from.bytes_sent = record.bytes_sent;
        done[std::size_t(message->source)] = true;
        --following;
        break;
      }
      default:
        throw RuntimeError("distributed render: rank " + std::to_string(message->source) +
                           " sent an unexpected message");
    }
    handling_seconds += thread_cpu_seconds() - handling_start;
  }
  for (int rank = 1; rank < communicator.size(); ++rank) communicator.send(rank, kFinished, {});
  render.join();
  ranks[0].scheduler_seconds = handling_seconds;
  ranks[0].remote_tiles = remote_tiles;
  ranks[0].tiles = clock.tiles();
  ranks[0].rays = clock.rays();
  ranks[0].busy_seconds = clock.busy_seconds();
  ranks[0].idle_seconds = clock.idle_seconds();
  return ranks;
}

void follow_distributed_render(Communicator& communicator, const TileRenderer& renderer, const TileGrid& grid,
                               int threads, const std::atomic<bool>* cancel, std::chrono::milliseconds rank_timeout) {
  const int channels = renderer.sums().floats();
  RankClock clock;
  OutgoingTiles outgoing(clock);
  GrantedTiles granted(clock, cancel, [&outgoing] { outgoing.wake(); });
  BackgroundRender render(renderer, grid, granted, outgoing, [&outgoing] { outgoing.wake(); });
  std::uint64_t bytes_sent = 0;
  const auto send_tiles = [&](const std::deque<TileResult>& tiles) {
    for (const TileResult& tile : tiles) {
      const std::vector<std::byte> bytes = encode_tile(tile, channels);
      communicator.send(0, kTile, bytes);
      bytes_sent += bytes.size();
    }
  };
  // Rank 0 may still be opening its journal when this rank starts: its silence counts from the
  // first word it sends.
  RankLiveness liveness(communicator.size(), rank_timeout);
  bool heard_leader = false;
  const auto check_leader = [&] {
    if (heard_leader && liveness.silent_too_long(0)) {
      granted.stop();  // the workers finish their tiles in flight; the job ends without them
      render.join();
      throw RuntimeError(liveness.silence(0));
    }
  };
  // Returns a message other than a heartbeat, if one came.
  const auto poll_leader = [&]() -> std::optional<Message> {
    while (std::optional<Message> message = communicator.poll()) {
      heard_leader = true;
      liveness.heard(0);
      if (message->tag != kAlive) return message;
    }
    return std::nullopt;
  };
  bool asked = false, no_more = false;
  outgoing.wake();  // the first pass asks for tiles at once
  while (true) {
    // Wakes when a worker runs low on tiles or the render ends; polls every kGrantPollPause while a
    // request is out, and otherwise looks in every kFollowerIdlePause (finished tiles, a cancel).
    send_tiles(outgoing.take(asked ? kGrantPollPause : kFollowerIdlePause));
    if (render.finished()) {
      send_tiles(outgoing.take(std::chrono::microseconds(0)));
      break;
    }
    if (liveness.heartbeat_due()) communicator.send(0, kAlive, {});
    if (!no_more && cancel && cancel->load()) {
      no_more = true;  // the tiles in flight are finished and sent; the queued ones are left to rank 0's journal
      granted.finish();
    }
    const std::size_t ahead = tiles_ahead(clock, threads);
    granted.set_low_water(ahead);
    if (!no_more && !asked && granted.queued() < ahead) {
      const auto wanted = static_cast<std::uint32_t>(2 * ahead - granted.queued());
      communicator.send(0, kRequest, bytes_of(wanted));
      bytes_sent += sizeof wanted;
      asked = true;
    }
    while (std::optional<Message> message = poll_leader()) {
      if (message->tag != kGrant) throw RuntimeError("distributed render: rank 0 sent an unexpected message");
      std::vector<std::uint64_t> indices(message->bytes.size() / sizeof(std::uint64_t));
      if (!indices.empty()) std::memcpy(indices.data(), message->bytes.data(), indices.size() * sizeof(std::uint64_t));
      for (std::uint64_t index : indices)
        if (index >= grid.count()) throw RuntimeError("distributed render: rank 0 granted a tile outside the image");
      asked = false;
      if (indices.empty()) {
        no_more = true;
        granted.finish();
      } else {
        granted.add(indices);
      }
    }
    check_leader();
  }
  render.join();
  const RayCounts rays = clock.rays();
  const DoneRecord done{clock.tiles(), rays, clock.busy_seconds(), clock.idle_seconds(),
                        bytes_sent + sizeof(DoneRecord)};
  communicator.send(0, kDone, bytes_of(done));
  // No heartbeats from here: rank 0 reads nothing more of this image once every kDone is in.
  while (true) {
    if (std::optional<Message> message = poll_leader()) {
      if (message->tag != kFinished) throw RuntimeError("distributed render: rank 0 sent an unexpected message");
      return;
    }
    check_leader();
    std::this_thread::sleep_for(kGrantPollPause);
  }
}

double load_imbalance(const std::vector<RankStats>& ranks) {
  double most = 0.0, sum = 0.0;
  for (const RankStats& r : ranks) {
    most = std::max(most, r.busy_seconds);
    sum += r.busy_seconds;
  }
  return sum > 0.0 ? most / (sum / static_cast<double>(ranks.size())) : 1.0;
}

}  // namespace rtpro
