// `rtpro info SCENE`: what a scene holds, without rendering it.
#include "command.h"
#include "load_scene.h"
#include "memory_option.h"
#include "path_controls.h"
#include "scene_overrides.h"
#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/scene/scene_lighting.h"
#include "rtpro/scene/scene_summary.h"
#include "rtpro/scene/unused_settings.h"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <variant>

namespace rtpro::cli {

namespace {

struct InfoOptions {
  std::string scene;
  std::vector<std::string> overrides, defines, environments, shutters;
  std::vector<SceneOverride> scene_overrides;  // both, in command-line order
  bool json = false;
  std::string max_memory_mb;
};

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json cost_json(const RenderCost& cost, const MemoryBudget& budget) {
  return {{"flattened_instances", cost.flattened_instances},
          {"pixels", cost.pixels},
          {"channels", cost.channels},
          {"camera_samples", cost.samples},
          {"image_bytes", cost.image_bytes},
          {"instance_bytes", cost.instance_bytes},
          {"mesh_bytes", cost.mesh_bytes},
          {"environment_width", cost.environment_width},
          {"environment_height", cost.environment_height},
          {"environment_bytes", cost.environment_bytes},
          {"volume_bytes", cost.volume_bytes},
          {"total_bytes", cost.total_bytes},
          {"budget_bytes", budget.bytes},
          {"budget", budget.source}};
}

// Each light as it is rendered: its kind, the colour and intensity it is given (a model file's
// converted to rtpro's radiometric units) and what they make, in the units the path integrator
// reads them in; where a model file's light came from.
struct LightLine {
  std::string type, name, unit, source;
  Color color;
  float intensity;
};

std::vector<LightLine> light_lines(const SceneDescription& description) {
  std::vector<LightLine> lines;
  for (std::size_t i = 0; i < description.lights.size(); ++i) {
    LightLine line = std::visit(
        [](const auto& light) { return LightLine{light_type_name(light), "", "", "", light.color, light.intensity}; },
        description.lights[i]);
    line.unit = line.type == "directional"                    ? "W/m^2 (irradiance)"
                : line.type == "point" || line.type == "spot" ? "W/sr (radiant intensity)"
                                                              : "W/(m^2 sr) (radiance)";
    line.name = description.light_names[i];
    line.source = description.light_sources[i];
    lines.push_back(std::move(line));
  }
  return lines;
}

nlohmann::json lights_json(const std::vector<LightLine>& lines) {
  nlohmann::json list = nlohmann::json::array();
  for (const LightLine& l : lines) {
    nlohmann::json light = {{"type", l.type},
                            {"color", vec_json(l.color)},
                            {"intensity", l.intensity},
                            {"rendered", vec_json(l.color * l.intensity)},
                            {"unit", l.unit}};
    if (!l.name.empty()) light["name"] = l.name;
    if (!l.source.empty()) light["source"] = l.source;
    list.push_back(std::move(light));
  }
  return list;
}

void print_lights(const std::vector<LightLine>& lines) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const LightLine& l = lines[i];
    const Color rendered = l.color * l.intensity;
    std::cout << "  light " << std::left << std::setw(5) << i << std::right << l.type
              << (l.name.empty() ? "" : " '" + printable_text(l.name, 80) + "'") << ": intensity " << std::defaultfloat
              << std::setprecision(6) << l.intensity << " x colour [" << l.color.x << ", " << l.color.y << ", "
              << l.color.z << "] = [" << rendered.x << ", " << rendered.y << ", " << rendered.z << "] " << l.unit
              << (l.source.empty() ? "" : ", from " + printable_text(l.source, 200)) << "\n";
  }
}

// Each volume's grid as rtpro holds it, against the file OpenVDB wrote: the memory figure of a
// grid medium (bytes per active voxel).
double per_voxel(std::uint64_t bytes, std::uint64_t voxels) {
  return voxels ? static_cast<double>(bytes) / static_cast<double>(voxels) : 0.0;
}

