#pragma once
// One notion of valid geometry for both backends, checked when the render scene is built: every
// top-level geometry and every placed instance lies strictly within ±kMaxTraceableMagnitude, and
// every ray that can arise in the scene stays within that range when an instance carries it into
// its object space. Debian's Embree aborts the process (an assertion) on a ray beyond ~1.8e18 and
// silently drops primitives beyond it; the native backend would render them. Refusing here, with
// the scene file's line and column, makes both backends answer the same input error.
#include "geometry_origin.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/render_scene.h"

#include <span>

namespace rtpro {

// The largest coordinate's magnitude; infinity when one is not finite (what each light kind's
// reach_from_origin measures with).
double largest_magnitude(const Vec3& v);

// `origins[g]` is where scene.top.geometries[g] came from. Throws InputError there.
void check_traceable_range(const RenderScene& scene, std::span<const GeometryOrigin> origins, const CameraDesc& camera,
                           const std::vector<LightDesc>& lights);

}  // namespace rtpro
