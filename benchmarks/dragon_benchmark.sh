#!/usr/bin/env bash
# The large-mesh benchmark on the Stanford dragon (871,414 triangles), all measured in one run:
# OBJ load time (rtpro vs tinyobjloader), BVH build per backend, Mrays/s for primary and
# primary + shadow rays at 1024×1024, time to first image of the whole process, peak RSS and bytes
# per triangle, and Embree's own `viewer` (Debian package embree-tools) on the same model and
# camera when it is installed. Usage: benchmarks/dragon_benchmark.sh
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${RTPRO_BUILD_DIR:-$root/build-release}
out="$build/benchmark-results/dragon"
threads=${RTPRO_BENCH_THREADS:-$(nproc)}

"$root/scripts/fetch-dragon.sh" >/dev/null
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTPRO_BUILD_TESTS=OFF >/dev/null
fi
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt" || { echo "$build is not a Release tree" >&2; exit 2; }
cmake --build "$build" --target rtpro rtpro_backend_benchmark rtpro_mesh_load_benchmark >/dev/null
mkdir -p "$out"

"$build/benchmarks/rtpro_mesh_load_benchmark" --benchmark_min_time=2 \
  --benchmark_out="$out/load.json" --benchmark_out_format=json >"$out/load.log" 2>&1
RTPRO_BENCH_SCENES="$root/scenes/dragon.yaml" RTPRO_BENCH_SIZE=1024x1024 \
  "$build/benchmarks/rtpro_backend_benchmark" --benchmark_min_time=1 \
  --benchmark_filter='^(build|primary|primary_shadow)/' \
  --benchmark_out="$out/backend.json" --benchmark_out_format=json >"$out/backend.log" 2>&1

# Time to first image: the whole process, from start to a written 1024×1024 PNG at 1 spp.
# The baseline is the same command on a scene without the mesh (libraries and image only).
baseline_scene="$out/baseline.yaml"
sed '/dragon.obj/d' "$root/scenes/dragon.yaml" >"$baseline_scene"
for backend in embree native; do
  for scene in dragon baseline; do
    file="$root/scenes/dragon.yaml"; [ "$scene" = baseline ] && file="$baseline_scene"
    /usr/bin/time -f "%e %M" -o "$out/$scene-$backend.time" "$build/rtpro" render "$file" -o "$out/$scene-$backend.png" \
      --backend "$backend" --size 1024x1024 --spp 1 --threads "$threads" --quiet
  done
done

# Whole rendered frames at 1024x1024, as a user runs them (load, build and shading included in the
# process, the rate from seconds.render): "primary" is the scene without lights or reflection (one
# ray per sample, what the viewer's eyelight shader traces), "primary + shadow" keeps the first
# light only (one shadow ray per hit, as pathtracer --max-path-length 1 traces). 4 spp so that
# rendering, not start-up, dominates seconds.render. The ground sphere stays in both variants, so rtpro
# traces a little more than the peers, whose scene is the mesh alone.
mesh="$root/assets/dragon.obj"
sed -e "s#../assets/dragon.obj#$mesh#" -e 's/max_depth: 3/max_depth: 0/' -e '/^lights:/,/^world:/{/^  - /d}' \
  -e 's/^lights:/lights: []/' "$root/scenes/dragon.yaml" >"$out/primary.yaml"
sed -e "s#../assets/dragon.obj#$mesh#" -e 's/max_depth: 3/max_depth: 0/' -e '/type: directional/d' \
  "$root/scenes/dragon.yaml" >"$out/primary_shadow.yaml"
for frame in primary primary_shadow; do
  for backend in embree native; do
    "$build/rtpro" render "$out/$frame.yaml" -o "$out/frame-$frame-$backend.exr" --backend "$backend" \
      --size 1024x1024 --spp 4 --threads "$threads" --quiet --stats-json "$out/frame-$frame-$backend.json"
  done
done
pathtracer_line="not run: install Debian's embree-tools for Embree's own pathtracer"
if command -v pathtracer >/dev/null 2>&1; then
  pathtracer -i "$mesh" --size 1024 1024 --vp -0.16 0.2 0.3 --vi 0 0.115 0 --vu 0 1 0 --fov 38 \
    --threads "$threads" --max-path-length 1 --spp 1 --benchmark 2 10 >"$out/pathtracer.log" 2>&1 || true
  pathtracer_line=""
fi

viewer_line="not run: install Debian's embree-tools for Embree's own viewer"
if command -v viewer >/dev/null 2>&1; then
  /usr/bin/time -f "%e %M" -o "$out/viewer.time" viewer -i "$root/assets/dragon.obj" --size 1024 1024 \
    --vp -0.16 0.2 0.3 --vi 0 0.115 0 --vu 0 1 0 --fov 38 --threads "$threads" --benchmark 2 10 >"$out/viewer.log" 2>&1 || true
  viewer_line=""
fi

