// The tile scheduler without MPI: ranks are threads of this process talking through mailboxes,
// so every hand-out order the scheduler allows is exercised under the sanitizers too.
#include "rtpro/distributed/distributed_render.h"

#include "rtpro/backend/backend.h"
#include "rtpro/core/error.h"
#include "rtpro/distributed/distributed_tile_executor.h"
#include "rtpro/render/renderer.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

namespace rtpro {
namespace distributed_render_test {

// Mailboxes of every rank of an in-process job; messages between two ranks stay in order.
struct Mailboxes {
  explicit Mailboxes(int ranks) : boxes(static_cast<std::size_t>(ranks)) {}
  std::mutex mutex;
  std::vector<std::deque<Message>> boxes;
  std::uint64_t bytes = 0;
};

class ThreadCommunicator final : public Communicator {
 public:
  ThreadCommunicator(Mailboxes& mail, int rank) : mail_(mail), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return static_cast<int>(mail_.boxes.size()); }
  void send(int destination, int tag, std::span<const std::byte> bytes) override {
    const std::lock_guard lock(mail_.mutex);
    mail_.boxes[std::size_t(destination)].push_back({rank_, tag, {bytes.begin(), bytes.end()}});
    mail_.bytes += bytes.size();
  }
  std::optional<Message> poll() override {
    const std::lock_guard lock(mail_.mutex);
    auto& box = mail_.boxes[std::size_t(rank_)];
    if (box.empty()) return std::nullopt;
    Message message = std::move(box.front());
    box.pop_front();
    return message;
  }
  [[noreturn]] void abort(int) override { std::abort(); }

