// Loading the Stanford dragon (871,414 triangles): rtpro's OBJ and PLY loaders against
// tinyobjloader. Fetch the model with scripts/fetch-dragon.sh; paths can be overridden with
// RTPRO_DRAGON_OBJ and RTPRO_DRAGON_PLY. Run with --benchmark_min_time=2 for stable figures.
#include "rtpro/scene/mesh_loader.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tiny_obj_loader.h>

#include <cstdlib>
#include <filesystem>

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

void load_with_rtpro(benchmark::State& state, const fs::path& file) {
  if (!have(state, file)) return;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const rtpro::LoadedMesh loaded = rtpro::load_mesh_file(file);
    triangles = loaded.mesh.triangle_count();
    benchmark::DoNotOptimize(loaded.mesh.normals.data());
  }
  report(state, file, triangles);
}

void BM_RtproObj(benchmark::State& state) { load_with_rtpro(state, dragon_obj()); }

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

BENCHMARK(BM_RtproObj)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproObjOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TinyObjLoader)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RtproAsciiPly)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
