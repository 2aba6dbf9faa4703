#include "render_journal.h"

#include "path_controls.h"
#include "rtpro/core/error.h"

#include <filesystem>

namespace rtpro::cli {

namespace {

std::string quality_name(EmbreeBuildQuality quality) {
  switch (quality) {
    case EmbreeBuildQuality::kLow: return "low";
    case EmbreeBuildQuality::kMedium: return "medium";
    case EmbreeBuildQuality::kHigh: return "high";
  }
  return "?";
}

}  // namespace

JobIdentity render_job_identity(const SceneDescription& description, const SceneBuildReport& report,
                                const RenderScene& scene, const RenderJobSettings& settings) {
  JobIdentity identity = scene_identity(description, report, scene);
  for (std::size_t i = 0; i < settings.overrides.size(); ++i)
    identity.set("override " + std::to_string(i + 1), settings.overrides[i]);
  identity.set("image", std::to_string(scene.camera.width) + "x" + std::to_string(scene.camera.height));
  identity.set("spp", std::to_string(scene.render.spp));
  identity.set("seed", std::to_string(scene.render.seed));
  identity.set("max depth", std::to_string(scene.render.max_depth));
  identity.set("integrator", std::string(integrator_name(scene.render.integrator)) + ", " +
                                 path_sampling_name(scene.render.path_sampling) + " sampling, " +
                                 sampler_name(scene.render.sampler) + " sampler, " +
                                 light_sampler_name(scene.render.light_sampler) + " light sampler");
  // Only when they change the image: journals of renders without them keep their identity.
  if (path_controls_in_effect(scene.render)) identity.set("path controls", path_controls_summary(scene.render));
  identity.set("backend", settings.backend);
  if (settings.backend == "embree")
    identity.set("embree", "quality " + quality_name(settings.backend_options.embree_quality) +
                               (settings.backend_options.embree_robust ? ", robust" : ", not robust") +
                               (settings.backend_options.embree_compact ? ", compact" : ""));
  // Only when set: journals of renders without it keep their identity.
  if (settings.compact_normals) identity.set("normals", "compact (octahedral)");
  // The triangles' order decides which of two at exactly the same distance is hit.
  if (settings.piece_triangles != 0)
    identity.set("mesh pieces", std::to_string(settings.piece_triangles) + " triangles");
  const PixelRegion& r = settings.region;
  identity.set("region", std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
                             std::to_string(r.y1));
  identity.set("tile size", std::to_string(settings.tile_size));
  std::string channels;
  for (const std::string& channel : settings.channels) channels += (channels.empty() ? "" : " ") + channel;
  identity.set("channels", channels);
  if (settings.adaptive.threshold > 0.0f)
    identity.set("adaptive sampling", "noise threshold " + std::to_string(settings.adaptive.threshold) + " (" +
                                          noise_metric_name(settings.adaptive.metric) + "), min samples " +
                                          std::to_string(settings.adaptive.min_samples));
  return identity;
}

void OpenedJournal::tile_result(const TileResult& item) {
  if (std::chrono::steady_clock::now() < record_from) {
    unrecorded_.value = true;
    return;
  }
  journal->append(item);
}

void OpenedJournal::pass_merged(int, const ProgressiveFilm& film) {
  const bool catch_up = unrecorded_.value && std::chrono::steady_clock::now() >= record_from;
  if (!catch_up && journal->bytes() <= 2 * film.bytes()) return;
  unrecorded_.value = false;
  journal->rewrite([&film](const auto& write) { film.visit_journal_items(write); });
}

void OpenedJournal::render_ended(const ProgressiveFilm& film, bool complete) {
  // A complete render's journal is removed; an interrupted one's is what --resume continues.
  if (complete || !unrecorded_.value) return;
  unrecorded_.value = false;
  journal->rewrite([&film](const auto& write) { film.visit_journal_items(write); });
}

OpenedJournal open_render_journal(const std::filesystem::path& file, const JobIdentity& identity, const TileGrid& grid,
                                  int channel_count, bool resume, Log& log) {
  OpenedJournal opened;
  opened.owner = std::make_unique<JournalOwner>(file);  // refuses a FIFO, device, directory or link there too
  std::error_code error;
  const bool exists = std::filesystem::symlink_status(file, error).type() != std::filesystem::file_type::not_found;
  if (resume && !exists) {
    log.warning("--resume: no journal at " + file.string() + "; rendering every tile");
  } else if (resume) {
    JournalContents contents = read_journal(file, grid, channel_count);
    const std::vector<std::string> differences = identity.differences(contents.identity, "the journal");
    if (!differences.empty()) {
      std::vector<std::string> lines = differences;
      lines.push_back("render without --resume to start over");
      throw InputError(file.string() + ": the journal is of another render, so --resume cannot continue it:", lines);
    }
    log.info("resuming: " + std::to_string(contents.tiles.size()) + " records of " + std::to_string(grid.count()) +
             " tiles in passes from " + file.string() +
             (contents.dropped_records > 0 ? " (" + std::to_string(contents.dropped_records) +
                                                 " damaged records dropped; their tiles render again)"
                                           : ""));
    opened.finished = std::move(contents.tiles);
  } else if (exists) {
    log.warning("replacing the journal of an unfinished render at " + file.string() +
                " (rtpro render --resume continues one)");
  }
  opened.journal = std::make_unique<TileJournal>(file, identity, channel_count, opened.finished);
  return opened;
}

}  // namespace rtpro::cli
