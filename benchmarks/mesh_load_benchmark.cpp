// Loading the Stanford dragon (871,414 triangles): rtpro's OBJ and PLY loaders against
// tinyobjloader, and the same dragon as glTF (a .glb written once from the PLY, in the temporary
// folder) against the OBJ, both read as whole scenes. Fetch the model with scripts/fetch-dragon.sh;
// paths can be overridden with RTPRO_DRAGON_OBJ and RTPRO_DRAGON_PLY. Run with
// --benchmark_min_time=2 for stable figures.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/mesh_loader.h"
#include "rtpro/scene/scene_parser.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tiny_obj_loader.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

fs::path asset(const char* variable, const char* name) {
  if (const char* path = std::getenv(variable)) return path;
  const char* source = std::getenv("RTPRO_SOURCE_DIR");
  return fs::path(source ? source : RTPRO_SOURCE_DIR) / "assets" / name;
}

const fs::path& dragon_obj() {
  static const fs::path path = asset("RTPRO_DRAGON_OBJ", "dragon.obj");
  return path;
}

const fs::path& dragon_ply() {
  static const fs::path path = asset("RTPRO_DRAGON_PLY", "dragon_vrip.ply");
  return path;
}

bool have(benchmark::State& state, const fs::path& file) {
  if (fs::is_regular_file(file)) return true;
  state.SkipWithError((file.string() + " is missing: run scripts/fetch-dragon.sh").c_str());
  return false;
}

void report(benchmark::State& state, const fs::path& file, std::size_t triangles) {
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(fs::file_size(file)));
  state.counters["triangles"] = double(triangles);
  state.counters["triangles/s"] =
      benchmark::Counter(double(triangles) * double(state.iterations()), benchmark::Counter::kIsRate);
}

void load_with_rtpro(benchmark::State& state, const fs::path& file,
                     rtpro::NormalsMode normals = rtpro::NormalsMode::kAuto) {
  if (!have(state, file)) return;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const rtpro::LoadedMesh loaded = rtpro::load_mesh_file(file, {normals});
    triangles = loaded.mesh.triangle_count();
    benchmark::DoNotOptimize(loaded.mesh.normals.data());
  }
  report(state, file, triangles);
}

void BM_RtproObj(benchmark::State& state) { load_with_rtpro(state, dragon_obj()); }

// With generated smooth normals, as scenes/dragon.yaml asks (and as every OBJ without `s` lines
// was read before flat became the default): the same work as the loader did then.
void BM_RtproObjSmooth(benchmark::State& state) { load_with_rtpro(state, dragon_obj(), rtpro::NormalsMode::kSmooth); }

// On one core its CPU time is the whole cost, which other jobs on a shared machine disturb least:
// the figure to compare loader versions with.
void BM_RtproObjSmoothOneThread(benchmark::State& state) {
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  load_with_rtpro(state, dragon_obj(), rtpro::NormalsMode::kSmooth);
}

// The same parse on one core: what the parser itself gains, without the parallelism.
void BM_RtproObjOneThread(benchmark::State& state) {
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  load_with_rtpro(state, dragon_obj());
}

void BM_TinyObjLoader(benchmark::State& state) {
  if (!have(state, dragon_obj())) return;
  std::size_t triangles = 0;
  for (auto _ : state) {
    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    if (!reader.ParseFromFile(dragon_obj().string(), config)) {
      state.SkipWithError(reader.Error().c_str());
      return;
    }
    triangles = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) triangles += shape.mesh.num_face_vertices.size();
    benchmark::DoNotOptimize(reader.GetAttrib().vertices.data());
  }
  report(state, dragon_obj(), triangles);
}

void BM_RtproAsciiPly(benchmark::State& state) { load_with_rtpro(state, dragon_ply()); }

