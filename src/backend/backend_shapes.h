#pragma once
// The kinds of shape the backends trace, registered: each kind's backend side is one header
// (native_hit, native_hit_lanes, embree_refusal, new_embree_geometry, hits_decided_by_rtpro: see
// sphere_backend.h). A new kind of shape is its header's include here; the native traversal, the
// Embree scene builder and the Embree backend then name whatever it still lacks.
#include "sphere_backend.h"
#include "triangle_backend.h"
