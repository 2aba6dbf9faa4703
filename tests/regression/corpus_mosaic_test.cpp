// A mosaic of Debian's assimp-testmodels (when installed) for a person to look at: every OBJ, PLY
// and glTF 2.0 file that loads, rendered small by rtpro's own render path and framed by its
// bounds, one tile each in <build>/regression/corpus_mosaic.png, which the regression report
// links. The test asserts what a look would: each model is in its frame (covers part of its
// tile) and no tile is the background alone.
#include "html_report.h"
#include "regression_paths.h"
#include "scene_textures.h"
#include "rtpro/backend/backend.h"
#include "rtpro/core/error.h"
#include "rtpro/image/image_io.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace rtpro {
namespace corpus_mosaic_test {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models";
constexpr int kTile = 64;
constexpr int kColumns = 10;
constexpr float kBackground = 0.25f;

std::vector<fs::path> corpus_models() {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::recursive_directory_iterator(kCorpus, error)) {
    std::string extension = entry.path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    const bool gltf2 =
        (extension == ".gltf" || extension == ".glb") && entry.path().string().find("glTF2") != std::string::npos;
    if (entry.is_regular_file() && (extension == ".obj" || extension == ".ply" || gltf2)) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The model alone under one directional light, camera placeholder replaced once bounds are known.
std::string scene_text(const fs::path& model) {
  return "rtpro: 1\ncamera: {position: [0, 0, 5], look_at: [0, 0, 0], resolution: [" + std::to_string(kTile) + ", " +
         std::to_string(kTile) + "]}\nrender: {spp: 4, max_depth: 1, ambient: 0.3, background: [" +
         std::to_string(kBackground) + ", " + std::to_string(kBackground) + ", " + std::to_string(kBackground) +
         "]}\nlights: [{type: directional, direction: [-0.4, -1, -0.7], intensity: 0.9}]\nworld:\n"
         "  - {type: mesh, file: \"" +
         model.string() + "\"}\n";
}

// Looks at the bounds' centre from a fixed diagonal, far enough that the bounding sphere fits.
CameraDesc framing(const BBox& bounds) {
  const Vec3 centre = (bounds.lower + bounds.upper) * 0.5f;
  const float radius = std::max(length(bounds.upper - bounds.lower) * 0.5f, 1e-6f);
  CameraDesc camera;
  camera.fov_degrees = 40.0f;
  camera.look_at = centre;
  camera.position = centre + normalize(Vec3(0.6f, 0.5f, 1.0f)) * (radius / std::sin(0.5f * 0.6981317f) * 1.05f);
  camera.width = camera.height = kTile;
  return camera;
}

std::size_t triangle_count(const RenderScene& scene) {
  std::size_t count = 0;
  const auto add = [&count](const Group& group) {
    for (const Geometry& geometry : group.geometries)
      if (const auto* mesh = std::get_if<TriangleMesh>(&geometry)) count += mesh->triangles.size();
  };
  add(scene.top);
  for (const Group& prototype : scene.prototypes) add(prototype);
  return count;
}

TEST(CorpusMosaic, EveryLoadableModelIsInItsFrame) {
  const std::vector<fs::path> models = corpus_models();
  if (models.empty()) GTEST_SKIP() << "assimp-testmodels is not installed (" << kCorpus << ")";
  std::vector<Image> tiles;
  std::vector<std::string> names;
  for (const fs::path& model : models) {
    SCOPED_TRACE(model.string());
    RenderScene scene;
    try {
      scene = build_render_scene(parse_scene_text(scene_text(model), fs::path(RTPRO_BINARY_DIR) / "mosaic.yaml"));
    } catch (const InputError&) {
      continue;  // refusals are the corpus test's subject (tests/scene/mesh_corpus_test.cpp)
    }
    if (triangle_count(scene) == 0) continue;  // loaded, but only points or lines
    const BBox bounds = scene.bounds();
    scene.camera = make_render_camera(framing(bounds));
    const auto backend = make_backend(BackendKind::kEmbree, scene, BackendOptions{});
    const std::unique_ptr<TextureLookup> textures = regression::open_scene_textures(scene);
    RenderOptions options;
    options.textures = textures.get();
    Image tile = render_image(scene, *backend, options).image;
    std::size_t covered = 0;
    for (std::size_t p = 0; p < tile.data.size(); p += 3)
      covered += std::fabs(tile.data[p] - kBackground) > 1e-3f || std::fabs(tile.data[p + 2] - kBackground) > 1e-3f;
    const double fraction = double(covered) / (kTile * kTile);
    EXPECT_GT(fraction, 0.005) << "the model is not in its frame";
    tiles.push_back(std::move(tile));
    names.push_back(fs::relative(model, kCorpus).string());
  }
  ASSERT_GT(tiles.size(), 40u) << "most of the corpus loads";
  RecordProperty("models", int(tiles.size()));

  const int rows = int((tiles.size() + kColumns - 1) / kColumns);
  Image mosaic(kColumns * kTile, rows * kTile);
  std::fill(mosaic.data.begin(), mosaic.data.end(), 0.0f);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int x0 = int(i % kColumns) * kTile, y0 = int(i / kColumns) * kTile;
    for (int y = 0; y < kTile; ++y)
      std::copy_n(tiles[i].data.begin() + std::ptrdiff_t(y) * kTile * 3, kTile * 3,
                  mosaic.data.begin() + (std::ptrdiff_t(y0 + y) * mosaic.width + x0) * 3);
  }
  const fs::path root = regression::results_root();
  fs::create_directories(root);
  write_image(root / "corpus_mosaic.png", mosaic, {});
  std::string legend;
  for (std::size_t i = 0; i < names.size(); ++i)
    legend += std::to_string(i / kColumns) + "," + std::to_string(i % kColumns) + " " + names[i] + "\n";
  regression::write_text_atomically(root / "corpus_mosaic.txt", legend);
  regression::regenerate_report(root, regression::update_command());
}

}  // namespace corpus_mosaic_test
}  // namespace rtpro
