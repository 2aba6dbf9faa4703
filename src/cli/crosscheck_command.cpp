// `rtpro crosscheck SCENE`: traces the same rays through the native and the Embree backend and
// compares them under the rules in backend/crosscheck.h. Exit codes: 0 within the rules, 1 for
// any mismatch, 2 for a bad scene or bad options.
#include "rtpro/crosscheck/crosscheck.h"
#include "rtpro/backend/backend.h"
#include "backend_options.h"
#include "command.h"
#include "load_scene.h"
#include "memory_option.h"
#include "scene_overrides.h"
#include "thread_count.h"
#include "rtpro/core/error.h"

#include <tbb/global_control.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace rtpro::cli {

namespace {

struct CrosscheckCommandOptions {
  std::string scene;
  std::vector<std::string> overrides, defines, environments, shutters;
  std::vector<SceneOverride> scene_overrides;  // both, in command-line order
  CrosscheckOptions check;
  int threads = 0;
  BackendOptions backend;  // Embree settings from the command line
  std::string max_memory_mb;
};

std::string describe(const Hit& hit, bool found) {
  if (!found) return "miss";
  char text[160];
  std::snprintf(text, sizeof text, "t=%.9g (%a) u=%.6g v=%.6g inst=%d geom=%u prim=%u", hit.t, hit.t, hit.u, hit.v,
                hit.inst_id == kInvalidId ? -1 : static_cast<int>(hit.inst_id), hit.geom_id, hit.prim_id);
  return text;
}

std::string describe(const Ray& ray) {
  char text[200];
  std::snprintf(text, sizeof text, "org=(%.9g, %.9g, %.9g) dir=(%.9g, %.9g, %.9g)", ray.org.x, ray.org.y, ray.org.z,
                ray.dir.x, ray.dir.y, ray.dir.z);
  return text;
}

const char* agreement_name(Agreement agreement) {
  switch (agreement) {
    case Agreement::kIdentical: return "identical";
    case Agreement::kWithinTolerance: return "within tolerance";
    case Agreement::kAmbiguous: return "ambiguous";
    case Agreement::kMismatch: return "MISMATCH";
  }
  return "?";
}

void print_report(const CrosscheckReport& r) {
  const auto share = [&](std::size_t n) { return r.rays ? 100.0 * double(n) / double(r.rays) : 0.0; };
  std::printf("crosscheck %s (reference) vs %s: %zu rays\n", r.reference_name.c_str(), r.candidate_name.c_str(),
              r.rays);
  std::printf("  identical          %zu (%.3f%%)\n", r.identical, share(r.identical));
  std::printf("  within tolerance   %zu (%.3f%%)\n", r.within_tolerance, share(r.within_tolerance));
  std::printf("  ambiguous          %zu (%.3f%%)\n", r.ambiguous, share(r.ambiguous));
  std::printf("  mismatches         %zu\n", r.mismatches);
  std::printf("  top-level spheres  %zu closest hits\n", r.top_level_sphere_hits);
  std::printf("  occlusion          %zu queries, %zu mismatches\n", r.occlusion_queries, r.occlusion_mismatches);
  std::printf("  largest errors     distance %.3g, barycentric point %.3g (relative to coordinates)\n", r.max_t_error,
              r.max_surface_error);
  if (!r.worst.empty()) std::printf("worst cases:\n");
  for (const CrosscheckCase& c : r.worst) {
    std::printf("  ray %zu (%s) %s%s%s%s\n", c.index, c.camera_ray ? "camera" : "random", agreement_name(c.agreement),
                c.note.empty() ? "" : ": ", c.note.c_str(), c.occlusion_differs ? " [occlusion differs]" : "");
    std::printf("    %s\n", describe(c.ray).c_str());
    std::printf("    %s: %s\n", r.reference_name.c_str(), describe(c.reference, c.reference_found).c_str());
    std::printf("    %s: %s\n", r.candidate_name.c_str(), describe(c.candidate, c.candidate_found).c_str());
  }
  std::printf("%s\n", r.passed() ? "PASSED: the backends agree within the rules"
                                 : "FAILED: the backends disagree beyond the rules");
}

int run_crosscheck(const CrosscheckCommandOptions& o) {
  const int threads = worker_thread_count(o.threads);
  const MemoryBudget memory = parse_memory_budget(o.max_memory_mb);
  // Must exist before any TBB or Embree work so the cap really holds.
  const tbb::global_control thread_cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  const LoadedScene loaded = load_scene({.file = o.scene, .overrides = o.scene_overrides, .memory = memory});
  const RenderScene& scene = loaded.scene;
  BackendOptions backend_options = o.backend;
  backend_options.threads = threads;
  backend_options.max_memory_bytes = memory.explicit_limit ? memory.bytes : 0;
  const auto native = make_backend(BackendKind::kNative, scene, backend_options);
  const auto embree = make_backend(BackendKind::kEmbree, scene, backend_options);

  const CrosscheckReport report = crosscheck(scene, *native, *embree, o.check);
  print_report(report);
  std::fflush(stdout);
  return report.passed() ? kExitOk : kExitRuntimeFailure;
}

}  // namespace

void add_crosscheck_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<CrosscheckCommandOptions>();
  CLI::App* cmd = app.add_subcommand("crosscheck", "Compare the native and Embree backends ray by ray");
  cmd->add_option("scene", o->scene, "Scene file (YAML), or a model as the whole scene (glTF, OBJ, PLY)")->required();
  add_scene_override_options(*cmd, o->overrides, o->defines, o->environments, o->shutters);
  cmd->add_option("--rays", o->check.rays, "Number of rays: half camera rays, half random rays")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}))
      ->capture_default_str();
  cmd->add_option("--seed", o->check.seed, "Seed of the ray generator")->capture_default_str();
  cmd->add_option("--worst", o->check.worst_cases, "How many of the worst cases to print")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1000}))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "Worker threads (0: all cores)")->check(CLI::Range(0, 4096));
  add_embree_options(*cmd, o->backend);
  cmd->add_option("--max-memory", o->max_memory_mb,
                  "Memory budget in MiB the scene's estimate is checked against before it is built, and Embree's "
                  "limit (0: no limit; default: the smaller of 4096 and the available memory)");
  cmd->callback([o, cmd, &action] {
    o->scene_overrides = command_line_overrides(*cmd);
    action = [o] { return run_crosscheck(*o); };
  });
}

}  // namespace rtpro::cli
