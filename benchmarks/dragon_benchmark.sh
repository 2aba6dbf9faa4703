#!/usr/bin/env bash
# The large-mesh benchmark on the Stanford dragon (871,414 triangles), all measured in one run:
# OBJ load time (rtpro vs tinyobjloader), BVH build per backend, Mrays/s for primary and
# primary + shadow rays at 1024×1024, time to first image of the whole process, peak RSS and bytes
# per triangle (also with the lean memory settings), and Embree's own `viewer` (Debian package embree-tools) on the same model and
# camera when it is installed. Usage: benchmarks/dragon_benchmark.sh [--runs N] [--threads T]
#   --runs N (or RTPRO_BENCH_RUNS=N) repeats the whole-process runs N times, interleaved (default 3);
#   --threads T (or RTPRO_BENCH_THREADS=T) renders on T threads (default every core);
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
default_runs=${RTPRO_BENCH_RUNS:-3}
default_threads=${RTPRO_BENCH_THREADS:-$(nproc)}
source "$(dirname "$0")/options.sh"
single_thread_count
out="$build/benchmark-results/dragon"

"$root/scripts/fetch-dragon.sh" >/dev/null
build_release rtpro rtpro_backend_benchmark rtpro_mesh_load_benchmark
mkdir -p "$out"

"$build/benchmarks/rtpro_mesh_load_benchmark" --benchmark_min_time=2 \
  --benchmark_out="$out/load.json" --benchmark_out_format=json >"$out/load.log" 2>&1
RTPRO_BENCH_SCENES="$root/scenes/dragon.yaml" RTPRO_BENCH_SIZE=1024x1024 \
  "$build/benchmarks/rtpro_backend_benchmark" --benchmark_min_time=1 \
  --benchmark_filter='^(build|primary|primary_shadow)/' \
  --benchmark_out="$out/backend.json" --benchmark_out_format=json >"$out/backend.log" 2>&1

# The peers trace the mesh alone; so do the frames they are compared with ("same work"). The
# shipped scene's ground sphere and second light are kept in separate figures.
mesh="$root/assets/dragon.obj"
sed -e "s#../assets/dragon.obj#$mesh#" "$root/scenes/dragon.yaml" >"$out/scene.yaml"
sed -e 's/max_depth: 3/max_depth: 0/' -e '/^lights:/,/^world:/{/^  - /d}' -e 's/^lights:/lights: []/' \
  "$out/scene.yaml" >"$out/primary_ground.yaml"
sed -e 's/max_depth: 3/max_depth: 0/' -e '/type: directional/d' "$out/scene.yaml" >"$out/primary_shadow_ground.yaml"
for frame in primary primary_shadow; do sed '/type: sphere/d' "$out/${frame}_ground.yaml" >"$out/$frame.yaml"; done

