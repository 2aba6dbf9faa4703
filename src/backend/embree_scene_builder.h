#pragma once
// Turns a RenderScene into Embree scenes: one per prototype group plus the top group, whose
// instance geometries reference the prototypes. Every geometry is attached under its own index in
// its group, so Embree's geomID and instID map straight back to the RenderScene.
#include "rtpro/backend/backend.h"
#include "embree_device.h"
#include "embree_handles.h"
#include "embree_hit_ids.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <span>
#include <vector>

namespace rtpro {

struct EmbreeBuildSettings {
  RTCSceneFlags flags = static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  RTCBuildQuality quality = RTC_BUILD_QUALITY_MEDIUM;
};

// Embree's scene flags and build quality for the backend options.
EmbreeBuildSettings embree_build_settings(const BackendOptions& options);

// The flags of one group's Embree scene (`prototypes`: the groups its instances place). Robust
// traversal keeps a ray that grazes an edge from slipping between triangles, and grazing sphere
// hits the native backend's, bit for bit; a group of curves alone needs neither (the backends
// agree on curves within a tolerance), so it goes without, as Embree's own tools trace: 7% more
// rays a second on Embree's furBall_A, the same image.
RTCSceneFlags embree_group_flags(const Group& group, std::span<const Group> prototypes,
                                 const EmbreeBuildSettings& settings);

struct EmbreeScenes {
  std::vector<EmbreeScene> prototypes;
  std::vector<EmbreeScene> pieces;  // of top-level meshes built in pieces, in `hit_ids.pieces`' order
  EmbreeScene top;
  EmbreeHitIds hit_ids;
};

// Builds and commits everything: prototypes first, then the pieces of top-level meshes ordered in
// pieces (TriangleMesh::piece_triangles; each piece committed before the next is made), then the
// top scene with the instances referencing them. Triangle and sphere arrays are shared, not copied, so `scene` must outlive the
// result. Throws RuntimeError for geometry Embree would silently drop (non-finite or beyond its
// coordinate range) and for every error Embree reports.
EmbreeScenes build_embree_scenes(EmbreeDevice::Session& session, const RenderScene& scene,
                                 const EmbreeBuildSettings& settings);

}  // namespace rtpro
