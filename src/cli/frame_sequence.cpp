#include "frame_sequence.h"

#include "rtpro/core/error.h"

#include <charconv>
#include <string>

namespace rtpro::cli {

namespace {

constexpr long kMaxFrames = 1000000;
constexpr long kMaxFrameNumber = 99999999;

bool parse_number(std::string_view text, long& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

}  // namespace

std::vector<long> FrameRange::frames() const {
  std::vector<long> list;
  for (long frame = first; frame <= last; frame += step) list.push_back(frame);
  return list;
}

FrameRange parse_frame_range(const std::string& text) {
  const std::string usage = "--frames '" + text + "': expected FIRST-LAST[:STEP] or one frame, e.g. 1-240 or 1-240:10";
  std::string_view rest(text);
  FrameRange range;
  const std::size_t colon = rest.find(':');
  if (colon != std::string_view::npos) {
    if (!parse_number(rest.substr(colon + 1), range.step)) throw InputError(usage);
    rest = rest.substr(0, colon);
  }
  const std::size_t dash = rest.find('-', 1);  // a leading '-' is a sign
  if (dash == std::string_view::npos) {
    if (!parse_number(rest, range.first)) throw InputError(usage);
    range.last = range.first;
  } else if (!parse_number(rest.substr(0, dash), range.first) || !parse_number(rest.substr(dash + 1), range.last)) {
    throw InputError(usage);
  }
  if (range.step < 1) throw InputError("--frames '" + text + "': the step must be at least 1");
  // A longer step never reaches a second frame, and stepping past the last frame would overflow.
  if (range.step > kMaxFrameNumber)
    throw InputError("--frames '" + text + "': the step must be at most " + std::to_string(kMaxFrameNumber));
  if (range.first < 0 || range.last > kMaxFrameNumber)
    throw InputError("--frames '" + text + "': frame numbers go from 0 to " + std::to_string(kMaxFrameNumber));
  if (range.first > range.last) throw InputError("--frames '" + text + "': the first frame is after the last");
  if ((range.last - range.first) / range.step + 1 > kMaxFrames)
    throw InputError("--frames '" + text + "': more than " + std::to_string(kMaxFrames) + " frames");
  return range;
}

bool has_frame_pattern(const std::string& output) { return output.find('#') != std::string::npos; }

std::string numbered_output(const std::string& output, long frame) {
  const std::size_t end = output.rfind('#');
  if (end == std::string::npos) return output;
  std::size_t begin = end;
  while (begin > 0 && output[begin - 1] == '#') --begin;
  // Padded to the run's length however long it is, so a long run is never cut short and every
  // frame of a 40-'#' pattern writes a file of its own.
  const std::string digits = std::to_string(frame);
  const std::size_t width = end - begin + 1;
  const std::string padded = digits.size() < width ? std::string(width - digits.size(), '0') + digits : digits;
  return output.substr(0, begin) + padded + output.substr(end + 1);
}

}  // namespace rtpro::cli