# Time to first image: the whole process, from start to a written 1024x1024 PNG at 1 spp, of the
# peers' work (the mesh under primary rays) and of the shipped scene (ground, two lights,
# reflection to depth 3). The baseline is the shipped scene without the mesh (libraries and image).
# Whole rendered frames at 1024x1024, as a user runs them (load, build and shading included in the
# process, the rate from seconds.render): "primary" is the mesh without lights or reflection (one
# ray per sample, what the viewer's eyelight shader traces), "primary + shadow" adds one point light
# (one shadow ray per hit, as pathtracer --max-path-length 1 traces). 4 spp so that rendering, not
# start-up, dominates seconds.render; the primary frame also at 1 spp (a frame's fixed costs: film,
# tiles, output image) and 16 spp. The *_ground frames add the shipped scene's ground sphere,
# which the peers do not trace. Every measurement is repeated $runs times, interleaved with the
# peers' runs (the machine is shared); the report gives medians and the spread.
baseline_scene="$out/baseline.yaml"
sed '/dragon.obj/d' "$out/scene.yaml" >"$baseline_scene"
have_viewer=$(command -v viewer >/dev/null 2>&1 && echo 1 || echo 0)
have_pathtracer=$(command -v pathtracer >/dev/null 2>&1 && echo 1 || echo 0)
camera=(--vp -0.16 0.2 0.3 --vi 0 0.115 0 --vu 0 1 0 --fov 38 --threads "$threads")
for run in $(seq "$runs"); do
  if [ "$have_viewer" = 1 ]; then
    /usr/bin/time -f "%e %M" -o "$out/viewer-$run.time" viewer -i "$mesh" --size 1024 1024 "${camera[@]}" --shader eyelight \
      --benchmark 2 10 >"$out/viewer-$run.log" 2>&1 || true
  fi
  for backend in embree native; do
    for scene in primary dragon baseline; do
      file="$out/$scene.yaml"; [ "$scene" = dragon ] && file="$out/scene.yaml"
      /usr/bin/time -f "%e %M" -o "$out/$scene-$backend-$run.time" "$build/rtpro" render "$file" \
        -o "$out/$scene-$backend.png" --backend "$backend" --size 1024x1024 --spp 1 --threads "$threads" --quiet
    done
  done
  # The lean memory settings (docs/performance.md, "Memory"), for their peaks against the viewer's:
  # compact leaves and normals with Embree's SAH build, with its Morton build, and with the SAH
  # build in pieces of 131,072 triangles (7 for the dragon).
  for lean in compact morton pieces; do
    extra=(--embree-quality medium)
    [ "$lean" = morton ] && extra=(--embree-quality low)
    [ "$lean" = pieces ] && extra=(--embree-pieces 131072)
    /usr/bin/time -f "%e %M" -o "$out/dragon-lean-$lean-$run.time" "$build/rtpro" render "$out/scene.yaml" \
      -o "$out/dragon-lean.png" --embree-compact "${extra[@]}" --compact-normals --size 1024x1024 \
      --spp 1 --threads "$threads" --quiet
  done
  if [ "$have_pathtracer" = 1 ]; then
    pathtracer -i "$mesh" --size 1024 1024 "${camera[@]}" --max-path-length 1 --spp 1 --benchmark 2 10 \
      >"$out/pathtracer-$run.log" 2>&1 || true
  fi
  for frame in primary primary_shadow primary_ground primary_shadow_ground; do
    for backend in embree native; do
      "$build/rtpro" render "$out/$frame.yaml" -o "$out/frame-$frame-$backend.exr" --backend "$backend" \
        --size 1024x1024 --spp 4 --threads "$threads" --quiet --stats-json "$out/frame-$frame-$backend-$run.json"
    done
  done
  # The primary frame at 1 spp (its fixed per-frame costs weigh most) and 16 spp, beside the 4.
  for spp in 1 16; do
    for backend in embree native; do
      "$build/rtpro" render "$out/primary.yaml" -o "$out/frame-primary-$backend.exr" --backend "$backend" \
        --size 1024x1024 --spp "$spp" --threads "$threads" --quiet \
        --stats-json "$out/frame-primary-$backend-spp$spp-$run.json"
    done
  done
done

python3 - "$out" "$runs" "$have_viewer" "$have_pathtracer" <<'PY'
import json, statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
have_viewer, have_pathtracer = sys.argv[3] == "1", sys.argv[4] == "1"
triangles = 871414
load = {b["name"].split("/")[0]: b for b in json.load(open(f"{out}/load.json"))["benchmarks"]}
back = {b["name"].replace("/real_time", ""): b for b in json.load(open(f"{out}/backend.json"))["benchmarks"]}

def spread(values):
    """median, min, max"""
    return statistics.median(values), min(values), max(values)

def timed(name):
    """Median seconds and median peak MiB of a whole-process run over the runs."""
    pairs = [open(f"{out}/{name}-{run}.time").read().split() for run in range(1, runs + 1)]
    return spread([float(s) for s, _ in pairs]), statistics.median(int(kb) / 1024 for _, kb in pairs)

