#pragma once
// A float image with named channels (interleaved, top row first): the film's output and what the
// image writer, reader and comparison work on.
#include <cstddef>
#include <string>
#include <vector>

namespace rtpro {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels{"R", "G", "B"};
  std::vector<float> data;  // width * height * channels.size()

  Image() = default;
  Image(int w, int h, std::vector<std::string> channel_names = {"R", "G", "B"})
      : width(w), height(h), channels(std::move(channel_names)),
        data(static_cast<std::size_t>(w) * h * channels.size(), 0.0f) {}

  int channel_count() const { return static_cast<int>(channels.size()); }
  std::size_t index(int x, int y, int c) const {
    return (static_cast<std::size_t>(y) * width + x) * channels.size() + c;
  }
  float& at(int x, int y, int c) { return data[index(x, y, c)]; }
  float at(int x, int y, int c) const { return data[index(x, y, c)]; }
};

}  // namespace rtpro