nlohmann::json volumes_json(const RenderScene& scene) {
  nlohmann::json list = nlohmann::json::array();
  for (const MediumIndex medium : scene.volumes) {
    const GridMedium& v = std::get<GridMedium>(scene.media[medium]);
    const VolumeMemory& m = v.grid->memory;
    const auto dims = v.grid->density.grid.active_box().dims();
    list.push_back(
        {{"file", v.file},
         {"grid", v.grid_name},
         {"active_voxels", m.active_voxels},
         {"active_box", {dims[0], dims[1], dims[2]}},
         {"bytes", m.bytes},
         {"bytes_per_active_voxel", per_voxel(m.bytes, m.active_voxels)},
         {"file_bytes", m.file_bytes},
         {"file_bytes_per_active_voxel", per_voxel(m.file_bytes, m.active_voxels)},
         {"bounds",
          {{"lower", vec_json(v.grid->world_bounds().lower)}, {"upper", vec_json(v.grid->world_bounds().upper)}}}});
  }
  return list;
}

void print_volumes(const RenderScene& scene) {
  for (const MediumIndex medium : scene.volumes) {
    const GridMedium& v = std::get<GridMedium>(scene.media[medium]);
    const VolumeMemory& m = v.grid->memory;
    const auto dims = v.grid->density.grid.active_box().dims();
    std::cout << "  volume     " << printable_text(v.file, 200) << " grid '" << printable_text(v.grid_name, 80)
              << "': " << m.active_voxels << " active voxels in " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", "
              << format_bytes(m.bytes) << " (" << std::setprecision(1) << per_voxel(m.bytes, m.active_voxels)
              << " bytes per active voxel; the file " << format_bytes(m.file_bytes) << ", "
              << per_voxel(m.file_bytes, m.active_voxels) << " per active voxel)\n";
  }
}

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
  const nlohmann::json bounds =
      s.bounds.empty() ? nlohmann::json(nullptr)
                       : nlohmann::json{{"lower", vec_json(s.bounds.lower)}, {"upper", vec_json(s.bounds.upper)}};
  nlohmann::json render = {{"spp", scene.render.spp},
                           {"max_depth", scene.render.max_depth},
                           {"seed", scene.render.seed},
                           {"integrator", integrator_name(scene.render.integrator)}};
  for (const PathControlValue& control : path_control_values(scene.render)) render[control.key] = control.value;
  return {{"scene", file},
          {"camera",
           {{"position", vec_json(scene.camera.position)},
            {"look_at", vec_json(scene.camera.look_at)},
            {"fov", scene.camera.fov_degrees},
            {"resolution", {scene.camera.width, scene.camera.height}}}},
          {"render", render},
          {"materials", s.materials},
          {"lights",
           {{"point", s.point_lights},
            {"spot", s.spot_lights},
            {"directional", s.directional_lights},
            {"area", s.area_lights}}},
          {"spheres", {{"stored", s.spheres_stored}, {"rendered", s.spheres_rendered}}},
          {"triangles", {{"stored", s.triangles_stored}, {"rendered", s.triangles_rendered}}},
          {"curve_segments", {{"stored", s.curve_segments_stored}, {"rendered", s.curve_segments_rendered}}},
          {"vertices", s.vertices_stored},
          {"meshes", meshes},
          {"volumes", volumes_json(scene)},
          {"prototypes", s.prototypes},
          {"instances", s.instances},
          {"motion",
           {{"shutter", {scene.camera.shutter.open, scene.camera.shutter.close}},
            {"shutter_opening", {scene.camera.shutter.opening, scene.camera.shutter.closing}},
            {"camera_moves", s.motion.camera_moves},
            {"moving_instances", s.motion.moving_instances},
            {"transform_steps", s.motion.transform_steps},
            {"deforming_meshes", s.motion.deforming_meshes},
            {"vertex_steps", s.motion.vertex_steps},
            {"moving_spheres", s.motion.moving_spheres},
            {"center_steps", s.motion.center_steps}}},
          {"bounds", bounds},
          {"memory_bytes",
           {{"geometry", s.geometry_bytes},
            {"native_bvh_estimate", s.estimated_bvh_bytes},
            {"total_estimate", s.geometry_bytes + s.estimated_bvh_bytes}}}};
}