python3 - "$out" "$viewer_line" "$pathtracer_line" <<'PY'
import json, sys
out, viewer_line, pathtracer_line = sys.argv[1], sys.argv[2], sys.argv[3]
triangles = 871414
load = {b["name"].split("/")[0]: b for b in json.load(open(f"{out}/load.json"))["benchmarks"]}
back = {b["name"].replace("/real_time", ""): b for b in json.load(open(f"{out}/backend.json"))["benchmarks"]}
def timed(name):
    seconds, kb = open(f"{out}/{name}.time").read().split()
    return float(seconds), int(kb) / 1024
print("dragon.obj: load")
rt, tiny = load.get("BM_RtproObj"), load.get("BM_TinyObjLoader")
for label, b in (("rtpro", rt), ("rtpro, 1 thread", load.get("BM_RtproObjOneThread")), ("tinyobjloader", tiny),
                 ("rtpro PLY (ascii)", load.get("BM_RtproAsciiPly"))):
    if b: print(f"  {label:20} {b['real_time']:8.1f} ms  {b['bytes_per_second'] / 1e6:8.1f} MB/s")
if rt and tiny: print(f"  speed-up over tinyobjloader: {tiny['real_time'] / rt['real_time']:.1f}x")
print("\ndragon at 1024x1024 (Mrays/s; build in ms)")
print(f"  {'backend':8} {'build':>8} {'primary':>9} {'prim+shadow':>12} {'first image s':>14} {'peak MiB':>9} {'B/tri':>7} {'B/tri>base':>11}")
rows = {}
for backend in ("native", "embree"):
    g = lambda k: back.get(f"{k}/dragon/{backend}")
    first_s, peak = timed(f"dragon-{backend}")
    _, base = timed(f"baseline-{backend}")
    rows[backend] = (g("build")["real_time"], g("primary")["Mrays/s"], g("primary_shadow")["Mrays/s"], first_s, peak)
    print(f"  {backend:8} {rows[backend][0]:8.1f} {rows[backend][1]:9.2f} {rows[backend][2]:12.2f} {first_s:14.2f} {peak:9.0f}"
          f" {peak * 1048576 / triangles:7.0f} {(peak - base) * 1048576 / triangles:11.0f}")
n, e = rows["native"], rows["embree"]
print(f"  {'e/n':8} {e[0] / n[0]:7.2f}x {e[1] / n[1]:8.2f}x {e[2] / n[2]:11.2f}x {e[3] / n[3]:13.2f}x {e[4] / n[4]:8.2f}x")
if viewer_line:
    print(f"\nEmbree viewer: {viewer_line}")
else:
    log = open(f"{out}/viewer.log").read()
    mrays = next((l.split()[-1] for l in log.splitlines() if l.startswith("BENCHMARK_RENDER_MRAYPS_AVG ")), "?")
    seconds, peak = timed("viewer")
    print(f"\nEmbree viewer (same model, camera, 1024x1024, primary rays): {float(mrays):.2f} Mrays/s,"
          f" peak {peak:.0f} MiB, {seconds:.2f} s for load + build + 12 frames")
    print(f"  rtpro embree / viewer: primary {e[1] / float(mrays):.2f}x, peak RSS {e[4] / peak:.2f}x")

def benchmark_value(log_name, key):
    log = open(f"{out}/{log_name}").read()
    return float(next((l.split()[-1] for l in log.splitlines() if l.startswith(key + " ")), "nan"))

print("\nwhole frames, 1024x1024 at 4 spp (camera samples per second of render, millions):")
frames = {}
for frame in ("primary", "primary_shadow"):
    for backend in ("embree", "native"):
        s = json.load(open(f"{out}/frame-{frame}-{backend}.json"))
        frames[frame, backend] = s["rays"]["camera"] / s["seconds"]["render"] / 1e6
        print(f"  {frame:15} {backend:7} {frames[frame, backend]:7.2f} Msamples/s  ({s['rays']['total'] / s['seconds']['render'] / 1e6:.2f} Mrays/s of all kinds,"
              f" total process {s['seconds']['total']:.2f} s)")
if not viewer_line:
    viewer = benchmark_value("viewer.log", "BENCHMARK_RENDER_MRAYPS_AVG")
    print(f"  primary: rtpro embree / viewer eyelight {frames['primary', 'embree'] / viewer:.2f}x, native / viewer {frames['primary', 'native'] / viewer:.2f}x")
if pathtracer_line:
    print(f"  Embree pathtracer: {pathtracer_line}")
else:
    tracer = benchmark_value("pathtracer.log", "BENCHMARK_RENDER_MRAYPS_AVG")
    print(f"  Embree pathtracer --max-path-length 1: {tracer:.2f} Msamples/s; rtpro primary + shadow embree / pathtracer"
          f" {frames['primary_shadow', 'embree'] / tracer:.2f}x, native / pathtracer {frames['primary_shadow', 'native'] / tracer:.2f}x")
PY
