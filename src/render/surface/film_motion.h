#pragma once
// The motion AOV's source: how a camera ray's hit moves on the film during the shutter, the
// surface point (its place on its sphere, triangle or curve) followed through its instance's,
// sphere's or mesh's time steps and seen by the camera at its pose then (scene/motion.h).
#include "rtpro/backend/hit.h"
#include "rtpro/render/sample_result.h"
#include "rtpro/scene/render_scene.h"

namespace rtpro {

// The film motion of hit `hit`, seen by a camera ray at ray time `time` at world point `position`:
// measured between the shutter's open, centre and close and scaled to pixels per frame. Zero with
// a closed shutter (the scene holds no motion then) and where the point is behind the camera.
FilmMotion film_motion(const RenderScene& scene, const Hit& hit, float time, const Vec3& position);

}  // namespace rtpro
