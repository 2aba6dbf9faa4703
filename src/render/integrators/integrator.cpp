#include "integrator.h"

#include "rtpro/core/error.h"

namespace rtpro {

namespace {

// The Whitted integrator shows the media inside glass and interfaces as absorption only (their
// Whitted approximation's transmittance, scene/build); a medium that fills the world it cannot
// show, and refuses rather than render something else.
void refuse_media_under_whitted(const RenderScene& scene) {
  if (scene.world_medium != kNoMedium)
    throw InputError(
        "the whitted integrator does not render a world `medium:`: render the scene with "
        "`--integrator path`");
}

}  // namespace

SceneIntegrator make_integrator(const RenderScene& scene, const IntegratorContext& context) {
  switch (scene.render.integrator) {
    case Integrator::kWhitted:
      refuse_media_under_whitted(scene);
      return SceneIntegrator(std::in_place_type<WhittedIntegrator>, scene, context.backend,
                             context.samplers.stratified(), context.textures, context.environment,
                             context.records_primary, context.records_motion);
    case Integrator::kPath:
      return SceneIntegrator(std::in_place_type<PathIntegrator>, scene, context.backend, context.samplers,
                             context.textures, context.environment, context.records_motion);
  }
  __builtin_unreachable();  // the switch covers every kind
}

}  // namespace rtpro
