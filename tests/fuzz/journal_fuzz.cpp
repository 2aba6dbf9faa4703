// Fuzz target: a resume journal (`OUT.rtpro-journal`) through the reader `rtpro render --resume`
// uses, for a 64x48 image in 16-pixel tiles with 3 channels (what the seeds were written for).
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/job/tile_journal.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file =
      rtpro::fuzz::write_workspace_file("out.exr.rtpro-journal", {reinterpret_cast<const char*>(data), size});
  const rtpro::TileGrid grid({0, 0, 64, 48}, 16);
  try {
    const rtpro::JournalContents contents = rtpro::read_journal(file, grid, 3);
    rtpro::JobIdentity expected;
    expected.set("rtpro", "fuzz");
    (void)expected.differences(contents.identity, "the journal");
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
