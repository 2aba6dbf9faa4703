#include "rtpro/core/error.h"

#include "rtpro/core/printable_text.h"

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
  const std::string prefix = printable_message(where.str());
  return prefix.empty() ? message : prefix + ": " + message;
}

std::string with_details(const std::string& message, const std::vector<std::string>& details) {
  std::string text = printable_message(message);
  for (const std::string& line : details) text += "\n  " + printable_message(line);
  return text;
}
}  // namespace

InputError::InputError(SourceLocation where, const std::string& message)
    : std::runtime_error(located(where, printable_message(message))), where_(std::move(where)),
      message_(printable_message(message)) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(printable_message(message)), message_(printable_message(message)) {}

InputError::InputError(const std::string& message, const std::vector<std::string>& details)
    : std::runtime_error(with_details(message, details)), message_(with_details(message, details)) {}

RuntimeError::RuntimeError(const std::string& message) : std::runtime_error(printable_message(message)) {}

}  // namespace rtpro
