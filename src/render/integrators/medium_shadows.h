#pragma once
// Shadow rays in a scene with media: what each lets through, the product of the transmittances of
// the media it crosses (ratio tracking, render/media/medium_tracking.h), through index-matched
// interfaces and the objects that do not cast its light's shadows (light linking), up to the
// first surface that blocks it (0) or its end. pbrt-v4's TraceTransmittance, hit by hit.
#include "path_integrator.h"
#include "rtpro/backend/backend.h"
#include "rtpro/scene/render_scene.h"

#include <span>

namespace rtpro {

// transmitted[i] for rays[i], which starts as starts[i] says.
// `times`: per ray, its time under an open shutter; empty otherwise.
void medium_shadow_transmittance(const Backend& backend, const RenderScene& scene, std::span<const Ray> rays,
                                 std::span<const float> times, std::span<const PathWorkspace::MediumShadow> starts,
                                 std::span<Color> transmitted);

}  // namespace rtpro
