#include "rtpro/scene/scene_lighting.h"

#include <algorithm>

namespace rtpro {

namespace {

bool positive(const Color& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; }

}  // namespace

std::optional<std::string> unlit_scene_warning(const RenderScene& scene) {
  if (!scene.lights.empty()) return std::nullopt;
  constexpr const char* kHow = "add lights, or light it with --environment FILE|R,G,B";
  switch (scene.render.integrator) {
    case Integrator::kWhitted:
      return std::string(
                 "the scene has no lights: under the whitted integrator, which lights nothing by emission or "
                 "the environment, only render.ambient shades it; ") +
             kHow + " and --integrator path";
    case Integrator::kPath: {
      // An emissive material counts whether or not a shape uses it: a scene that defines one means to.
      const bool emits = std::any_of(scene.materials.begin(), scene.materials.end(),
                                     [](const Material& m) { return m.emission.emits(); });
      const bool environment = scene.environment && positive(scene.environment->scale);
      if (emits || environment || positive(scene.render.background)) return std::nullopt;
      return std::string(
                 "nothing lights the scene (no lights, no emissive surfaces, no environment, a black "
                 "render.background): the image will be black; ") +
             kHow;
    }
  }
  return std::nullopt;
}

}  // namespace rtpro
