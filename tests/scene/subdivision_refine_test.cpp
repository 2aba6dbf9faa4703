#include "cage_check.h"
#include "obj_parser.h"
#include "subdivided_mesh.h"
#include "subdivision_level.h"
#include "subdivision_refine.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rtpro {
namespace subdivision_refine_test {

// A unit cube (side 1, centred on the origin), faces wound outwards, vertices numbered from 0.
PolygonCage unit_cube() {
  PolygonCage cage;
  for (int i = 0; i < 8; ++i)
    cage.positions.push_back({(i & 1) ? 0.5f : -0.5f, (i & 2) ? 0.5f : -0.5f, (i & 4) ? 0.5f : -0.5f});
  const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    cage.face_sizes.push_back(4);
    cage.face_vertices.insert(cage.face_vertices.end(), f, f + 4);
  }
  return cage;
}

float distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection 5.1.5: the closest point by Voronoi region.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(p - a);
  const Vec3 bp = p - b;
  const float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(p - b);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + ab * (d1 / (d1 - d3))));
  const Vec3 cp = p - c;
  const float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(p - c);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + ac * (d2 / (d2 - d6))));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  const float denom = 1.0f / (va + vb + vc);
  return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

float distance_to_mesh(const Vec3& p, const TriangleMesh& mesh) {
  float best = INFINITY;
  for (const TriangleIndices& t : mesh.triangles)
    best = std::min(best, distance_to_triangle(p, mesh.vertex(t.v0), mesh.vertex(t.v1), mesh.vertex(t.v2)));
  return best;
}

SubdivisionDesc catmull_clark(int level) {
  SubdivisionDesc desc;
  desc.level = level;
  return desc;
}

TEST(SubdivisionRefine, CubeAtLevel5LiesWithin1e3OfTheLimitSurface) {
  const SubdivisionDesc desc = catmull_clark(5);
  const CheckedCage cage = check_cage(unit_cube(), desc, "cube.obj");
  const TriangleMesh mesh = refine_cage(cage, desc.scheme, 5, "cube.obj").mesh;
  EXPECT_EQ(mesh.triangles.size(), 6u * 1024u * 2u);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<LimitSample> samples;
  for (int i = 0; i < 120; ++i) samples.push_back({std::uint32_t(i % 6), uniform(rng), uniform(rng)});
  const std::vector<LimitPoint> limit = evaluate_limit_surface(cage, desc.scheme, samples);
  float worst = 0.0f;
  for (const LimitPoint& p : limit) worst = std::max(worst, distance_to_mesh(p.position, mesh));
  EXPECT_LT(worst, 1e-3f);
  // The refined vertices are limit points themselves, with the limit normal.
  const LimitPoint corner = evaluate_limit_surface(cage, desc.scheme, std::vector<LimitSample>{{0, 0.0f, 0.0f}})[0];
  const auto nearest = std::min_element(mesh.vertices.begin(), mesh.vertices.end(), [&](auto& a, auto& b) {
    return length(a.position() - corner.position) < length(b.position() - corner.position);
  });
  EXPECT_LT(length(nearest->position() - corner.position), 1e-5f);
  EXPECT_GT(std::abs(dot(mesh.normals[std::size_t(nearest - mesh.vertices.begin())], corner.normal)), 0.9999f);
}

TEST(SubdivisionRefine, LimitNormalsPointOutOfAClosedCage) {
  const TriangleMesh mesh = refine_cage(check_cage(unit_cube(), catmull_clark(2), "c"), {}, 2, "c").mesh;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) EXPECT_GT(dot(mesh.normals[i], mesh.vertex(i)), 0.0f) << i;
}

