#pragma once
// rtpro's error values. Input errors (bad scene, bad OBJ, bad options) exit with code 2,
// runtime failures (cannot write, out of memory, backend failure) with code 1.
#include <stdexcept>
#include <string>
#include <vector>

namespace rtpro {

// Where in an input file something was found. line/column are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;

  // "file:line:column", "file:line" or "file", whatever is known.
  std::string str() const;
};

// A message is one line: control characters in it (an ESC or a newline of echoed input) are shown
// escaped (core/printable_text.h), whoever built it. A message that lists things gives them as
// `details`, each on a line of its own, indented, and escaped the same way.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message);
  explicit InputError(const std::string& message);
  InputError(const std::string& message, const std::vector<std::string>& details);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

// One line, escaped as an InputError's.
class RuntimeError : public std::runtime_error {
 public:
  explicit RuntimeError(const std::string& message);
};

enum ExitCode : int { kExitOk = 0, kExitRuntimeFailure = 1, kExitInputError = 2, kExitInterrupted = 130 };

}  // namespace rtpro
