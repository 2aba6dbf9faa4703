#include "integrator.h"

namespace rtpro {

SceneIntegrator make_integrator(const RenderScene& scene, const IntegratorContext& context) {
  switch (scene.render.integrator) {
    case Integrator::kWhitted:
      return SceneIntegrator(std::in_place_type<WhittedIntegrator>, scene, context.backend,
                             context.samplers.stratified(), context.textures, context.environment,
                             context.records_primary);
    case Integrator::kPath:
      return SceneIntegrator(std::in_place_type<PathIntegrator>, scene, context.backend, context.samplers,
                             context.textures, context.environment);
  }
  __builtin_unreachable();  // the switch covers every kind
}

}  // namespace rtpro
