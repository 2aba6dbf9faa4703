// --display-server against a small server in the suite that speaks tev's IPC protocol (as tev's
// src/Ipc.cpp reads it) and reassembles the image from the tiles it receives.
#include "rtpro/image/image_io.h"
#include "sphere_on_floor.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace rtpro {
namespace display_server_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::rtpro_command;
using test::run_command;
using test::run_rtpro;

// Reads fields the way tev's IpcPacket::IStream does.
class PacketReader {
 public:
  explicit PacketReader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T number() {
    if (at_ + sizeof(T) > bytes_.size()) throw std::runtime_error("packet too short");
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  bool boolean() { return number<char>() == 1; }
  std::string text() {
    const std::size_t end = bytes_.find('\0', at_);
    if (end == std::string_view::npos) throw std::runtime_error("unterminated string");
    std::string value(bytes_.substr(at_, end - at_));
    at_ = end + 1;
    return value;
  }
  std::size_t remaining() const { return bytes_.size() - at_; }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

struct ReceivedImage {
  std::string name;
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> rgb;   // width * height * 3
  std::vector<int> writes;  // per pixel: how many tiles wrote it
  int creates = 0, updates = 0;
};

// A socket listening on a free port of 127.0.0.1; `port` is set to it.
int listen_on_loopback(int& port) {
  const int listener = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || listen(listener, 1) != 0)
    throw std::runtime_error("cannot listen");
  socklen_t length = sizeof address;
  getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
  port = ntohs(address.sin_port);
  return listener;
}

// A tev stand-in on 127.0.0.1 at an ephemeral port; serves one connection. With
// close_after_accept it hangs up at once, a viewer that goes away mid-render.
class TevTestServer {
 public:
  explicit TevTestServer(bool close_after_accept = false) {
    listener_ = listen_on_loopback(port_);
    thread_ = std::thread([this, close_after_accept] { serve(close_after_accept); });
  }
  ~TevTestServer() {
    shutdown(listener_, SHUT_RDWR);
    close(listener_);
    if (thread_.joinable()) thread_.join();
  }
  int port() const { return port_; }
  // After the client has disconnected.
  const ReceivedImage& image() {
    thread_.join();
    if (!error_.empty()) throw std::runtime_error(error_);
    return image_;
  }

 private:
  void serve(bool close_after_accept) {
    const int client = accept(listener_, nullptr, nullptr);
    if (client < 0) return;
    if (close_after_accept) {
      close(client);
      return;
    }
    std::string bytes;
    char chunk[65536];
    ssize_t got;
    while ((got = read(client, chunk, sizeof chunk)) > 0) bytes.append(chunk, static_cast<std::size_t>(got));
    close(client);
    try {
      parse(bytes);
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }

  void parse(std::string_view bytes) {
    while (!bytes.empty()) {
      std::uint32_t size;
      if (bytes.size() < 4) throw std::runtime_error("truncated size");
      std::memcpy(&size, bytes.data(), 4);
      if (size < 5 || size > bytes.size()) throw std::runtime_error("bad packet size");
      PacketReader packet(bytes.substr(4, size - 4));
      bytes.remove_prefix(size);
      const char type = packet.number<char>();
      if (type == 4) {
        packet.boolean();
        image_.name = packet.text();
        image_.width = packet.number<std::int32_t>();
        image_.height = packet.number<std::int32_t>();
        const int channels = packet.number<std::int32_t>();
        for (int c = 0; c < channels; ++c) image_.channels.push_back(packet.text());
        image_.rgb.assign(static_cast<std::size_t>(image_.width) * image_.height * 3, -1.0f);
        image_.writes.assign(static_cast<std::size_t>(image_.width) * image_.height, 0);
        ++image_.creates;
      } else if (type == 6) {
        packet.boolean();
        if (packet.text() != image_.name) throw std::runtime_error("update for another image");
        const int channels = packet.number<std::int32_t>();
        if (channels != 3) throw std::runtime_error("expected 3 channels");
        for (int c = 0; c < channels; ++c) packet.text();
        const int x0 = packet.number<std::int32_t>(), y0 = packet.number<std::int32_t>();
        const int width = packet.number<std::int32_t>(), height = packet.number<std::int32_t>();
        std::int64_t offsets[3], strides[3];
        for (auto& offset : offsets) offset = packet.number<std::int64_t>();
        for (auto& stride : strides) stride = packet.number<std::int64_t>();
        std::vector<float> data(packet.remaining() / sizeof(float));
        for (float& value : data) value = packet.number<float>();
        for (int p = 0; p < width * height; ++p) {
          const int x = x0 + p % width, y = y0 + p / width;
          if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) throw std::runtime_error("tile outside");
          ++image_.writes[static_cast<std::size_t>(y) * image_.width + x];
          for (int c = 0; c < 3; ++c) {
            const auto index = static_cast<std::size_t>(offsets[c] + p * strides[c]);
            if (index >= data.size()) throw std::runtime_error("pixel data short");
            image_.rgb[(static_cast<std::size_t>(y) * image_.width + x) * 3 + c] = data[index];
          }
        }
        ++image_.updates;
      } else {
        throw std::runtime_error("unexpected packet type " + std::to_string(type));
      }
    }
  }

