// `rtpro info SCENE`: what a scene holds, without rendering it.
#include "command.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "rtpro/scene/scene_summary.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>

namespace rtpro::cli {

namespace {

struct InfoOptions {
  std::string scene;
  std::vector<std::string> overrides;
  bool json = false;
};

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json info_json(const std::string& file, const RenderScene& scene, const SceneSummary& s,
                         const SceneBuildReport& report) {
  nlohmann::json meshes = nlohmann::json::array();
  for (const auto& m : report.meshes)
    meshes.push_back({{"file", m.file},
                      {"vertices", m.stats.vertices},
                      {"triangles", m.stats.triangles},
                      {"faces", m.stats.faces},
                      {"materials", m.stats.materials},
                      {"dropped_degenerate", m.stats.dropped_degenerate},
                      {"normals_generated", m.stats.normals_generated},
                      {"concave_polygons", m.stats.concave_polygons},
                      {"warnings", m.stats.warnings},
                      {"load_seconds", m.load_seconds}});
  // An empty scene has no bounds: null, not [inf, ...] (which is not even valid JSON).
  const nlohmann::json bounds = s.bounds.empty() ? nlohmann::json(nullptr)
                                                 : nlohmann::json{{"lower", vec_json(s.bounds.lower)}, {"upper", vec_json(s.bounds.upper)}};
  return {{"scene", file},
          {"camera",
           {{"position", vec_json(scene.camera.position)},
            {"look_at", vec_json(scene.camera.look_at)},
            {"fov", scene.camera.fov_degrees},
            {"resolution", {scene.camera.width, scene.camera.height}}}},
          {"render",
           {{"spp", scene.render.spp}, {"max_depth", scene.render.max_depth}, {"seed", scene.render.seed}}},
          {"materials", s.materials},
          {"lights", {{"point", s.point_lights}, {"directional", s.directional_lights}}},
          {"spheres", {{"stored", s.spheres_stored}, {"rendered", s.spheres_rendered}}},
          {"triangles", {{"stored", s.triangles_stored}, {"rendered", s.triangles_rendered}}},
          {"vertices", s.vertices_stored},
          {"meshes", meshes},
          {"prototypes", s.prototypes},
          {"instances", s.instances},
          {"bounds", bounds},
          {"memory_bytes",
           {{"geometry", s.geometry_bytes},
            {"native_bvh_estimate", s.estimated_bvh_bytes},
            {"total_estimate", s.geometry_bytes + s.estimated_bvh_bytes}}}};
}

void print_text(const std::string& file, const RenderScene& scene, const SceneSummary& s,
                const SceneBuildReport& report) {
  const auto mib = [](std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); };
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "scene        " << file << "\n"
            << "image        " << scene.camera.width << "x" << scene.camera.height << ", " << scene.render.spp
            << " spp, max depth " << scene.render.max_depth << ", seed " << scene.render.seed << "\n"
            << "materials    " << s.materials << "\n"
            << "lights       " << s.point_lights << " point, " << s.directional_lights << " directional\n"
            << "spheres      " << s.spheres_stored << " stored, " << s.spheres_rendered << " after instancing\n"
            << "triangles    " << s.triangles_stored << " stored, " << s.triangles_rendered << " after instancing\n"
            << "meshes       " << s.meshes << " (" << s.vertices_stored << " vertices)\n"
            << "instances    " << s.instances << " of " << s.prototypes << " prototypes\n";
  for (const auto& m : report.meshes)
    std::cout << "  mesh       " << m.file << ": " << m.stats.triangles << " triangles, " << m.stats.vertices
              << " vertices" << (m.stats.normals_generated ? ", normals generated" : "")
              << (m.stats.dropped_degenerate ? ", " + std::to_string(m.stats.dropped_degenerate) + " degenerate dropped"
                                             : "")
              << (m.stats.concave_polygons ? ", " + std::to_string(m.stats.concave_polygons) + " concave polygons" : "")
              << "\n";
  for (const auto& m : report.meshes)
    for (const std::string& warning : m.stats.warnings) std::cout << "  warning    " << warning << "\n";
  std::cout << std::setprecision(3);
  if (s.bounds.empty()) {
    std::cout << "bounds       none (nothing to render)\n";
  } else {
    std::cout << "bounds       [" << s.bounds.lower.x << ", " << s.bounds.lower.y << ", " << s.bounds.lower.z << "] .. ["
              << s.bounds.upper.x << ", " << s.bounds.upper.y << ", " << s.bounds.upper.z << "]\n";
  }
  std::cout << std::setprecision(1) << "memory       " << mib(s.geometry_bytes) << " MiB geometry + ~"
            << mib(s.estimated_bvh_bytes) << " MiB native BVH (estimate)\n";
}

int run_info(const InfoOptions& o) {
  const SceneDescription description = parse_scene_file(o.scene, o.overrides);
  SceneBuildReport report;
  const RenderScene scene = build_render_scene(description, &report);
  const SceneSummary summary = summarize(scene);
  if (o.json) std::cout << info_json(o.scene, scene, summary, report).dump(2) << "\n";
  else print_text(o.scene, scene, summary, report);
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Describe what a scene holds without rendering it");
  cmd->add_option("scene", options->scene, "Scene file (YAML)")->required();
  cmd->add_option("--set", options->overrides, "Override a scene value, e.g. --set render.spp=64 (repeatable)");
  cmd->add_flag("--json", options->json, "Print JSON instead of text");
  cmd->callback([options, &action] { action = [options] { return run_info(*options); }; });
}

}  // namespace rtpro::cli