def benchmark_values(prefix, key):
    values = []
    for run in range(1, runs + 1):
        log = open(f"{out}/{prefix}-{run}.log").read()
        values += [float(l.split()[-1]) for l in log.splitlines() if l.startswith(key + " ")]
    return spread(values)

def fmt(m):
    return f"{m[0]:.2f} ({m[1]:.2f}-{m[2]:.2f})"

print("dragon.obj: load")
rt, tiny = load.get("BM_RtproObj"), load.get("BM_TinyObjLoader")
for label, b in (("rtpro", rt), ("rtpro, 1 thread", load.get("BM_RtproObjOneThread")), ("tinyobjloader", tiny),
                 ("rtpro PLY (ascii)", load.get("BM_RtproAsciiPly"))):
    if b: print(f"  {label:20} {b['real_time']:8.1f} ms  {b['bytes_per_second'] / 1e6:8.1f} MB/s")
if rt and tiny: print(f"  speed-up over tinyobjloader: {tiny['real_time'] / rt['real_time']:.1f}x")

print(f"\ndragon at 1024x1024: BVH build (ms) and trace-only loops (Mrays/s), peak RSS of the shipped scene")
print(f"  {'backend':8} {'build':>8} {'primary':>9} {'prim+shadow':>12} {'peak MiB':>9} {'B/tri':>7} {'B/tri>base':>11}")
rows = {}
for backend in ("native", "embree"):
    g = lambda k: back.get(f"{k}/dragon/{backend}")
    _, peak = timed(f"dragon-{backend}")
    _, base = timed(f"baseline-{backend}")
    rows[backend] = (g("build")["real_time"], g("primary")["Mrays/s"], g("primary_shadow")["Mrays/s"], peak)
    print(f"  {backend:8} {rows[backend][0]:8.1f} {rows[backend][1]:9.2f} {rows[backend][2]:12.2f} {peak:9.0f}"
          f" {peak * 1048576 / triangles:7.0f} {(peak - base) * 1048576 / triangles:11.0f}")
n, e = rows["native"], rows["embree"]
print(f"  {'e/n':8} {e[0] / n[0]:7.2f}x {e[1] / n[1]:8.2f}x {e[2] / n[2]:11.2f}x {e[3] / n[3]:8.2f}x")

print(f"\nwhole frames, 1024x1024 at 4 spp, median (min-max) of {runs} runs:"
      " camera samples per second of render, millions")
frames = {}
for frame in ("primary", "primary_shadow", "primary_ground", "primary_shadow_ground"):
    for backend in ("embree", "native"):
        stats = [json.load(open(f"{out}/frame-{frame}-{backend}-{run}.json")) for run in range(1, runs + 1)]
        frames[frame, backend] = spread([s["rays"]["camera"] / s["seconds"]["render"] / 1e6 for s in stats])
        all_kinds = statistics.median(s["rays"]["total"] / s["seconds"]["render"] / 1e6 for s in stats)
        total = statistics.median(s["seconds"]["total"] for s in stats)
        print(f"  {frame:22} {backend:7} {fmt(frames[frame, backend]):>20} Msamples/s  ({all_kinds:.2f} Mrays/s of all kinds,"
              f" total process {total:.2f} s)")
def against_peer(present, log, peer, unit, frame, label):
    """The peer's rate and rtpro's frames over it, on the mesh alone and with the ground sphere."""
    if not present:
        print(f"  {peer}: not run: install Debian's embree-tools")
        return
    rate = benchmark_values(log, "BENCHMARK_RENDER_MRAYPS_AVG")
    print(f"  {peer} (the mesh alone): {fmt(rate)} {unit}")
    ratio = lambda f, b: frames[f, b][0] / rate[0]
    print(f"  {label}: embree {ratio(frame, 'embree'):.2f}x, native {ratio(frame, 'native'):.2f}x (with the ground"
          f" sphere: {ratio(frame + '_ground', 'embree'):.2f}x, {ratio(frame + '_ground', 'native'):.2f}x)")