float largest_coordinate(const TriangleMesh& mesh) {
  float m = 0.0f;
  for (const MeshVertex& v : mesh.vertices) m = std::max({m, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return m;
}

TEST(SubdivisionRefine, InfinitelySharpCreasesKeepTheCageEdges) {
  SubdivisionDesc desc = catmull_clark(3);
  const TriangleMesh smooth = refine_cage(check_cage(unit_cube(), desc, "c"), desc.scheme, 3, "c").mesh;
  const std::uint32_t edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                      {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& e : edges) desc.creases.push_back({e[0], e[1], 10.0f, {}});
  const TriangleMesh sharp = refine_cage(check_cage(unit_cube(), desc, "c"), desc.scheme, 3, "c").mesh;
  EXPECT_LT(largest_coordinate(smooth), 0.45f);
  EXPECT_FLOAT_EQ(largest_coordinate(sharp), 0.5f);
  // A point halfway along the cage edge between vertices 0 and 1 stays on that edge.
  const Vec3 middle(0.0f, -0.5f, -0.5f);
  float nearest = INFINITY;
  for (const MeshVertex& v : sharp.vertices) nearest = std::min(nearest, length(v.position() - middle));
  EXPECT_LT(nearest, 1e-6f);
}

TEST(SubdivisionRefine, ASemiSharpCornerPullsTheSurfaceTowardsIt) {
  SubdivisionDesc desc = catmull_clark(3);
  const auto reach = [&](const SubdivisionDesc& d) {
    const TriangleMesh mesh = refine_cage(check_cage(unit_cube(), d, "c"), d.scheme, 3, "c").mesh;
    float r = 0.0f;
    for (const MeshVertex& v : mesh.vertices) r = std::max(r, v.x + v.y + v.z);
    return r;
  };
  const float smooth = reach(desc);
  desc.corners.push_back({7, 10.0f, {}});
  EXPECT_FLOAT_EQ(reach(desc), 1.5f);  // the corner (0.5, 0.5, 0.5) itself
  EXPECT_LT(smooth, 1.3f);
}

TEST(SubdivisionRefine, ObjQuadsAreKeptAsTheCage) {
  const auto file = test::write_file("quads.obj",
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                     "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nf 2/1 5/2 6/3 3/4\n");
  const LoadedMesh loaded = load_obj_file(file, MeshLoadOptions{NormalsMode::kAuto, true});
  ASSERT_TRUE(loaded.cage);
  EXPECT_EQ(loaded.cage->face_sizes, (std::vector<std::uint32_t>{4, 4}));
  EXPECT_EQ(loaded.cage->face_vertices, (std::vector<std::uint32_t>{0, 1, 2, 3, 1, 4, 5, 2}));
  EXPECT_EQ(loaded.cage->face_uvs, (std::vector<std::uint32_t>{0, 1, 2, 3, 0, 1, 2, 3}));
  EXPECT_EQ(loaded.mesh.triangles.size(), 4u);  // the triangulated mesh is still there
  // The uv seam between the two quads splits vertices, but the surface stays one piece.
  const RefinedMesh refined = refine_cage(check_cage(*loaded.cage, catmull_clark(2), "q"), {}, 2, "q");
  EXPECT_GT(refined.mesh.vertices.size(), refined.surface_vertex_count);
  EXPECT_EQ(refined.mesh.uvs.size(), refined.mesh.vertices.size());
}

TEST(SubdivisionRefine, BadCagesAreInputErrorsNamingTheFace) {
  PolygonCage fan = unit_cube();  // a seventh face on edge 0-1: three faces share it
  fan.positions.push_back({0.0f, -1.0f, -1.0f});
  fan.face_sizes.push_back(3);
  fan.face_vertices.insert(fan.face_vertices.end(), {0, 1, 8});
  EXPECT_NE(test::error_message_of<InputError>([&] { check_cage(fan, catmull_clark(1), "fan.obj"); }).find("face 7"),
            std::string::npos);
  PolygonCage flipped = unit_cube();
  std::reverse(flipped.face_vertices.begin(), flipped.face_vertices.begin() + 4);
  EXPECT_NE(test::error_message_of<InputError>([&] {
              check_cage(flipped, catmull_clark(1), "f.obj");
            }).find("wind consistently"),
            std::string::npos);
  SubdivisionDesc desc = catmull_clark(1);
  desc.creases.push_back({0, 99, 2.0f, {"s.yaml", 3, 5}});
  EXPECT_NE(test::error_message_of<InputError>([&] { check_cage(unit_cube(), desc, "c.obj"); }).find("out of range"),
            std::string::npos);
  desc.creases = {{0, 7, 2.0f, {"s.yaml", 3, 5}}};
  EXPECT_NE(test::error_message_of<InputError>([&] { check_cage(unit_cube(), desc, "c.obj"); }).find("share no edge"),
            std::string::npos);
  desc = catmull_clark(1);
  desc.scheme = SubdivisionScheme::kLoop;
  EXPECT_NE(test::error_message_of<InputError>([&] { check_cage(unit_cube(), desc, "c.obj"); }).find("Loop"),
            std::string::npos);
}

TEST(SubdivisionRefine, DegenerateFacesAreLeftOutWithAWarning) {
  PolygonCage cage = unit_cube();
  cage.face_sizes.push_back(3);
  cage.face_vertices.insert(cage.face_vertices.end(), {0, 0, 1});
  const CheckedCage checked = check_cage(cage, catmull_clark(1), "d.obj");
  EXPECT_EQ(checked.cage.face_count(), 6u);
  ASSERT_EQ(checked.warnings.size(), 1u);
  EXPECT_NE(checked.warnings[0].find("face 7"), std::string::npos);
}

TEST(SubdivisionRefine, ALevelBeyondTheMemoryBudgetIsRefusedBeforeRefining) {
  const CameraDesc camera;
  const SceneBuildOptions options;
  SubdivisionContext context{camera, options, 1u << 20};
  std::vector<std::string> warnings;
  const std::string message = test::error_message_of<InputError>([&] {
    subdivide_cage(unit_cube(), catmull_clark(10), nullptr, "cube.obj", {"s.yaml", 4, 3}, context, warnings);
  });
  EXPECT_NE(message.find("s.yaml:4:3"), std::string::npos) << message;
  EXPECT_NE(message.find("level 10"), std::string::npos) << message;
  EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
}

TEST(SubdivisionRefine, EdgeLengthChoosesTheLevelFromTheProjectedCage) {
  CameraDesc camera;  // at (0, 0, -5), 45 degrees over 480 pixels: the unit cube's edges span ~100 px
  const int near = choose_subdivision_level(unit_cube(), camera, 2.0f, 12);
  camera.position = {0.0f, 0.0f, -50.0f};
  const int far = choose_subdivision_level(unit_cube(), camera, 2.0f, 12);
  EXPECT_EQ(near - far, 3);  // ten times farther: 2^3.3 times fewer pixels
  EXPECT_EQ(choose_subdivision_level(unit_cube(), camera, 2.0f, 2), 2);
  EXPECT_EQ(choose_subdivision_level(unit_cube(), camera, 1000.0f, 12), 0);
}

}  // namespace subdivision_refine_test
}  // namespace rtpro
