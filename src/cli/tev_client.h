#pragma once
// A live preview in the tev image viewer (`--display-server HOST:PORT`, as in pbrt-v4 and
// Mitsuba): the image is created when the render starts and each finished tile is sent as it
// lands, in tev's own IPC protocol (packets in tev_packets.h). The preview never stops a render:
// the workers only queue a packet (a bounded queue: when it is full, a tile is dropped from the
// preview, never waited for) and a sender thread of its own writes them. A viewer that is absent,
// takes longer than kSendTimeoutSeconds over one packet or goes away gives one warning and the
// render goes on without it; at the end, what is still queued gets kFinishStallSeconds without
// progress before it is dropped.
#include "log.h"
#include "rtpro/image/image.h"
#include "rtpro/render/render_observer.h"
#include "rtpro/render/tiles.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

namespace rtpro::cli {

// "HOST:PORT" (HOST may be a name, an IPv4 address or a bracketed IPv6 address); throws
// InputError naming --display-server otherwise.
struct DisplayServerAddress {
  std::string host, port;
};
DisplayServerAddress parse_display_server(const std::string& text);

class TevClient final : public RenderObserver {
 public:
  static constexpr int kConnectTimeoutSeconds = 2;
  static constexpr int kSendTimeoutSeconds = 5;
  static constexpr int kFinishStallMilliseconds = 500;
  // Packets waiting for the sender; one packet is always taken, however large (a whole image).
  static constexpr std::size_t kMaxQueuedBytes = std::size_t(64) << 20;

  // Connects and creates the image `name` (R, G, B; width × height); warns through `log` and
  // stays disconnected when that fails.
  TevClient(const DisplayServerAddress& address, const std::string& name, int width, int height, Log& log);
  ~TevClient() override;
  TevClient(const TevClient&) = delete;
  TevClient& operator=(const TevClient&) = delete;

  bool wants_images() const override { return true; }
  // Queues the R, G, B pixels of `region` of `image` for the viewer, or drops them when the queue
  // is full; never waits for the viewer. Safe to call from several threads.
  void pass_image(const Image& image, const PixelRegion& region) override;
  bool connected() const;

 private:
  void send_queued();  // the sender thread
  // Writes the whole packet within kSendTimeoutSeconds (and, once the render is finishing, while
  // the viewer takes some of it every kFinishStallMilliseconds); returns why not, or nothing.
  std::string send_packet(const std::string& packet);
  void drop(const std::string& why);

  std::string where_;
  std::string name_;
  Log& log_;
  int socket_ = -1;  // used by the sender thread alone once it runs
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::string> queue_;
  std::size_t queued_bytes_ = 0;
  bool connected_ = false;
  std::atomic<bool> finishing_{false};
  std::size_t dropped_tiles_ = 0;
  std::thread sender_;
};

}  // namespace rtpro::cli
