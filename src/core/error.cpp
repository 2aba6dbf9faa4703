#include "rtpro/core/error.h"

namespace rtpro {

std::string SourceLocation::str() const {
  std::string text = file;
  if (line > 0) {
    text.append(":").append(std::to_string(line));
    if (column > 0) text.append(":").append(std::to_string(column));
  }
  return text;
}

namespace {
std::string located(const SourceLocation& where, const std::string& message) {
  const std::string prefix = where.str();
  return prefix.empty() ? message : prefix + ": " + message;
}
}  // namespace

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(located(where, message)), where_(std::move(where)), message_(message) {}

InputError::InputError(const std::string& message) : std::runtime_error(message), message_(message) {}

}  // namespace rtpro