 private:
  Mailboxes& mail_;
  int rank_;
};

RenderScene test_scene() {
  RenderScene scene = test::random_mixed_scene(5, 200, 200, 6);
  test::set_camera(scene, 45, 31);
  scene.render.spp = 4;
  return scene;
}

struct JobResult {
  RenderResult image;
  std::vector<RankStats> ranks;
};

JobResult render_as_job(const RenderScene& scene, const Backend& backend, int ranks, int tile_size) {
  Mailboxes mail(ranks);
  RenderOptions options;
  options.tile_size = tile_size;
  options.aovs = {Aov::kAlbedo, Aov::kDepth};
  const TileGrid grid = render_grid(scene, checked_region(scene, options), tile_size);
  JobResult result;
  std::vector<std::thread> followers;
  for (int rank = 1; rank < ranks; ++rank)
    followers.emplace_back([&, rank] {
      ThreadCommunicator communicator(mail, rank);
      const TileRenderer renderer(scene, backend, grid, render_sums(options));
      follow_distributed_render(communicator, renderer, grid, 1);
    });
  ThreadCommunicator leader(mail, 0);
  DistributedTileExecutor executor(leader);
  options.tile_executor = &executor;
  result.image = render_image(scene, backend, options);
  result.ranks = executor.ranks();
  for (auto& follower : followers) follower.join();
  return result;
}

// test_scene with its instances moving during an open shutter: each turns and travels, so every
// sample's time (a sampler dimension) decides what its rays meet.
void set_moving(RenderScene& scene) {
  scene.camera.shutter = {0.0f, 1.0f};
  for (Geometry& geometry : scene.top.geometries)
    if (auto* instance = std::get_if<Instance>(&geometry))
      instance->object_to_world_steps = {instance->object_to_world,
                                         compose(Affine::translate({0.4f, 0.2f, 0.0f}),
                                                 compose(instance->object_to_world, Affine::rotate({0, 1, 0}, 20))),
                                         compose(Affine::translate({0.8f, 0.0f, 0.0f}), instance->object_to_world)};
}

// Whitted with stratified samples renders in one pass; the path integrator with Sobol samples in
// passes of 1, 1, 2 and 4 samples, which ranks render ahead of the film's merging. Each also with
// motion blur (`moving`).
struct Case {
  Integrator integrator;
  bool moving;
};
class DistributedRenderScenes : public ::testing::TestWithParam<Case> {};

TEST_P(DistributedRenderScenes, ImageIsBitIdenticalForAnyRankCountAndTileSize) {
  RenderScene scene = test_scene();
  if (GetParam().integrator == Integrator::kPath) {
    scene.render.integrator = Integrator::kPath;
    scene.render.sampler = SamplerKind::kSobol;
    scene.render.spp = 8;
  }
  if (GetParam().moving) set_moving(scene);
  ASSERT_EQ(render_passes(scene).passes(), GetParam().integrator == Integrator::kPath ? 4 : 1);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  RenderOptions options;
  options.aovs = {Aov::kAlbedo, Aov::kDepth};
  options.tile_size = 8;
  const RenderResult alone = render_image(scene, *backend, options);
  if (GetParam().moving) {
    RenderScene still = scene;
    still.camera.shutter = {};
    const auto still_backend = make_backend(BackendKind::kNative, still, {});
    const RenderResult unblurred = render_image(still, *still_backend, options);
    ASSERT_NE(
        std::memcmp(unblurred.image.data.data(), alone.image.data.data(), alone.image.data.size() * sizeof(float)), 0)
        << "the shutter blurs";
  }
  // A moving scene's tile sizes and rank counts are fewer: its rays go one by one.
  const std::vector<int> rank_counts = GetParam().moving ? std::vector{1, 3} : std::vector{1, 2, 3, 4};
  for (int ranks : rank_counts)
    for (int tile_size : {8, 5}) {
      SCOPED_TRACE(std::to_string(ranks) + " ranks, tiles of " + std::to_string(tile_size));
      const JobResult job = render_as_job(scene, *backend, ranks, tile_size);
      ASSERT_TRUE(job.image.complete());
      ASSERT_EQ(job.image.image.data.size(), alone.image.data.size());
      EXPECT_EQ(
          std::memcmp(job.image.image.data.data(), alone.image.data.data(), alone.image.data.size() * sizeof(float)),
          0);
      EXPECT_EQ(job.image.rays.total(), alone.rays.total());
      ASSERT_EQ(job.ranks.size(), std::size_t(ranks));
      std::uint64_t tiles = 0, rays = 0;
      for (const RankStats& r : job.ranks) {
        tiles += r.tiles;
        rays += r.rays.total();
        EXPECT_GE(r.busy_seconds, 0.0);
      }
      EXPECT_EQ(tiles, job.image.tiles_total);
      EXPECT_EQ(rays, alone.rays.total());
      for (std::size_t r = 1; r < job.ranks.size(); ++r)
        if (job.ranks[r].tiles > 0) {
          EXPECT_GT(job.ranks[r].bytes_sent, 0u);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, DistributedRenderScenes,
                         ::testing::Values(Case{Integrator::kWhitted, false}, Case{Integrator::kPath, false},
                                           Case{Integrator::kWhitted, true}, Case{Integrator::kPath, true}));

TEST(DistributedRender, HandshakeNamesTheRankAndWhatDiffers) {
  Mailboxes mail(3);
  JobIdentity ours;
  ours.set("rtpro", "1");
  ours.set("mesh dragon.ply", "aaaa");
  JobIdentity theirs = ours;
  theirs.set("mesh dragon.ply", "bbbb");
  std::thread same([&] {
    ThreadCommunicator c(mail, 1);
    agree_on_job(c, ours);
  });
  std::thread other([&] {
    ThreadCommunicator c(mail, 2);
    const std::string text = theirs.text();
    c.send(0, 1, std::as_bytes(std::span(text)));  // its hello, without waiting for the verdict
  });
  ThreadCommunicator leader(mail, 0);
  try {
    agree_on_job(leader, ours);
    FAIL() << "a rank with another mesh was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("rank 2"), std::string::npos) << message;
    EXPECT_NE(message.find("mesh dragon.ply: aaaa here, bbbb in rank 2"), std::string::npos) << message;
  }
  other.join();
  // Rank 1 waits for a verdict that never comes (in a real job MPI_Abort ends it): release it.
  leader.send(1, 2, {});
  same.join();
}

// A rank that never reaches the start of the job (stopped, hung, or loading for ever) held every
// other rank in the handshake for ever: rank 0 now names it once the rank timeout has passed, and
// a rank waiting on a silent rank 0 says so.
TEST(DistributedRender, HandshakeNamesASilentRankAfterTheRankTimeout) {
  Mailboxes mail(3);
  JobIdentity ours;
  ours.set("rtpro", "1");
  std::thread talking([&] {
    ThreadCommunicator c(mail, 1);
    const std::string text = ours.text();
    c.send(0, 1, std::as_bytes(std::span(text)));  // its hello; rank 2 never sends one
  });
  talking.join();
  ThreadCommunicator leader(mail, 0);
  const auto started = std::chrono::steady_clock::now();
  try {
    agree_on_job(leader, ours, std::chrono::milliseconds(200));
    FAIL() << "the handshake ended without rank 2";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("rank 2 did not reach the start of the job"), std::string::npos) << message;
    EXPECT_EQ(message.find("rank 1"), std::string::npos) << message;
  }
  EXPECT_GE(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(200));

  Mailboxes alone(2);
  ThreadCommunicator follower(alone, 1);
  try {
    agree_on_job(follower, ours, std::chrono::milliseconds(100));
    FAIL() << "a follower accepted a job rank 0 never answered";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("rank 0 did not answer the handshake within"), std::string::npos) << e.what();
  }
}

// A rank whose every message reaches the others `delay` late: a slow link, or a node under load.
class SlowCommunicator final : public Communicator {
 public:
  SlowCommunicator(Communicator& inner, std::chrono::milliseconds delay) : inner_(inner), delay_(delay) {}
  int rank() const override { return inner_.rank(); }
  int size() const override { return inner_.size(); }
  void send(int destination, int tag, std::span<const std::byte> bytes) override {
    std::this_thread::sleep_for(delay_);
    inner_.send(destination, tag, bytes);
  }
  std::optional<Message> poll() override { return inner_.poll(); }
  [[noreturn]] void abort(int code) override {
    inner_.abort(code);
    std::terminate();  // the inner communicator's abort does not return either
  }