// What moves during an open shutter, and the most time steps each kind takes (each step a copy of
// what moves: the cost of motion blur in memory and build time).
void print_motion(const RenderScene& scene, const SceneSummary::Motion& m) {
  if (!scene.camera.shutter.is_open()) return;
  const std::streamsize precision = std::cout.precision(6);
  const Shutter& shutter = scene.camera.shutter;
  std::cout << std::defaultfloat << "motion       shutter [" << shutter.open << ", " << shutter.close << "] frames";
  if (!shutter.is_box()) std::cout << ", opening [" << shutter.opening << ", " << shutter.closing << "]";
  std::cout << ": " << std::fixed;
  std::cout.precision(precision);
  if (!m.any()) {
    std::cout << "nothing moves\n";
    return;
  }
  std::vector<std::string> parts;
  const auto count = [](std::uint64_t n, const std::string& what, std::size_t steps) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s") + " (" + (n == 1 ? "" : "at most ") +
           std::to_string(steps) + " time steps)";
  };
  if (m.deforming_meshes > 0) parts.push_back(count(m.deforming_meshes, "deforming mesh", m.vertex_steps));
  if (m.moving_instances > 0) parts.push_back(count(m.moving_instances, "moving instance", m.transform_steps));
  if (m.moving_spheres > 0) parts.push_back(count(m.moving_spheres, "moving sphere", m.center_steps));
  if (m.camera_moves) parts.push_back("the camera");
  for (std::size_t i = 0; i < parts.size(); ++i) std::cout << (i ? ", " : "") << parts[i];
  std::cout << "\n";
}

void print_text(const std::string& file, const RenderScene& scene, const SceneSummary& s,
                const SceneBuildReport& report, const std::vector<LightLine>& lights) {
  const auto mib = [](std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); };
  std::cout << std::fixed << std::setprecision(1);
  std::cout << "scene        " << file << "\n"
            << "image        " << scene.camera.width << "x" << scene.camera.height << ", " << scene.render.spp
            << " spp, max depth " << scene.render.max_depth << ", seed " << scene.render.seed << ", "
            << integrator_name(scene.render.integrator) << " integrator\n"
            << (scene.render.integrator == Integrator::kPath
                    ? "path         " + path_controls_summary(scene.render) + "\n"
                    : std::string())
            << "materials    " << s.materials << "\n"
            << "lights       " << s.point_lights << " point, " << s.spot_lights << " spot, " << s.directional_lights
            << " directional, " << s.area_lights << " area\n";
  print_lights(lights);
  std::cout << std::fixed << std::setprecision(1) << "spheres      " << s.spheres_stored << " stored, "
            << s.spheres_rendered << " after instancing\n"
            << "triangles    " << s.triangles_stored << " stored, " << s.triangles_rendered << " after instancing\n"
            << (s.curve_segments_stored > 0
                    ? "curves       " + std::to_string(s.curve_segments_stored) + " segments stored, " +
                          std::to_string(s.curve_segments_rendered) + " after instancing\n"
                    : std::string())
            << "meshes       " << s.meshes << " (" << s.vertices_stored << " vertices)\n"
            << "instances    " << s.instances << " of " << s.prototypes << " prototypes\n";
  print_motion(scene, s.motion);
  for (const auto& m : report.meshes)
    std::cout << "  mesh       " << m.file << ": " << m.stats.triangles << " triangles, " << m.stats.vertices
              << " vertices" << (m.stats.normals_generated ? ", normals generated" : "")
              << (m.stats.dropped_degenerate ? ", " + std::to_string(m.stats.dropped_degenerate) + " degenerate dropped"
                                             : "")
              << (m.stats.concave_polygons ? ", " + std::to_string(m.stats.concave_polygons) + " concave polygons" : "")
              << "\n";
  for (const auto& m : report.meshes)
    for (const std::string& warning : m.stats.warnings) std::cout << "  warning    " << warning << "\n";
  print_volumes(scene);
  std::cout << std::fixed;
  std::cout << std::setprecision(3);
  if (s.bounds.empty()) {
    std::cout << "bounds       none (nothing to render)\n";
  } else {
    std::cout << "bounds       [" << s.bounds.lower.x << ", " << s.bounds.lower.y << ", " << s.bounds.lower.z
              << "] .. [" << s.bounds.upper.x << ", " << s.bounds.upper.y << ", " << s.bounds.upper.z << "]\n";
  }
  std::cout << std::setprecision(1) << "memory       " << mib(s.geometry_bytes) << " MiB geometry + ~"
            << mib(s.estimated_bvh_bytes) << " MiB native BVH (estimate)\n";
}

