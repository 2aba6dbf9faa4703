#pragma once
// The integrators, a closed kind: each is a type holding its scene and settings, with a
// `Workspace` (the buffers one worker reuses from batch to batch) and
//   void trace(const CameraBatch&, RayCounts&, Workspace&) const;
// A new integrator is its file pair, an alternative of SceneIntegrator and a case in
// make_integrator, whose switch over the scene's render.integrator names a kind it lacks.
#include "camera_batch.h"
#include "camera_samplers.h"
#include "path_integrator.h"
#include "rtpro/backend/backend.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/ray_counts.h"
#include "rtpro/scene/render_scene.h"
#include "whitted_integrator.h"

#include <tuple>
#include <variant>

namespace rtpro {

using SceneIntegrator = std::variant<WhittedIntegrator, PathIntegrator>;

// One worker's buffers for every integrator kind (only the scene's is ever filled).
template <class Variant>
struct WorkspacesOf;
template <class... Integrators>
struct WorkspacesOf<std::variant<Integrators...>> {
  using type = std::tuple<typename Integrators::Workspace...>;
};
using IntegratorWorkspaces = WorkspacesOf<SceneIntegrator>::type;

// What an integrator needs besides the scene: the backend it traces with, the samplers it draws
// from, the scene's opened textures and environment (each required when the scene has one), and
// whether anything reads the primary hits (the film keeps more than colour) and their film motion
// (the motion AOV).
struct IntegratorContext {
  const Backend& backend;
  const CameraSamplers& samplers;
  const TextureLookup* textures;
  const EnvironmentLight* environment;
  bool records_primary;
  bool records_motion = false;
};

// The integrator the scene's render.integrator names.
SceneIntegrator make_integrator(const RenderScene& scene, const IntegratorContext& context);

inline void trace(const SceneIntegrator& integrator, const CameraBatch& batch, RayCounts& counts,
                  IntegratorWorkspaces& workspaces) {
  std::visit(
      [&](const auto& kind) {
        using Workspace = typename std::decay_t<decltype(kind)>::Workspace;
        kind.trace(batch, counts, std::get<Workspace>(workspaces));
      },
      integrator);
}

}  // namespace rtpro
