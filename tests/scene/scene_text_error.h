#pragma once
// For the scene module's YAML tests: a scene text's parse error and where it points.
#include "rtpro/core/error.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::test {

// Two lines; test documents add their own lines from line 3.
inline const std::string kHeader =
    "rtpro: 1\n"
    "camera: {position: [0, 1, -5], look_at: [0, 0, 0]}\n";

struct Position {
  int line;
  int column;
};

// The 1-based position of `token` on `line` of `text`, so tests say what an error points at
// rather than counting columns.
inline Position at(const std::string& text, int line, const std::string& token) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::string line_text = text.substr(start, text.find('\n', start) - start);
  const std::size_t column = line_text.find(token);
  EXPECT_NE(column, std::string::npos) << "'" << token << "' is not on line " << line;
  return {line, static_cast<int>(column) + 1};
}

// The InputError parsing `text` (as test.yaml) throws; a test failure when it parses.
inline InputError parse_error(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene_text(text, "test.yaml", overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("(none)");
}

inline void check_error(const std::string& text, Position expected, const std::vector<std::string>& fragments) {
  const InputError error = parse_error(text);
  EXPECT_EQ(error.where().file, "test.yaml");
  EXPECT_EQ(error.where().line, expected.line) << error.what();
  EXPECT_EQ(error.where().column, expected.column) << error.what();
  for (const std::string& fragment : fragments)
    EXPECT_NE(error.message().find(fragment), std::string::npos) << "'" << fragment << "' not in: " << error.what();
}

// Expects parsing `text` to fail at `position` with a message holding every one of the fragments.
#define EXPECT_SCENE_ERROR(text, position, ...) \
  do {                                          \
    SCOPED_TRACE("expected error");             \
    check_error(text, position, __VA_ARGS__);   \
  } while (false)

inline std::string with_world(const std::string& world_lines) { return kHeader + "world:\n" + world_lines; }

inline std::string camera_scene(const std::string& camera) { return "rtpro: 1\ncamera: " + camera + "\n"; }

}  // namespace rtpro::test
