#pragma once
// A mesh entry's `subdivision:` (and `displacement:`) carried out while the render scene is built:
// the cage checked, its level chosen and its memory counted against the budget before OpenSubdiv
// refines it, the refined triangles displaced.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/subdivision.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

struct SubdivisionContext {
  const CameraDesc& camera;
  const SceneBuildOptions& options;
  std::uint64_t budget_left;  // bytes; each refined mesh takes its share
};

// A triangle mesh as a cage: vertices at the same position welded into one (a file splits them
// where normals or texture coordinates differ), texture coordinates kept face-varying.
PolygonCage cage_of_triangles(const TriangleMesh& mesh);

// The refined (and displaced) surface of `cage`. Input errors name `file` (the cage's faces), or
// `where` (the entry: a level over the budget, a texture that cannot be read); warnings go to
// `warnings`.
TriangleMesh subdivide_cage(const PolygonCage& cage, const SubdivisionDesc& subdivision,
                            const DisplacementDesc* displacement, const std::string& file, const SourceLocation& where,
                            SubdivisionContext& context, std::vector<std::string>& warnings);

}  // namespace rtpro
