#include "subdivided_mesh.h"

#include "rtpro/core/memory_budget.h"
#include "rtpro/core/printable_text.h"
#include "cage_check.h"
#include "displacement.h"
#include "subdivision_level.h"
#include "subdivision_refine.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <tuple>

namespace rtpro {

namespace {

const char* scheme_name(SubdivisionScheme scheme) {
  switch (scheme) {
    case SubdivisionScheme::kCatmullClark: return "catmull-clark";
    case SubdivisionScheme::kLoop: return "loop";
  }
  return "?";
}

ScalarImage read_displacement_image(const DisplacementDesc& desc, SubdivisionContext& context) {
  if (!context.options.read_scalar_image)
    throw InputError(desc.where, "displacement: textures cannot be read here (no image reader)");
  try {
    return context.options.read_scalar_image(desc.texture, context.budget_left);
  } catch (const InputError& e) {
    throw InputError(desc.where, "displacement: " + e.message());
  }
}

}  // namespace

PolygonCage cage_of_triangles(const TriangleMesh& mesh) {
  PolygonCage cage;
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::uint32_t> welded;
  std::vector<std::uint32_t> point_of(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const MeshVertex& v = mesh.vertices[i];
    const auto key = std::make_tuple(std::bit_cast<std::uint32_t>(v.x), std::bit_cast<std::uint32_t>(v.y),
                                     std::bit_cast<std::uint32_t>(v.z));
    const auto [it, added] = welded.try_emplace(key, std::uint32_t(cage.positions.size()));
    if (added) cage.positions.push_back(v.position());
    point_of[i] = it->second;
  }
  cage.uvs = mesh.uvs;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const TriangleIndices& tri = mesh.triangles[t];
    cage.face_sizes.push_back(3);
    for (const std::uint32_t v : {tri.v0, tri.v1, tri.v2}) {
      cage.face_vertices.push_back(point_of[v]);
      if (!mesh.uvs.empty()) cage.face_uvs.push_back(v);
    }
    if (!mesh.triangle_materials.empty()) cage.face_materials.push_back(mesh.triangle_materials[t]);
  }
  return cage;
}

TriangleMesh subdivide_cage(const PolygonCage& cage, const SubdivisionDesc& subdivision,
                            const DisplacementDesc* displacement, const std::string& file, const SourceLocation& where,
                            SubdivisionContext& context, std::vector<std::string>& warnings) {
  CheckedCage checked = check_cage(cage, subdivision, file);
  warnings.insert(warnings.end(), checked.warnings.begin(), checked.warnings.end());
  if (checked.cage.face_count() == 0)
    throw InputError(where, "subdivision: '" + printable_text(file) + "' has no faces");
  int level = subdivision.level;
  if (subdivision.edge_length > 0.0f)
    level = choose_subdivision_level(checked.cage, context.camera, subdivision.edge_length, subdivision.level);
  level = effective_subdivision_level(checked, subdivision.scheme, level);

  const std::uint64_t faces = refined_face_count(checked.cage, subdivision.scheme, level);
  const std::uint64_t bytes = saturating_multiply(faces, kBytesPerRefinedFace);
  if (bytes > context.budget_left)
    throw InputError(where, "subdivision: " + std::string(scheme_name(subdivision.scheme)) + " level " +
                                std::to_string(level) + " of '" + printable_text(file) + "' makes " +
                                std::to_string(faces) + " faces, an estimated " + format_bytes(bytes) +
                                ", more than the " + format_bytes(context.budget_left) +
                                " left of the memory budget (" + context.options.budget_source +
                                "); lower the level (or raise edge_length), or raise the budget with --max-memory MiB");
  context.budget_left -= bytes;

  RefinedMesh refined = refine_cage(checked, subdivision.scheme, level, file);
  if (displacement) {
    const ScalarImage image =
        displacement->texture.empty() ? ScalarImage{} : read_displacement_image(*displacement, context);
    displace_mesh(refined, *displacement, displacement->texture.empty() ? nullptr : &image, warnings);
  }
  return std::move(refined.mesh);
}

}  // namespace rtpro
