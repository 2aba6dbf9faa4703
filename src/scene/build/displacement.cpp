#include "displacement.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

}  // namespace

float sample_scalar_image(const ScalarImage& image, float u, float v) {
  const float x = u * float(image.width) - 0.5f, y = (1.0f - v) * float(image.height) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const auto at = [&](int i, int j) {
    return image
        .values[std::size_t(wrap(j, image.height)) * std::size_t(image.width) + std::size_t(wrap(i, image.width))];
  };
  const int i = int(fx), j = int(fy);
  const float top = at(i, j) * (1.0f - tx) + at(i + 1, j) * tx;
  const float bottom = at(i, j + 1) * (1.0f - tx) + at(i + 1, j + 1) * tx;
  return top * (1.0f - ty) + bottom * ty;
}

void displace_mesh(RefinedMesh& refined, const DisplacementDesc& desc, const ScalarImage* image,
                   std::vector<std::string>& warnings) {
  TriangleMesh& mesh = refined.mesh;
  const std::size_t points = refined.surface_vertex_count;
  std::vector<float> offset(points, 0.0f);
  std::vector<std::uint32_t> copies(points, 0);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::uint32_t p = refined.surface_vertex[i];
    const float value = image && !mesh.uvs.empty() ? sample_scalar_image(*image, mesh.uvs[i].u, mesh.uvs[i].v)
                        : image                    ? sample_scalar_image(*image, 0.0f, 0.0f)
                                                   : desc.value;
    offset[p] += desc.scale * value;
    ++copies[p];
  }
  std::size_t clamped = 0;
  for (std::size_t p = 0; p < points; ++p) {
    if (copies[p] > 0) offset[p] /= float(copies[p]);
    if (desc.bound && std::abs(offset[p]) > *desc.bound) {
      offset[p] = std::copysign(*desc.bound, offset[p]);
      ++clamped;
    }
  }
  if (clamped > 0)
    warnings.push_back(desc.where.str() + ": displacement: " + std::to_string(clamped) +
                       " vertices would move beyond bound " + std::to_string(*desc.bound) + "; clamped to it");

  // Every copy of a point moves along the first copy's normal, so the copies stay together.
  std::vector<Vec3> direction(points, Vec3(0.0f));
  std::vector<bool> seen(points, false);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::uint32_t p = refined.surface_vertex[i];
    if (!seen[p]) direction[p] = mesh.normals[i];
    seen[p] = true;
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const std::uint32_t p = refined.surface_vertex[i];
    const Vec3 moved = mesh.vertex(std::uint32_t(i)) + direction[p] * offset[p];
    mesh.vertices[i] = {moved.x, moved.y, moved.z};
  }

  std::vector<Vec3> normal(points, Vec3(0.0f));
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 n = cross(mesh.vertex(t.v1) - mesh.vertex(t.v0), mesh.vertex(t.v2) - mesh.vertex(t.v0));
    for (const std::uint32_t v : {t.v0, t.v1, t.v2}) normal[refined.surface_vertex[v]] += n;
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3 n = normal[refined.surface_vertex[i]];
    const float len = length(n);
    if (len > 0.0f && std::isfinite(len)) mesh.normals[i] = n / len;
  }
}

}  // namespace rtpro