  int listener_ = -1;
  int port_ = 0;
  std::thread thread_;
  ReceivedImage image_;
  std::string error_;
};

// The viewer gets each tile of the first pass as it finishes (12: 30x20 in 8x8 tiles), then the
// whole image after each pass: one pass for Whitted's stratified samples, four (1, 1, 2 and 4
// samples) for the path integrator's Sobol samples at 8 spp; the last is the image written.
void expect_every_pass_and_the_written_image(const std::string& options, int passes) {
  const auto scene = test::write_file("scene.yaml", test::sphere_on_floor_scene(30, 20));
  const auto output = scene.parent_path() / "preview.exr";
  TevTestServer server;
  std::string out =
      run_rtpro(render_args(scene, output) + " " + options +
                    " --tile-size 8 --progress never --display-server 127.0.0.1:" + std::to_string(server.port()),
                0);
  EXPECT_EQ(out.find("warning"), std::string::npos) << out;
  const ReceivedImage& received = server.image();
  EXPECT_EQ(received.creates, 1);
  EXPECT_EQ(received.name, "preview.exr");
  EXPECT_EQ(received.channels, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(received.updates, 12 + passes);
  for (int writes : received.writes) ASSERT_EQ(writes, 1 + passes);
  const Image written = read_image(output);
  ASSERT_EQ(written.width, received.width);
  ASSERT_EQ(written.height, received.height);
  ASSERT_EQ(written.channel_count(), 3);
  EXPECT_EQ(written.data, received.rgb);
}

TEST(DisplayServer, ViewerReceivesTheOnePassOfAStratifiedRenderAndTheWrittenImage) {
  expect_every_pass_and_the_written_image("", 1);
}

TEST(DisplayServer, ViewerReceivesEveryPassOfAProgressiveRenderAndTheWrittenImage) {
  expect_every_pass_and_the_written_image("--integrator path --spp 8", 4);
}

TEST(DisplayServer, AbsentViewerWarnsAndTheRenderGoesOn) {
  int port = 0;
  {
    TevTestServer probe;  // a port that was free a moment ago, and is closed again
    port = probe.port();
  }
  const auto scene = test::write_file("scene.yaml", test::sphere_on_floor_scene(16, 12));
  const auto output = scene.parent_path() / "alone.exr";
  expect_rtpro_answer(
      render_args(scene, output) + " --progress never" + " --display-server 127.0.0.1:" + std::to_string(port), 0,
      "no live preview: cannot reach the display server at 127.0.0.1:");
  EXPECT_TRUE(std::filesystem::exists(output));
}

TEST(DisplayServer, ViewerThatGoesAwayWarnsOnceAndTheRenderGoesOn) {
  const auto scene = test::write_file("scene.yaml", test::sphere_on_floor_scene(160, 120));
  const auto output = scene.parent_path() / "gone.exr";
  TevTestServer server(true);
  std::string out =
      run_rtpro(render_args(scene, output) +
                    " --tile-size 4 --progress never --display-server 127.0.0.1:" + std::to_string(server.port()),
                0);
  const std::string warning = "live preview stopped: the display server at 127.0.0.1:";
  EXPECT_NE(out.find(warning), std::string::npos) << out;
  EXPECT_EQ(out.find(warning), out.rfind(warning)) << out;
  const Image written = read_image(output);
  EXPECT_EQ(written.width, 160);
}

// A viewer that accepts the connection and then never reads a byte (hung, or stopped in a
// debugger): rtpro's packets fill the socket's buffers and every further send would wait.
class SilentTevServer {
 public:
  SilentTevServer() {
    listener_ = listen_on_loopback(port_);
    thread_ = std::thread([this] { client_ = accept(listener_, nullptr, nullptr); });
  }
  ~SilentTevServer() {
    shutdown(listener_, SHUT_RDWR);
    thread_.join();
    if (client_ >= 0) close(client_);
    close(listener_);
  }
  int port() const { return port_; }

 private:
  int listener_ = -1, port_ = 0;
  int client_ = -1;
  std::thread thread_;
};

// Issue 28: a viewer that accepts and stops reading held a 0.4 s render for 16-21 s (each
// partial send restarted the 5 s timeout, and the workers waited on the preview's lock). The
// preview must cost tiles of the preview, not render time: 1.5 MB of tiles and 1.5 MB for each of
// the 4 passes' images fill the socket's buffers, and the render still ends near its time alone.
TEST(DisplayServer, ViewerThatNeverReadsDoesNotHoldTheRender) {
  const auto scene = test::write_file("scene.yaml", test::sphere_on_floor_scene(360, 360));
  const auto dir = scene.parent_path();
  const std::string args = " --integrator path --spp 8 --tile-size 16 --progress never";
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  ASSERT_EQ(run_command(rtpro_command(render_args(scene, dir / "alone.exr") + args)), 0);
  const double alone = std::chrono::duration<double>(Clock::now() - start).count();

  SilentTevServer server;
  std::string out;
  start = Clock::now();
  out = run_rtpro(
      render_args(scene, dir / "previewed.exr") + args + " --display-server 127.0.0.1:" + std::to_string(server.port()),
      0);
  const double previewed = std::chrono::duration<double>(Clock::now() - start).count();
  EXPECT_LT(previewed, alone + 2.0) << "alone " << alone << " s, with a viewer that never reads " << previewed << " s";
  const std::string warning = "live preview stopped: the display server at 127.0.0.1:";
  EXPECT_NE(out.find(warning), std::string::npos) << out;
  EXPECT_EQ(out.find(warning), out.rfind(warning)) << out;
  EXPECT_EQ(read_image(dir / "alone.exr").data, read_image(dir / "previewed.exr").data);
}

}  // namespace display_server_test
}  // namespace rtpro
