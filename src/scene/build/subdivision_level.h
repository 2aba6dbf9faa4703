#pragma once
// The level an `edge_length:` asks for: the smallest at which the cage's longest edge, as the
// camera sees it, is refined below that many pixels.
#include "rtpro/scene/description.h"
#include "rtpro/scene/subdivision.h"

namespace rtpro {

// Each refinement halves an edge. An edge of length L whose nearer end is at distance z from the
// camera spans L / (z · 2·tan(fov/2) / height) pixels (z at least L, so an edge through the camera
// counts as filling a view); the level is ceil(log2(longest span / edge_length)), from 0 to `cap`.
// Edges are measured in the mesh's own space: a world mesh as placed, a mesh inside an object as
// if that object were placed without a transform.
int choose_subdivision_level(const PolygonCage& cage, const CameraDesc& camera, float edge_length, int cap);

}  // namespace rtpro