 private:
  Communicator& inner_;
  std::chrono::milliseconds delay_;
};

// Issue 28: `mpirun -n 3 ... --frames 1-3` failed in frame 1 with "rank N sent an unexpected
// message": a follower that finished its frame sent the next frame's hello while rank 0 still
// waited for the other follower's last message of this one. Here rank 2's messages are late, so
// rank 1 always finishes first; every frame must still come out whole.
TEST(DistributedRender, FramesFollowEachOtherWhenOneRankIsLate) {
  RenderScene scene = test::random_mixed_scene(3, 32, 24, 6);
  test::set_camera(scene, 45, 31);
  scene.render.spp = 1;
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  RenderOptions options;
  options.tile_size = 8;
  const RenderResult alone = render_image(scene, *backend, options);
  const TileGrid grid = render_grid(scene, checked_region(scene, options), options.tile_size);
  JobIdentity identity;
  identity.set("rtpro", "test");
  constexpr int kFrames = 3;
  Mailboxes mail(3);
  std::vector<std::thread> followers;
  for (int rank = 1; rank < 3; ++rank)
    followers.emplace_back([&, rank] {
      ThreadCommunicator direct(mail, rank);
      SlowCommunicator slow(direct, std::chrono::milliseconds(rank == 2 ? 20 : 0));
      const TileRenderer renderer(scene, *backend, grid, render_sums(options));
      for (int frame = 0; frame < kFrames; ++frame) {
        agree_on_job(slow, identity);
        follow_distributed_render(slow, renderer, grid, 1);
      }
    });
  ThreadCommunicator leader(mail, 0);
  DistributedTileExecutor executor(leader);
  options.tile_executor = &executor;
  for (int frame = 0; frame < kFrames; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    agree_on_job(leader, identity);
    const RenderResult result = render_image(scene, *backend, options);
    ASSERT_TRUE(result.complete());
    EXPECT_EQ(std::memcmp(result.image.data.data(), alone.image.data.data(), alone.image.data.size() * sizeof(float)),
              0);
  }
  for (auto& follower : followers) follower.join();
}

// Issue 28: a stopped or unreachable rank held the whole job for ever. Rank 2 here never says a
// word: rank 0 ends the render naming it once the rank timeout has passed, after its own workers
// finish (rank 1's tiles and rank 0's reach the sink, as they reach the journal).
TEST(DistributedRender, SilentRankEndsTheRenderAfterTheRankTimeout) {
  RenderScene scene = test::random_mixed_scene(3, 32, 24, 6);
  test::set_camera(scene, 45, 31);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  RenderOptions options;
  options.tile_size = 8;
  const TileGrid grid = render_grid(scene, checked_region(scene, options), options.tile_size);
  Mailboxes mail(3);
  std::thread follower([&] {
    ThreadCommunicator communicator(mail, 1);
    const TileRenderer renderer(scene, *backend, grid, render_sums(options));
    try {
      follow_distributed_render(communicator, renderer, grid, 1, nullptr, std::chrono::milliseconds(1000));
    } catch (const RuntimeError&) {
      // rank 0 went quiet once it gave up: in a real job its MPI_Abort ends this rank first
    }
  });
  ThreadCommunicator leader(mail, 0);
  DistributedTileExecutor executor(leader, nullptr, std::chrono::milliseconds(1000));
  options.tile_executor = &executor;
  const auto start = std::chrono::steady_clock::now();
  try {
    render_image(scene, *backend, options);
    ADD_FAILURE() << "the render waited for a silent rank and finished";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("rank 2 sent nothing for"), std::string::npos) << message;
    EXPECT_NE(message.find("--rank-timeout 1"), std::string::npos) << message;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(seconds, 0.9);
  EXPECT_LT(seconds, 5.0);
  follower.join();
}

// The other way round: rank 0 answers once and then goes silent (stopped); the follower ends.
TEST(DistributedRender, FollowerEndsWhenRankZeroFallsSilent) {
  RenderScene scene = test::random_mixed_scene(3, 32, 24, 6);
  test::set_camera(scene, 45, 31);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const TileGrid grid = render_grid(scene, checked_region(scene, RenderOptions{}), 8);
  Mailboxes mail(2);
  ThreadCommunicator leader(mail, 0);
  const std::vector<std::uint64_t> one_tile{0};
  leader.send(1, 4, std::as_bytes(std::span(one_tile)));  // a grant, then nothing more
  ThreadCommunicator communicator(mail, 1);
  const TileRenderer renderer(scene, *backend, grid, render_sums(RenderOptions{}));
  const auto start = std::chrono::steady_clock::now();
  try {
    follow_distributed_render(communicator, renderer, grid, 1, nullptr, std::chrono::milliseconds(1000));
    ADD_FAILURE() << "the follower waited for a silent rank 0 and returned";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("rank 0 sent nothing for"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(DistributedRender, LoadImbalanceIsBusiestOverMean) {
  std::vector<RankStats> ranks(2);
  ranks[0].busy_seconds = 3.0;
  ranks[1].busy_seconds = 1.0;
  EXPECT_DOUBLE_EQ(load_imbalance(ranks), 1.5);
  ranks[1].busy_seconds = 3.0;
  EXPECT_DOUBLE_EQ(load_imbalance(ranks), 1.0);
}

}  // namespace distributed_render_test
}  // namespace rtpro
