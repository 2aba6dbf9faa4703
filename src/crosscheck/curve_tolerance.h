#pragma once
// How far the backends' curve surfaces may differ, and where a ray meets a curve so nearly at its
// silhouette that one backend may hit it and the other not. Embree intersects its exact round
// tubes and its own ray-facing quads; the native backend straight pieces of the curve (see
// src/backend/curve_intersect.h and docs/backends.md, which states the tolerance).
#include "rtpro/core/ray.h"
#include "rtpro/backend/hit.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>

namespace rtpro {

// The two surfaces of a segment lie within this fraction of its largest radius of each other:
// round tubes (the native pieces' chord error is 1% of it), and flat ribbons, whose quads Embree
// turns about the curve's direction at their corners where the native ribbons turn about each
// piece's chord.
inline constexpr double kRoundCurveTolerance = 0.05;
inline constexpr double kFlatCurveTolerance = 0.25;

// The distance (in the segment's own space) within which both backends' hits on the segment agree.
double curve_surface_tolerance(const CurveSet& curves, std::uint32_t prim);

// Whether `ray` (in the segment's space) passes within curve_surface_tolerance of the segment's
// silhouette, starts inside its tube or within two radii of it, passes where flat pieces meet, or passes through a strand's end (which Embree leaves open
// on cubic curves and the native pieces close with a sphere).
bool grazes_curve(const CurveSet& curves, std::uint32_t prim, const Ray& ray);

// The ray in the space of the hit's geometry (an instance's object space, `stretch` set to how far
// that space's distances grow at most on the way to the world's).
Ray object_ray(const RenderScene& scene, const Hit& hit, const Ray& ray, double* stretch = nullptr);

// How far apart (in world units) the backends may put a hit on the curve segment `hit` names: its
// curve_surface_tolerance carried to the world; 0 for any other shape or ids that name nothing.
double curve_allowance(const RenderScene& scene, const Hit& hit);

}  // namespace rtpro
