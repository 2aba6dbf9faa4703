#pragma once
// The Whitted integrator's shadow rays: for every shaded surface of a generation, one ray a point,
// spot or directional light, samples² an area light, each with the query that weighs its answer.
#include "whitted_integrator.h"

#include "rtpro/scene/render_scene.h"

#include <span>

namespace rtpro {

// The shadow rays of every surface of the generation into ws.shadow_rays and ws.shadow_queries
// (each surface's range in its first_shadow and end_shadow): surface by surface, lights in scene
// order.
void queue_shadow_rays(const RenderScene& scene, const StratifiedSampler& sampler, std::span<const SampleKey> keys,
                       const ShadingWorkspace::GenerationView& generation, int depth, ShadingWorkspace& ws);

}  // namespace rtpro
