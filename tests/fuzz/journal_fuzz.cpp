// Fuzz target: a resume journal (`OUT.rtpro-journal`) through the reader `rtpro render --resume`
// uses, for a 16x16 image in 8-pixel tiles and 3 passes, records of 23 floats a pixel (what the
// seeds were written for; the reader takes any count).
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/job/tile_journal.h"

#include <cstdint>
#include <string_view>

namespace {
constexpr int kSeedFloatsPerPixel = 23;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file =
      rtpro::fuzz::write_workspace_file("out.exr.rtpro-journal", {reinterpret_cast<const char*>(data), size});
  const rtpro::TileGrid grid({0, 0, 16, 16}, 8, 3);
  try {
    const rtpro::JournalContents contents = rtpro::read_journal(file, grid, kSeedFloatsPerPixel);
    rtpro::JobIdentity expected;
    expected.set("rtpro", "fuzz");
    (void)expected.differences(contents.identity, "the journal");
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
