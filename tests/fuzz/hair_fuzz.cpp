// Fuzz target: a .hair file through the public call a scene's curves entry makes, in each basis
// (the strands become Bézier segments differently in each), and the bounds every segment gives the
// BVH builders.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/curve_geometry.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rtpro::CurvesDesc desc;
  desc.file = rtpro::fuzz::write_workspace_file("strands.hair", {reinterpret_cast<const char*>(data), size});
  desc.where = rtpro::SourceLocation{"scene.yaml", 1, 1};
  for (const rtpro::CurveBasis basis : {rtpro::CurveBasis::kLinear, rtpro::CurveBasis::kBezier,
                                        rtpro::CurveBasis::kBSpline, rtpro::CurveBasis::kCatmullRom}) {
    desc.basis = basis;
    try {
      const rtpro::CurveSet curves = rtpro::load_curves(desc);
      rtpro::bounds_of(curves);
    } catch (const rtpro::InputError&) {
      // A file refused, or strands this basis cannot take (a Bézier strand needs 3n + 1 points).
    }
  }
  return 0;
}
