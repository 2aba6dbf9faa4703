#include "embree_device.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>

namespace rtpro {

namespace {

// Embree picks its kernels at run time (SSE2 … AVX-512); triangle hits differ in the last bits
// between them (FMA from AVX2 on). Capping at AVX2 gives every AVX2-or-better machine the same
// answers; older machines still run, on SSE kernels.
std::string device_config(int threads) {
  std::string config = "max_isa=avx2,verbose=0";
  if (threads > 0) config += ",threads=" + std::to_string(threads);
  return config;
}

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
  }
  return "unrecognised error";
}

std::string megabytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

}  // namespace

std::shared_ptr<EmbreeDevice> EmbreeDevice::get(int threads) {
  static std::mutex registry_mutex;
  static std::map<int, std::shared_ptr<EmbreeDevice>> registry;
  const int key = threads > 0 ? threads : 0;
  std::lock_guard<std::mutex> lock(registry_mutex);
  std::shared_ptr<EmbreeDevice>& device = registry[key];
  if (!device) device.reset(new EmbreeDevice(key));
  return device;
}

EmbreeDevice::EmbreeDevice(int threads) {
  device_ = rtcNewDevice(device_config(threads).c_str());
  if (!device_) {
    throw RuntimeError(std::string("cannot start Embree: ") + error_name(rtcGetDeviceError(nullptr)));
  }
  rtcSetDeviceErrorFunction(device_, &EmbreeDevice::record_error, this);
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeDevice::monitor_memory, this);
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

// Runs on whichever thread hit the error, possibly an Embree worker: record only, never throw.
void EmbreeDevice::record_error(void* user, RTCError code, const char* message) {
  auto* self = static_cast<EmbreeDevice*>(user);
  std::lock_guard<std::mutex> lock(self->error_mutex_);
  if (self->first_error_ != RTC_ERROR_NONE) return;
  self->first_error_ = code;
  self->first_error_message_ = message ? message : "";
}

// Called around every large allocation (bytes > 0) and free (bytes < 0), from many build threads
// at once. Returning false makes Embree abandon the build with OUT_OF_MEMORY (or CANCELLED).
bool EmbreeDevice::monitor_memory(void* user, ssize_t bytes, bool post) {
  auto* self = static_cast<EmbreeDevice*>(user);
  const std::int64_t total = self->session_bytes_.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  const std::int64_t limit = self->session_limit_.load(std::memory_order_relaxed);
  if (bytes <= 0 || limit == 0 || total <= limit) {
    std::int64_t peak = self->session_peak_.load(std::memory_order_relaxed);
    while (total > peak && !self->session_peak_.compare_exchange_weak(peak, total, std::memory_order_relaxed)) {
    }
    return true;
  }
  self->limit_exceeded_.store(true, std::memory_order_relaxed);
  // Before the allocation (post == false) cancelling means it never happens; after it, Embree
  // frees the block itself and reports that free.
  if (!post) self->session_bytes_.fetch_sub(bytes, std::memory_order_relaxed);
  return false;
}

EmbreeDevice::Session::Session(EmbreeDevice& device, std::size_t memory_limit)
    : device_(device), lock_(device.session_mutex_), memory_limit_(memory_limit) {
  device_.session_bytes_.store(0, std::memory_order_relaxed);
  device_.session_peak_.store(0, std::memory_order_relaxed);
  const std::size_t limit = std::min<std::size_t>(memory_limit, std::numeric_limits<std::int64_t>::max());
  device_.session_limit_.store(static_cast<std::int64_t>(limit), std::memory_order_relaxed);
  device_.limit_exceeded_.store(false, std::memory_order_relaxed);
  std::lock_guard<std::mutex> error_lock(device_.error_mutex_);
  device_.first_error_ = RTC_ERROR_NONE;
  device_.first_error_message_.clear();
}

void EmbreeDevice::Session::check(std::string_view operation) {
  RTCError code;
  std::string message;
  {
    std::lock_guard<std::mutex> error_lock(device_.error_mutex_);
    code = device_.first_error_;
    message.swap(device_.first_error_message_);
    device_.first_error_ = RTC_ERROR_NONE;
  }
  if (code == RTC_ERROR_NONE) return;
  const bool out_of_memory = code == RTC_ERROR_OUT_OF_MEMORY || code == RTC_ERROR_CANCELLED;
  if (out_of_memory && device_.limit_exceeded_.load(std::memory_order_relaxed)) {
    throw RuntimeError("Embree BVH build needs more than the --max-memory limit of " + megabytes(memory_limit_) +
                       " MB");
  }
  std::string text = "Embree failed during " + std::string(operation) + ": " + error_name(code);
  if (!message.empty()) text += " (" + message + ")";
  throw RuntimeError(text);
}

std::int64_t EmbreeDevice::Session::allocated_bytes() const {
  return device_.session_bytes_.load(std::memory_order_relaxed);
}

std::int64_t EmbreeDevice::Session::peak_bytes() const { return device_.session_peak_.load(std::memory_order_relaxed); }

}  // namespace rtpro
