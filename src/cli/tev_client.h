#pragma once
// A live preview in the tev image viewer (`--display-server HOST:PORT`, as in pbrt-v4 and
// Mitsuba): the image is created when the render starts and each finished tile is sent as it
// lands, in tev's own IPC protocol (packets in tev_packets.h). The preview never stops a render:
// a viewer that is absent, stops reading for kSendTimeoutSeconds or goes away gives one warning
// and the render goes on without it.
#include "log.h"
#include "rtpro/image/image.h"
#include "rtpro/render/tiles.h"

#include <mutex>
#include <string>

namespace rtpro::cli {

// "HOST:PORT" (HOST may be a name, an IPv4 address or a bracketed IPv6 address); throws
// InputError naming --display-server otherwise.
struct DisplayServerAddress {
  std::string host, port;
};
DisplayServerAddress parse_display_server(const std::string& text);

class TevClient {
 public:
  static constexpr int kConnectTimeoutSeconds = 2;
  static constexpr int kSendTimeoutSeconds = 5;

  // Connects and creates the image `name` (R, G, B; width × height); warns through `log` and
  // stays disconnected when that fails.
  TevClient(const DisplayServerAddress& address, const std::string& name, int width, int height, Log& log);
  ~TevClient();
  TevClient(const TevClient&) = delete;
  TevClient& operator=(const TevClient&) = delete;

  // Sends the R, G, B pixels of `region` of `image`; safe to call from several threads.
  void send_tile(const Image& image, const PixelRegion& region);
  bool connected() const;

 private:
  void send_packet(const std::string& packet);  // with mutex_ held
  void drop(const std::string& why);            // with mutex_ held

  std::string where_;
  std::string name_;
  Log& log_;
  mutable std::mutex mutex_;
  int socket_ = -1;
};

}  // namespace rtpro::cli