// The PLY dragon as a binary glTF: positions (float) and indices (uint32) in one buffer, one
// mesh, one node. Written by hand (the format is two chunks) so the benchmark needs nothing but
// rtpro's public headers.
fs::path write_dragon_glb() {
  const fs::path glb = fs::temp_directory_path() / "rtpro_benchmark_dragon.glb";
  const rtpro::TriangleMesh mesh = rtpro::load_mesh_file(dragon_ply()).mesh;
  std::string bin;
  for (const rtpro::MeshVertex& v : mesh.vertices) bin.append(reinterpret_cast<const char*>(&v), 12);
  const std::size_t positions_bytes = bin.size();
  bin.append(reinterpret_cast<const char*>(mesh.triangles.data()), mesh.triangles.size() * 12);
  const rtpro::BBox b = mesh.bounds();
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                     R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
                     R"("buffers":[{"byteLength":)" +
                     std::to_string(bin.size()) +
                     R"(}],"bufferViews":[)"
                     R"({"buffer":0,"byteOffset":0,"byteLength":)" +
                     std::to_string(positions_bytes) +
                     R"(},)"
                     R"({"buffer":0,"byteOffset":)" +
                     std::to_string(positions_bytes) + R"(,"byteLength":)" +
                     std::to_string(bin.size() - positions_bytes) +
                     R"(}],"accessors":[)"
                     R"({"bufferView":0,"componentType":5126,"count":)" +
                     std::to_string(mesh.vertices.size()) + R"(,"type":"VEC3","min":[)" + std::to_string(b.lower.x) +
                     "," + std::to_string(b.lower.y) + "," + std::to_string(b.lower.z) + R"(],"max":[)" +
                     std::to_string(b.upper.x) + "," + std::to_string(b.upper.y) + "," + std::to_string(b.upper.z) +
                     R"(]},{"bufferView":1,"componentType":5125,"count":)" + std::to_string(mesh.triangles.size() * 3) +
                     R"(,"type":"SCALAR"}]})";
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string file = "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
                           u32(std::uint32_t(json.size())) + "JSON" + json + u32(std::uint32_t(bin.size())) + "BIN" +
                           std::string(1, '\0') + bin;
  std::ofstream(glb, std::ios::binary) << file;
  return glb;
}

const fs::path& dragon_glb() {
  static const fs::path path = fs::is_regular_file(dragon_ply()) ? write_dragon_glb() : fs::path();
  return path;
}

// A file as a whole scene: parse, load and build, as `rtpro render` does before tracing.
void load_scene(benchmark::State& state, const fs::path& scene, const fs::path& measured) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    const rtpro::RenderScene loaded = rtpro::build_render_scene(rtpro::parse_scene_file(scene));
    triangles = 0;
    for (const rtpro::Group& prototype : loaded.prototypes)
      for (const rtpro::Geometry& g : prototype.geometries)
        triangles += std::get<rtpro::TriangleMesh>(g).triangle_count();
    for (const rtpro::Geometry& g : loaded.top.geometries)
      if (const auto* mesh = std::get_if<rtpro::TriangleMesh>(&g)) triangles += mesh->triangle_count();
    benchmark::DoNotOptimize(loaded.prototypes.data());
  }
  report(state, measured, triangles);
}

void BM_RtproGltfScene(benchmark::State& state) {
  if (!have(state, dragon_ply())) return;
  load_scene(state, dragon_glb(), dragon_glb());
}

// The OBJ read the same way, for the ratio against glTF.
void BM_RtproObjScene(benchmark::State& state) {
  if (!have(state, dragon_obj())) return;
  const fs::path yaml = fs::temp_directory_path() / "rtpro_benchmark_dragon_obj.yaml";
  std::ofstream(yaml)
      << "rtpro: 1\ncamera: {position: [0, 0, 1], look_at: [0, 0, 0]}\nworld:\n  - {type: mesh, file: \""
      << fs::absolute(dragon_obj()).string() << "\"}\n";
  load_scene(state, yaml, dragon_obj());
}

// 100,000 distinct unknown keywords (1.6 MB): the warning tally must stay linear.
void BM_RtproObjUnknownKeywords(benchmark::State& state) {
  const fs::path file = fs::temp_directory_path() / "rtpro_benchmark_keywords.obj";
  if (!fs::is_regular_file(file)) {
    std::ofstream out(file);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int i = 0; i < 100000; ++i) out << "kw" << i << " 1 2 3\n";
  }
  std::size_t warnings = 0;
  for (auto _ : state) warnings = rtpro::load_mesh_file(file).stats.warnings.size();
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(fs::file_size(file)));
  state.counters["warnings"] = double(warnings);
}

BENCHMARK(BM_RtproObj)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjSmooth)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjSmoothOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TinyObjLoader)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproAsciiPly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjScene)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproGltfScene)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjUnknownKeywords)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
