// Curves on the scene's side: Cem Yuksel's .hair files (read, and refused when hostile), strands
// turned into segments of each basis, and `type: curves` entries in a scene file.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/curve_basis.h"
#include "rtpro/scene/curve_geometry.h"
#include "scene_text_error.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rtpro::test {
namespace curve_geometry_test {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// A .hair file: the header (flags: segments, points, thickness, colour), then the arrays.
struct HairSpec {
  std::uint32_t strands = 2, points = 7, arrays = 1 | 2 | 4 | 16;
  std::vector<std::uint16_t> segments = {2, 3};
  float thickness = 0.02f;
  std::size_t cut = 0;  // bytes dropped from the end
};

std::string hair_bytes(const HairSpec& spec) {
  std::string out = "HAIR";
  for (std::uint32_t v : {spec.strands, spec.points, spec.arrays, 1u}) put(out, v);
  for (float v : {0.01f, 1.0f, 0.5f, 0.5f, 0.5f}) put(out, v);
  out.append(88, ' ');
  if (spec.arrays & 1)
    for (std::uint16_t s : spec.segments) put(out, s);
  for (std::uint32_t i = 0; i < spec.points; ++i)
    for (float c : {float(i), 0.5f * float(i), 0.0f}) put(out, c);
  if (spec.arrays & 4)
    for (std::uint32_t i = 0; i < spec.points; ++i) put(out, spec.thickness);
  if (spec.arrays & 16)
    for (std::uint32_t i = 0; i < spec.points; ++i)
      for (float c : {0.1f, 0.2f, 0.3f}) put(out, c);
  out.resize(out.size() - spec.cut);
  return out;
}

CurvesDesc hair_entry(const HairSpec& spec, CurveBasis basis = CurveBasis::kCatmullRom) {
  CurvesDesc desc;
  desc.file = write_file("fur.hair", hair_bytes(spec));
  desc.basis = basis;
  return desc;
}

TEST(HairFile, ReadsStrandsThicknessAndColour) {
  const CurveSet curves = load_curves(hair_entry({}));
  // Catmull–Rom: each strand's ends repeated once, a segment per pair of its points.
  EXPECT_EQ(curves.segments.size(), 2u + 3u);
  EXPECT_EQ(curves.points.size(), 7u + 4u);
  EXPECT_FLOAT_EQ(curves.points[0].radius, 0.01f);
  ASSERT_EQ(curves.colors.size(), curves.points.size());
  EXPECT_FLOAT_EQ(curves.colors[4].z, 0.3f);
  // The curve passes through every point of the file: segment 0 starts at point 0 and ends at 1.
  const BezierSegment first = bezier_segment(curves, 0);
  EXPECT_FLOAT_EQ(first.at(0.0f).position.x, 0.0f);
  EXPECT_FLOAT_EQ(first.at(1.0f).position.x, 1.0f);
  const BezierSegment last = bezier_segment(curves, 4);
  EXPECT_FLOAT_EQ(last.at(1.0f).position.x, 6.0f);
}

TEST(HairFile, StrandsBecomeSegmentsOfEachBasis) {
  EXPECT_EQ(load_curves(hair_entry({}, CurveBasis::kLinear)).segments.size(), 5u);
  EXPECT_EQ(load_curves(hair_entry({}, CurveBasis::kBSpline)).segments.size(), 2u + 3u);
  // A B-spline strand, given a phantom point past each end, starts and ends at them, leaving them
  // along the strand (p1 − p0 per unit of u), not with the zero tangent of an end repeated thrice,
  // which Embree's round curves cannot sweep a circle along.
  const CurveSet bspline = load_curves(hair_entry({}, CurveBasis::kBSpline));
  const BezierSegment first = bezier_segment(bspline, 0), last = bezier_segment(bspline, 4);
  EXPECT_NEAR(first.at(0.0f).position.x, 0.0f, 1e-6f);
  EXPECT_NEAR(last.at(1.0f).position.x, 6.0f, 1e-5f);
  EXPECT_NEAR(first.derivative(0.0f).x, 1.0f, 1e-5f);
  EXPECT_NEAR(first.derivative(0.0f).y, 0.5f, 1e-5f);
  EXPECT_NEAR(last.derivative(1.0f).x, 1.0f, 1e-5f);
  EXPECT_NEAR(first.at(0.0f).radius, 0.01f, 1e-8f);
  HairSpec bezier;
  bezier.strands = 1;
  bezier.segments = {6};
  EXPECT_EQ(load_curves(hair_entry(bezier, CurveBasis::kBezier)).segments.size(), 2u);
}

// The error load_curves throws for the file, which must name the file.
std::string hair_error(const HairSpec& spec) {
  try {
    load_curves(hair_entry(spec));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fur.hair"), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(HairFile, RefusesHostileFilesNamingTheProblem) {
  HairSpec truncated;
  truncated.cut = 5;
  EXPECT_NE(hair_error(truncated).find("truncated"), std::string::npos);
  for (const float thickness : {0.0f, -0.5f, std::numeric_limits<float>::quiet_NaN()}) {
    HairSpec bad;
    bad.thickness = thickness;
    EXPECT_NE(hair_error(bad).find("thickness"), std::string::npos);
  }
  HairSpec mismatch;
  mismatch.segments = {2, 2};
  EXPECT_NE(hair_error(mismatch).find("points"), std::string::npos);
}

// A header claiming 10^9 strands and points in a file of a few hundred bytes: refused from its
// size before anything is allocated.
TEST(HairFile, RefusesAHeaderClaimingABillionSegments) {
  std::string bytes = hair_bytes({});
  const std::uint32_t billion = 1000000000u;
  std::memcpy(bytes.data() + 4, &billion, 4);  // strands
  std::memcpy(bytes.data() + 8, &billion, 4);  // points
  CurvesDesc desc;
  desc.file = write_file("fur.hair", bytes);
  try {
    load_curves(desc);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
}

TEST(CurvesEntry, ReadsInlinePointsRadiiAndStrands) {
  const SceneDescription scene = parse_scene_text(
      with_world("  - {type: curves, points: [[0, 0, 0], [0, 1, 0], [1, 1, 0], [2, 0, 0], [2, 1, 0]],\n"
                 "     radius: [0.1, 0.1, 0.05, 0.1, 0.02], strands: [3, 2], basis: linear, shape: flat}\n"),
      "test.yaml");
  ASSERT_EQ(scene.world.curves.size(), 1u);
  const CurveSet curves = load_curves(scene.world.curves[0]);
  EXPECT_EQ(curves.segments.size(), 3u);
  EXPECT_EQ(curves.shape, CurveShape::kFlat);
  EXPECT_FLOAT_EQ(curves.points[2].radius, 0.05f);
}

TEST(CurvesEntry, RefusesBadValuesWithTheirPlace) {
  const std::string strands =
      with_world("  - {type: curves, points: [[0, 0, 0], [0, 1, 0], [1, 1, 0]], strands: [2, 2]}\n");
  EXPECT_SCENE_ERROR(strands, at(strands, 4, "[2, 2]"), {"curves.strands", "add up to the 3 points"});
  const std::string radius = with_world("  - {type: curves, points: [[0, 0, 0], [0, 1, 0]], radius: [0.1]}\n");
  EXPECT_SCENE_ERROR(radius, at(radius, 4, "[0.1]"), {"curves.radius", "one radius per point"});
  const std::string zero = with_world("  - {type: curves, points: [[0, 0, 0], [0, 1, 0]], radius: 0}\n");
  EXPECT_SCENE_ERROR(zero, at(zero, 4, "0}"), {"curves.radius must be > 0"});
  const std::string basis = with_world("  - {type: curves, points: [[0, 0, 0], [0, 1, 0]], basis: nurbs}\n");
  EXPECT_SCENE_ERROR(basis, at(basis, 4, "nurbs"), {"curves.basis", "catmull-rom"});
  const std::string missing = with_world("  - {type: curves, file: none.hair}\n");
  EXPECT_SCENE_ERROR(missing, at(missing, 4, "none.hair"), {"hair file 'none.hair' not found"});
}

TEST(CurvesEntry, EmittingCurvesAreRefused) {
  const SceneDescription scene =
      parse_scene_text(kHeader + "materials:\n  glow: {emission: [1, 1, 1]}\nworld:\n" +
                           "  - {type: curves, points: [[0, 0, 0], [0, 1, 0]], material: glow}\n",
                       "test.yaml");
  try {
    build_render_scene(scene);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curves cannot emit light"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().line, 6);
  }
}

// The hostile files through the command line: a truncated file, a negative thickness and a
// header claiming 10^9 segments (a strand of the default segment count) each end the render with
// exit status 2 and the file named, writing no image.
TEST(CurvesEntry, ABadHairFileEndsTheRenderWithExitTwo) {
  const std::filesystem::path output = scratch_dir() / "fur.png";
  HairSpec truncated;
  truncated.cut = 9;
  HairSpec negative;
  negative.thickness = -0.01f;
  std::string billion = hair_bytes({});
  const std::uint32_t no_segments_array = 2 | 4 | 16, segments = 1000000000u;
  std::memcpy(billion.data() + 12, &no_segments_array, 4);
  std::memcpy(billion.data() + 16, &segments, 4);
  const std::pair<std::string, std::string> cases[] = {
      {hair_bytes(truncated), "truncated"}, {hair_bytes(negative), "thickness"}, {billion, "strands already need"}};
  for (const auto& [bytes, problem] : cases) {
    write_file("fur.hair", bytes);
    const auto scene = write_file("fur.yaml", kHeader + "world:\n  - {type: curves, file: fur.hair}\n");
    const std::string out = run_rtpro(render_args(scene, output, "--size 8x8 --spp 1"), 2);
    EXPECT_NE(out.find("fur.hair"), std::string::npos) << out;
    EXPECT_NE(out.find(problem), std::string::npos) << out;
    EXPECT_FALSE(std::filesystem::exists(output));
  }
}

}  // namespace curve_geometry_test
}  // namespace rtpro::test