against_peer(have_viewer, "viewer", "Embree viewer --shader eyelight", "Mrays/s", "primary", "primary / viewer")
if have_viewer:
    viewer_rate = benchmark_values("viewer", "BENCHMARK_RENDER_MRAYPS_AVG")[0]
    primary_frames = {(backend, spp): [json.load(open(f"{out}/frame-primary-{backend}{'' if spp == 4 else f'-spp{spp}'}-{run}.json"))
                                       for run in range(1, runs + 1)]
                      for backend in ("embree", "native") for spp in (1, 4, 16)}
    for backend in ("embree", "native"):
        ratios = []
        for spp in (1, 4, 16):
            rate = spread([s["rays"]["camera"] / s["seconds"]["render"] / 1e6 for s in primary_frames[backend, spp]])
            ratios.append(f"{spp} spp {rate[0] / viewer_rate:.2f}x ({rate[1] / viewer_rate:.2f}-{rate[2] / viewer_rate:.2f})")
        print(f"  primary / viewer by samples per pixel, {backend}: " + ", ".join(ratios))
    # The render phase as a line in the samples per pixel (least squares over the three frames):
    # what a frame costs whatever its samples (film, tiles, output image, and the camera rays'
    # first, least coherent pass through the BVH) and what each further sample a pixel adds.
    print(f"  render phase = per frame + per sample a pixel, ms (the viewer's frame: {1048576 / viewer_rate / 1e3:.1f} ms):",
          end="")
    for backend in ("embree", "native"):
        points = [(spp, s["seconds"]["render"] * 1e3) for spp in (1, 4, 16) for s in primary_frames[backend, spp]]
        mean_n = statistics.mean(n for n, _ in points)
        mean_t = statistics.mean(t for _, t in points)
        slope = (sum((n - mean_n) * (t - mean_t) for n, t in points) / sum((n - mean_n) ** 2 for n, _ in points))
        print(f" {backend} {mean_t - slope * mean_n:.1f} + {slope:.1f}", end=";" if backend == "embree" else "\n")
against_peer(have_pathtracer, "pathtracer", "Embree pathtracer --max-path-length 1", "Msamples/s", "primary_shadow",
             "primary + shadow / pathtracer")

print(f"\ntime to first image: whole process to a 1024x1024 PNG at 1 spp, seconds, median (min-max) of {runs} runs")
first = {}
for backend in ("embree", "native"):
    for scene, label in (("primary", "the mesh, primary rays"), ("dragon", "the shipped scene")):
        first[scene, backend], _ = timed(f"{scene}-{backend}")
        print(f"  {label:24} {backend:7} {fmt(first[scene, backend])}")
if have_viewer:
    whole, viewer_peak = timed("viewer")
    print(f"  Embree viewer, load + build + 12 frames: {fmt(whole)} s, peak {viewer_peak:.0f} MiB")
    for backend in ("embree", "native"):
        print(f"  first image / viewer's whole process, {backend}: mesh {first['primary', backend][0] / whole[0]:.2f}x,"
              f" shipped scene {first['dragon', backend][0] / whole[0]:.2f}x")
# Peaks with and without the lean settings, the mesh's share per triangle, and against the viewer's
# when it ran.
for name, label in (("dragon-embree", "embree"), ("dragon-native", "native"),
                    ("dragon-lean-compact", "embree --embree-compact --compact-normals"),
                    ("dragon-lean-morton", "embree --embree-compact --embree-quality low --compact-normals"),
                    ("dragon-lean-pieces", "embree --embree-compact --compact-normals --embree-pieces 131072")):
    _, peak = timed(name)
    _, base = timed("baseline-native" if label == "native" else "baseline-embree")
    against = f", {peak / viewer_peak:.2f}x the viewer's" if have_viewer else ""
    print(f"  peak RSS of the shipped scene, {label}: {peak:.0f} MiB ({(peak - base) * 1048576 / triangles:.0f} B/tri"
          f" above the scene without the mesh){against}")
PY
