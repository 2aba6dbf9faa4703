#include "triangle_backend.h"

#include <string>

namespace rtpro {

std::optional<std::string> embree_refusal(const TriangleMesh& mesh) {
  for (const PaddedVertex& v : mesh.vertices) {
    if (!within_traceable_range(v.position())) return "has a vertex outside Embree's coordinate range";
  }
  for (const std::vector<PaddedVertex>& step : mesh.vertex_steps)
    for (const PaddedVertex& v : step)
      if (!within_traceable_range(v.position())) return "moves a vertex outside Embree's coordinate range";
  const std::size_t vertex_count = mesh.vertices.size();
  for (const TriangleIndices& t : mesh.triangles) {
    if (t.v0 >= vertex_count || t.v1 >= vertex_count || t.v2 >= vertex_count)
      return "has a triangle index past its " + std::to_string(vertex_count) + " vertices";
  }
  return std::nullopt;
}

// A 16-byte vertex stride (x, y, z, pad) keeps Embree's rule that vertex buffers are readable 16
// bytes past the last vertex.
EmbreeGeometry new_embree_geometry(RTCDevice device, const TriangleMesh& mesh, RTCBuildQuality quality) {
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  if (mesh.moving()) {
    // One vertex buffer per time step; Embree interpolates them linearly, as vertex_at does.
    rtcSetGeometryTimeStepCount(g, static_cast<unsigned>(mesh.vertex_steps.size()));
    for (unsigned step = 0; step < mesh.vertex_steps.size(); ++step)
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3, mesh.vertex_steps[step].data(), 0,
                                 sizeof(PaddedVertex), mesh.vertex_steps[step].size());
  } else {
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.vertices.data(), 0,
                               sizeof(PaddedVertex), mesh.vertices.size());
  }
  rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(), 0,
                             sizeof(TriangleIndices), mesh.triangles.size());
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

}  // namespace rtpro
