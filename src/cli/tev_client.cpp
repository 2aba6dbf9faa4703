#include "tev_client.h"

#include "rtpro/core/error.h"
#include "tev_packets.h"

#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace rtpro::cli {

namespace {

const char* const kChannels[] = {"R", "G", "B"};

std::string create_image_packet(const std::string& name, int width, int height) {
  tev::PacketWriter packet(tev::kCreateImage);
  packet.boolean(true).text(name).number<std::int32_t>(width).number<std::int32_t>(height).number<std::int32_t>(3);
  for (const char* channel : kChannels) packet.text(channel);
  return packet.finish();
}

std::string update_image_packet(const std::string& name, const Image& image, const PixelRegion& region) {
  tev::PacketWriter packet(tev::kUpdateImageV3);
  packet.boolean(false).text(name).number<std::int32_t>(3);
  for (const char* channel : kChannels) packet.text(channel);
  packet.number<std::int32_t>(region.x0).number<std::int32_t>(region.y0);
  packet.number<std::int32_t>(region.width()).number<std::int32_t>(region.height());
  for (std::int64_t c = 0; c < 3; ++c) packet.number<std::int64_t>(c);  // interleaved RGB:
  for (int c = 0; c < 3; ++c) packet.number<std::int64_t>(3);           // offset c, stride 3
  std::vector<float> rgb;
  rgb.reserve(static_cast<std::size_t>(region.width()) * region.height() * 3);
  for (int y = region.y0; y < region.y1; ++y)
    for (int x = region.x0; x < region.x1; ++x)
      for (int c = 0; c < 3; ++c) rgb.push_back(image.at(x, y, c));
  return packet.floats(rgb).finish();
}

// A connected TCP socket, or -1 with `error` set; gives up after `timeout_seconds`.
int connect_with_timeout(const DisplayServerAddress& address, int timeout_seconds, std::string& error) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int code = getaddrinfo(address.host.c_str(), address.port.c_str(), &hints, &found); code != 0) {
    error = gai_strerror(code);
    return -1;
  }
  int connected = -1;
  error = "no address";
  for (addrinfo* candidate = found; candidate && connected < 0; candidate = candidate->ai_next) {
    const int fd =
        socket(candidate->ai_family, candidate->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, candidate->ai_protocol);
    if (fd < 0) continue;
    int result = connect(fd, candidate->ai_addr, candidate->ai_addrlen);
    if (result != 0 && errno == EINPROGRESS) {
      pollfd wait{fd, POLLOUT, 0};
      result = poll(&wait, 1, timeout_seconds * 1000) == 1 ? 0 : -1;
      if (result != 0) errno = ETIMEDOUT;
      int socket_error = 0;
      socklen_t length = sizeof socket_error;
      if (result == 0 && getsockopt(fd, SOL_SOCKET, SO_ERROR, &socket_error, &length) == 0 && socket_error != 0) {
        result = -1;
        errno = socket_error;
      }
    }
    if (result == 0) {
      connected = fd;
    } else {
      error = std::strerror(errno);
      close(fd);
    }
  }
  freeaddrinfo(found);
  return connected;  // non-blocking: send_packet waits with poll, against its deadline
}

}  // namespace

DisplayServerAddress parse_display_server(const std::string& text) {
  const std::size_t colon = text.rfind(':');
  DisplayServerAddress address;
  if (colon != std::string::npos) {
    address.host = text.substr(0, colon);
    address.port = text.substr(colon + 1);
  }
  if (address.host.size() > 2 && address.host.front() == '[' && address.host.back() == ']')
    address.host = address.host.substr(1, address.host.size() - 2);
  const bool digits = !address.port.empty() && address.port.size() <= 5 &&
                      address.port.find_first_not_of("0123456789") == std::string::npos;
  if (address.host.empty() || !digits || std::stoi(address.port) < 1 || std::stoi(address.port) > 65535)
    throw InputError("--display-server '" + text + "': expected HOST:PORT of a running tev, e.g. localhost:14158");
  return address;
}

TevClient::TevClient(const DisplayServerAddress& address, const std::string& name, int width, int height, Log& log)
    : where_(address.host + ":" + address.port), name_(name), log_(log) {
  std::string error;
  socket_ = connect_with_timeout(address, kConnectTimeoutSeconds, error);
  if (socket_ < 0) {
    log_.warning("no live preview: cannot reach the display server at " + where_ + " (" + error +
                 "); rendering without it");
    return;
  }
  connected_ = true;
  queue_.push_back(create_image_packet(name_, width, height));
  queued_bytes_ = queue_.back().size();
  sender_ = std::thread([this] { send_queued(); });
}

TevClient::~TevClient() {
  if (sender_.joinable()) {
    {
      const std::lock_guard lock(mutex_);
      finishing_ = true;
    }
    changed_.notify_one();
    sender_.join();
  }
  if (socket_ >= 0) close(socket_);
  if (dropped_tiles_ > 0)
    log_.verbose("live preview: " + std::to_string(dropped_tiles_) +
                 " tile updates were dropped while the display server was slower than the render");
}

bool TevClient::connected() const {
  const std::lock_guard lock(mutex_);
  return connected_;
}

void TevClient::pass_image(const Image& image, const PixelRegion& region) {
  {
    const std::lock_guard lock(mutex_);
    if (!connected_) return;
  }
  std::string packet = update_image_packet(name_, image, region);
  {
    const std::lock_guard lock(mutex_);
    if (!connected_) return;
    if (!queue_.empty() && queued_bytes_ + packet.size() > kMaxQueuedBytes) {
      ++dropped_tiles_;
      return;
    }
    queued_bytes_ += packet.size();
    queue_.push_back(std::move(packet));
  }
  changed_.notify_one();
}

void TevClient::send_queued() {
  while (true) {
    std::string packet;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || finishing_; });
      if (queue_.empty()) return;
      packet = std::move(queue_.front());
      queue_.pop_front();
      queued_bytes_ -= packet.size();
    }
    if (const std::string why = send_packet(packet); !why.empty()) {
      drop(why);
      return;
    }
  }
}

std::string TevClient::send_packet(const std::string& packet) {
  using Clock = std::chrono::steady_clock;
  // One deadline for the whole packet: a viewer that takes a byte now and then must not hold
  // the sender (and the end of the render) for kSendTimeoutSeconds per byte.
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(kSendTimeoutSeconds);
  Clock::time_point progress = Clock::now();
  std::size_t sent = 0;
  while (sent < packet.size()) {
    const ssize_t got = send(socket_, packet.data() + sent, packet.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (got > 0) {
      sent += static_cast<std::size_t>(got);
      progress = Clock::now();
      continue;
    }
    if (got < 0 && errno == EINTR) continue;
    if (got == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) return std::strerror(errno);
    const Clock::time_point now = Clock::now();
    if (now >= deadline || (finishing_ && now - progress >= std::chrono::milliseconds(kFinishStallMilliseconds)))
      return "it stopped reading";
    // In slices, so that the end of the render is noticed while the viewer holds a packet.
    pollfd writable{socket_, POLLOUT, 0};
    poll(&writable, 1, 50);
  }
  return {};
}

void TevClient::drop(const std::string& why) {
  log_.warning("live preview stopped: the display server at " + where_ + " went away (" + why +
               "); the render goes on");
  const std::lock_guard lock(mutex_);
  connected_ = false;
  queue_.clear();
  queued_bytes_ = 0;
}

}  // namespace rtpro::cli
