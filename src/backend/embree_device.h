#pragma once
// The Embree device: one per process and build-thread count, created on first use and kept for
// the life of the process. Embree reports errors through a callback that may run on its worker
// threads, and allocations through a memory-monitor callback; both are only recorded here, and
// a Session turns them into rtpro errors on the thread that made the API call.
#include <embree3/rtcore.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace rtpro {

class EmbreeDevice {
 public:
  // The device for `threads` build threads (0: all cores). Thread-safe. Throws RuntimeError when
  // Embree cannot start (e.g. an unsupported CPU).
  static std::shared_ptr<EmbreeDevice> get(int threads);

  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice handle() const { return device_; }

  // Exclusive use of the device for creating, committing and releasing scenes. Sessions are
  // serialised, so every error and every byte Embree reports during one belongs to it: builds of
  // backends on different threads never see each other's failures or allocations.
  class Session {
   public:
    // `memory_limit`: how many bytes Embree may allocate during the session (0: no limit).
    Session(EmbreeDevice& device, std::size_t memory_limit);
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    // Throws RuntimeError for the first error Embree reported since the previous check;
    // `operation` says what was being done (e.g. "commit of the top-level scene").
    void check(std::string_view operation);
    // Net bytes Embree allocated since the session started, and the most it held at once.
    std::int64_t allocated_bytes() const;
    std::int64_t peak_bytes() const;
    RTCDevice device() const { return device_.handle(); }

   private:
    EmbreeDevice& device_;
    std::lock_guard<std::mutex> lock_;
    std::size_t memory_limit_;
  };

 private:
  explicit EmbreeDevice(int threads);
  static void record_error(void* device, RTCError code, const char* message);
  static bool monitor_memory(void* device, ssize_t bytes, bool post);

  RTCDevice device_ = nullptr;
  std::mutex session_mutex_;

  std::mutex error_mutex_;
  RTCError first_error_ = RTC_ERROR_NONE;
  std::string first_error_message_;

  std::atomic<std::int64_t> session_bytes_{0};
  std::atomic<std::int64_t> session_peak_{0};
  std::atomic<std::int64_t> session_limit_{0};  // 0: unlimited
  std::atomic<bool> limit_exceeded_{false};
};

}  // namespace rtpro
