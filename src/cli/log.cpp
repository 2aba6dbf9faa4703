#include "log.h"

#include "rtpro/core/printable_text.h"

#include <iostream>

namespace rtpro::cli {

void Log::info(const std::string& message) {
  if (level_ < LogLevel::kNormal) return;
  std::lock_guard lock(mutex_);
  std::cerr << "rtpro: " << printable_message(message) << "\n";
}

void Log::verbose(const std::string& message) {
  if (level_ < LogLevel::kVerbose) return;
  std::lock_guard lock(mutex_);
  std::cerr << "rtpro: " << printable_message(message) << "\n";
}

void Log::warning(const std::string& message) {
  std::lock_guard lock(mutex_);
  if (warnings_[message]++ > 0 || level_ < LogLevel::kNormal) return;
  std::cerr << "rtpro: warning: " << printable_message(message) << "\n";
}

void Log::summarise_repeats() {
  std::lock_guard lock(mutex_);
  if (level_ < LogLevel::kNormal) return;
  for (const auto& [message, count] : warnings_)
    if (count > 1)
      std::cerr << "rtpro: warning repeated " << count - 1 << " more times: " << printable_message(message) << "\n";
}

}  // namespace rtpro::cli
