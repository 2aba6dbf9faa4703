#pragma once
// Frame sequences: --frames FIRST-LAST[:STEP] renders each frame to an output whose run of '#'
// becomes the zero-padded frame number (out_####.exr → out_0001.exr), with the scene variable
// `frame` set to the frame (so keyframed values and $frame follow it). A frame of a sequence is
// exactly the image `-D frame=N` renders alone.
#include <string>
#include <vector>

namespace rtpro::cli {

struct FrameRange {
  long first = 1, last = 1, step = 1;
  std::vector<long> frames() const;
};

// Throws InputError naming --frames for anything but FIRST-LAST[:STEP] or N, FIRST <= LAST,
// STEP from 1 to the largest frame number, and at most kMaxFrames frames.
FrameRange parse_frame_range(const std::string& text);

// Whether `output` holds a run of '#' (a frame number pattern).
bool has_frame_pattern(const std::string& output);
// `output` with its last run of '#' replaced by `frame`, zero-padded to the run's length.
std::string numbered_output(const std::string& output, long frame);

}  // namespace rtpro::cli