// The up-front estimate `rtpro render` checks before it allocates anything (without AOVs).
void print_cost(const RenderCost& cost, const MemoryBudget& budget) {
  std::cout << "estimate     " << format_bytes(cost.total_bytes) << " before the BVH: image "
            << format_bytes(cost.image_bytes) << ", " << cost.flattened_instances << " instances "
            << format_bytes(cost.instance_bytes) << ", meshes " << format_bytes(cost.mesh_bytes) << ", environment map "
            << format_bytes(cost.environment_bytes) << ", volumes " << format_bytes(cost.volume_bytes) << "; budget "
            << format_bytes(budget.bytes) << " (" << budget.source << ")\n"
            << "camera rays  " << cost.samples << " (pixels x spp)\n";
}

int run_info(const InfoOptions& o) {
  const MemoryBudget budget = parse_memory_budget(o.max_memory_mb);
  const LoadedScene loaded = load_scene({.file = o.scene, .overrides = o.scene_overrides, .memory = budget});
  const SceneSummary summary = summarize(loaded.scene);
  const std::vector<LightLine> lights = light_lines(loaded.description);
  std::vector<std::string> notes = loaded.description.notes;
  if (const auto warning = unlit_scene_warning(loaded.scene)) notes.push_back("warning: " + *warning);
  if (const auto warning = ignored_path_controls_warning(loaded.scene.render)) notes.push_back("warning: " + *warning);
  if (o.json) {
    nlohmann::json json = info_json(o.scene, loaded.scene, summary, loaded.report);
    json["light_list"] = lights_json(lights);
    json["notes"] = notes;
    json["estimate"] = cost_json(loaded.cost, budget);
    std::cout << json.dump(2) << "\n";
  } else {
    print_text(o.scene, loaded.scene, summary, loaded.report, lights);
    print_cost(loaded.cost, budget);
    for (const std::string& note : notes) std::cout << "note         " << note << "\n";
  }
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Describe what a scene holds without rendering it");
  cmd->add_option(
         "scene", options->scene,
         "Scene file (YAML), a model as the whole scene (glTF, OBJ, PLY), or '-' for a YAML scene on standard input")
      ->required();
  add_scene_override_options(*cmd, options->overrides, options->defines, options->environments, options->shutters);
  cmd->add_flag("--json", options->json, "Print JSON instead of text");
  cmd->add_option("--max-memory", options->max_memory_mb,
                  "Memory budget in MiB the render estimate is checked against (0: no limit; default: the smaller "
                  "of 4096 and the available memory)");
  cmd->callback([options, cmd, &action] {
    options->scene_overrides = command_line_overrides(*cmd);
    action = [options] { return run_info(*options); };
  });
}

}  // namespace rtpro::cli
