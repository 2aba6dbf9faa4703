#include "triangle_backend.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

namespace {

// The checks as branch-free passes, which the compiler vectorises: with a test and a return per
// element the dragon's 437,645 vertices and 871,414 triangles took 4 ms of one thread before its
// build. within_traceable_range's finiteness test is in its magnitude test (NaN and ∞ fail it).
bool all_within_traceable_range(const VertexArray& vertices) {
  unsigned outside = 0;
  for (const MeshVertex& v : vertices)
    outside |= static_cast<unsigned>(!(std::fabs(v.x) < kMaxTraceableMagnitude)) |
               static_cast<unsigned>(!(std::fabs(v.y) < kMaxTraceableMagnitude)) |
               static_cast<unsigned>(!(std::fabs(v.z) < kMaxTraceableMagnitude));
  return outside == 0;
}

std::uint32_t largest_index(const std::vector<TriangleIndices>& triangles) {
  std::uint32_t largest = 0;
  for (const TriangleIndices& t : triangles) largest = std::max(largest, std::max(t.v0, std::max(t.v1, t.v2)));
  return largest;
}

}  // namespace

std::optional<std::string> embree_refusal(const TriangleMesh& mesh) {
  if (!all_within_traceable_range(mesh.vertices)) return "has a vertex outside Embree's coordinate range";
  for (const VertexArray& step : mesh.vertex_steps)
    if (!all_within_traceable_range(step)) return "moves a vertex outside Embree's coordinate range";
  const std::size_t vertex_count = mesh.vertices.size();
  if (!mesh.triangles.empty() && largest_index(mesh.triangles) >= vertex_count)
    return "has a triangle index past its " + std::to_string(vertex_count) + " vertices";
  return std::nullopt;
}

// A deforming mesh of at most this many vertices goes to Embree at kEmbreeSmallMeshSteps time steps
// (new_embree_geometry): at most 9 copies of 4,096 vertices, 576 KiB.
constexpr std::size_t kEmbreeSmallMeshVertices = 4096;
constexpr unsigned kEmbreeSmallMeshSteps = 9;

// Embree's rule that a vertex buffer be readable 16 bytes past its last vertex holds for the
// shared arrays (VertexArray's allocator, mesh.h) and for buffers Embree allocates itself.
EmbreeGeometry new_embree_geometry(RTCDevice device, const TriangleMesh& mesh, RTCBuildQuality quality) {
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  if (mesh.moving() && mesh.vertex_steps.size() < kEmbreeSmallMeshSteps &&
      mesh.vertices.size() <= kEmbreeSmallMeshVertices) {
    // The same motion at kEmbreeSmallMeshSteps steps, each the mesh at that time (vertex_at's
    // interpolation; the mesh's own steps fall on the finer ones, 2, 3 and 5 steps being 1, 2 and
    // 4 segments of 8): Embree's motion builder splits a tree in time only at steps, and a small
    // mesh that deforms much within one segment otherwise sits in one node whose triangles every
    // ray gathers at both steps.
    rtcSetGeometryTimeStepCount(g, kEmbreeSmallMeshSteps);
    for (unsigned step = 0; step < kEmbreeSmallMeshSteps; ++step) {
      auto* vertices = static_cast<MeshVertex*>(rtcSetNewGeometryBuffer(
          g, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3, sizeof(MeshVertex), mesh.vertices.size()));
      if (vertices == nullptr) return EmbreeGeometry();
      const float time = static_cast<float>(step) / static_cast<float>(kEmbreeSmallMeshSteps - 1);
      for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const Vec3 p = mesh.vertex_at(v, time);
        vertices[v] = {p.x, p.y, p.z};
      }
    }
  } else if (mesh.moving()) {
    // One vertex buffer per time step; Embree interpolates them linearly, as vertex_at does.
    rtcSetGeometryTimeStepCount(g, static_cast<unsigned>(mesh.vertex_steps.size()));
    for (unsigned step = 0; step < mesh.vertex_steps.size(); ++step)
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3, mesh.vertex_steps[step].data(), 0,
                                 sizeof(MeshVertex), mesh.vertex_steps[step].size());
  } else {
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                               sizeof(MeshVertex), mesh.vertices.size());
  }
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(), 0,
                             sizeof(TriangleIndices), mesh.triangles.size());
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

EmbreeGeometry new_embree_piece(RTCDevice device, const TriangleMesh& mesh, std::uint32_t first_triangle,
                                std::uint32_t triangle_count, RTCBuildQuality quality) {
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                             sizeof(MeshVertex), mesh.vertices.size());
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(),
                             std::size_t{first_triangle} * sizeof(TriangleIndices), sizeof(TriangleIndices),
                             triangle_count);
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

}  // namespace rtpro
