#!/usr/bin/env bash
# A Catmull-Clark subdivision model of Debian's embree-tools (MODEL=subdiv5: an 11-face cage of
# quads, a pentagon and triangles, seen from its subdiv5.ecs camera) rendered by Embree's own
# `pathtracer` and by rtpro on both backends, side by side in one run. Embree subdivides it itself
# (RTC_GEOMETRY_TYPE_SUBDIVISION; its tutorial scene gives every edge a fixed tessellation level of
# 4, i.e. 4 x 4 quads per quad face), rtpro reads the same cage as an OBJ
# (benchmarks/embree_subdiv_to_obj.py) and refines it with OpenSubdiv at LEVEL=2 (2^2 = 4 segments
# per cage edge: the same 320 triangles) into triangles. The benchmark's copy of the XML pins the
# cage's boundary corners (subdiv_mode="pin_corners"), OpenSubdiv's edge-and-corner rule that rtpro
# uses, so both trace the same limit surface. Lights as fur_ball_benchmark.sh: a directional light
# of 3 along [1, -1, 1] and an ambient (environment) of 1; a white Lambert surface (the model's Kd 1);
# Embree's tutorial camera is mirrored left-right against rtpro's: the same rays, the image flopped.
# Reported: Mrays/s (Embree's BENCHMARK_RENDER_MRAYPS_AVG over FRAMES timed frames of 1 spp after 1
# warm-up; rtpro's rays over its render phase at FRAMES spp) and Mpaths/s, medians and spread of RUNS
# interleaved runs per thread count; each side's build (Embree's BVH4<subdivpatch1> builder as its
# verbose log times it: it tessellates the grids as it builds; rtpro's OpenSubdiv refinement, the
# load time above that of the same scene at level 0, plus its BVH build) and bytes per subdivided
# triangle (Embree: the builder's BVH and grid bytes over the triangles of the same tessellation;
# rtpro: its geometry and acceleration bytes). Then rtpro alone at FINE_LEVEL=6 (64 segments per cage
# edge), where the refinement's cost per triangle is no longer lost in the start-up.
# Usage: benchmarks/embree_subdiv_benchmark.sh [--runs N] [--threads "1 2"]
#   MODEL=subdiv5 SIZE=256 FRAMES=8 DEPTH=8 LEVEL=2 FINE_LEVEL=6; RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
command -v pathtracer >/dev/null || { echo "pathtracer not found: apt-get install embree-tools" >&2; exit 2; }
models=/usr/share/doc/embree3/models
model=${MODEL:-subdiv5}
size=${SIZE:-256}
frames=${FRAMES:-8}
depth=${DEPTH:-8}
level=${LEVEL:-2}
fine_level=${FINE_LEVEL:-6}
build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-subdiv.XXXXXX")
xml=$models/$model.xml
[ -f "$xml" ] || xml=$xml.gz
keys=$(python3 "$root/benchmarks/embree_subdiv_to_obj.py" "$xml" "$out/$model.obj")
case "$xml" in *.gz) reader=(gunzip -c) ;; *) reader=(cat) ;; esac
"${reader[@]}" "$xml" | sed 's/<position_indices\( subdiv_mode="[a-z_]*"\)\{0,1\}>/<position_indices subdiv_mode="pin_corners">/' \
  >"$out/$model.xml"
# The ecs file's camera (-vp, -vi, -vu, -fov), as the peer reads it (line 1), for rtpro (line 2).
{ read -r -a view; read -r camera; } < <(python3 - "$models/$model.ecs" <<'PY'
import sys
words, values = open(sys.argv[1]).read().split(), {}
for i, w in enumerate(words):
    if w in ("-vp", "-vi", "-vu", "-fov"):
        values[w] = words[i + 1:i + (2 if w == "-fov" else 4)]
print(" ".join(f"{k} {' '.join(v)}" for k, v in values.items()))
vec = lambda k: "[" + ", ".join(values[k]) + "]"
print(f"position: {vec('-vp')}, look_at: {vec('-vi')}, up: {vec('-vu')}, fov: {values['-fov'][0]}")
PY
)
scene() {  # scene LEVEL: the rtpro scene at that subdivision level
  cat >"$out/rtpro-level$1.yaml" <<YAML
rtpro: 1
camera: {$camera, resolution: [$size, $size]}
render: {integrator: path, spp: 1, max_depth: $depth}
lights: [{type: directional, direction: [1, -1, 1], color: [1, 1, 1], intensity: 3}]
environment: {color: [1, 1, 1]}
materials: {white: {type: diffuse, color: [1, 1, 1]}}
world: [{type: mesh, file: $model.obj, material: white, subdivision: {level: $1${keys:+, $keys}}}]
YAML
}
for l in 0 "$level" "$fine_level"; do scene "$l"; done

rtpro_run() {  # rtpro_run LEVEL BACKEND THREADS NAME
  "$build/rtpro" render "$out/rtpro-level$1.yaml" -o "$out/rtpro.exr" --spp "$frames" --threads "$3" --backend "$2" \
    --quiet --no-journal --stats-json "$out/$4.json"
}
for t in $threads; do
  for r in $(seq "$runs"); do
    verbose=()
    [ "$r" != 1 ] || verbose=(--rtcore verbose=2)  # the builder's time and bytes, once per thread count
    (cd "$out" && pathtracer -i "$model.xml" "${view[@]}" --ambientlight 1 1 1 --directionallight 1 -1 1 3 3 3 \
      --size "$size" "$size" --spp 1 --max-path-length "$depth" --threads "$t" "${verbose[@]}" \
      --benchmark 1 "$frames" >"$out/embree-t$t-r$r.log" 2>&1)
    for backend in embree native; do
      rtpro_run "$level" "$backend" "$t" "rtpro-$backend-t$t-r$r"
      rtpro_run 0 "$backend" "$t" "rtpro-level0-$backend-t$t-r$r"
      rtpro_run "$fine_level" "$backend" "$t" "rtpro-fine-$backend-t$t-r$r"
    done
  done
done

python3 - "$out" "$runs" "$threads" "$frames" "$size" "$depth" "$model" "$level" "$fine_level" <<'PY'
import json, re, statistics, sys
out, runs, threads, frames, size, depth, model, level, fine = (sys.argv[1], int(sys.argv[2]), sys.argv[3].split(),
                                                              *map(int, sys.argv[4:7]), sys.argv[7], *sys.argv[8:])
paths = frames * size * size
def stats(name):
    return json.load(open(f"{out}/{name}.json"))
def embree(t, r):
    log = open(f"{out}/embree-t{t}-r{r}.log").read()
    fps = float(re.search(r"BENCHMARK_RENDER_AVG ([\d.]+)", log).group(1))
    return float(re.search(r"BENCHMARK_RENDER_MRAYPS_AVG ([\d.]+)", log).group(1)), fps * size * size / 1e6
def embree_build(t):
    # The tutorial commits the scene more than once: the builds of the final set of grid patches
    # (the most primitives), the fastest of them, and the allocator's bytes in use after it.
    log = open(f"{out}/embree-t{t}-r1.log").read()
    builds = [(int(p), float(ms), float(mb)) for ms, p, mb in re.findall(
        r"finished BVH\S*subdivpatch\S* : ([\d.]+)ms.*?primitives = (\d+).*?^\s*total : used =\s*([\d.]+) MB", log, re.S | re.M)]
    most = max(p for p, _, _ in builds)
    return min(ms for p, ms, _ in builds if p == most) / 1e3, max(mb for p, _, mb in builds if p == most) * 1e6
def rtpro(prefix, backend, t, r):
    s = stats(f"{prefix}-{backend}-t{t}-r{r}")
    base = stats(f"rtpro-level0-{backend}-t{t}-r{r}")
    refine = max(s["seconds"]["load"] - base["seconds"]["load"], 0.0)
    seconds = s["seconds"]["render"]
    return (s["rays"]["total"] / seconds / 1e6, paths / seconds / 1e6, refine, s["seconds"]["build"],
            sum(s["memory_bytes"][k] for k in ("geometry", "acceleration")) / s["triangles"], s["triangles"])
def row(name, t, rows, em=None, build=None):
    m, q = statistics.median(x[0] for x in rows), statistics.median(x[1] for x in rows)
    ratio = f"{m / em:6.2f}x" if em else f"{'':>7}"
    refine = f"{build[0] * 1e3:9.2f}" if build[0] is not None else f"{'-':>9}"
    print(f"{name:26} {t:>3} {m:8.3f} {min(x[0] for x in rows):6.3f}-{max(x[0] for x in rows):<6.3f} {q:9.3f} {ratio} "
          f"{refine} {build[1] * 1e3:8.2f} {build[2]:8.0f} {build[3]:>9}")
print(f"{model} (Embree's subdivision geometry, edge level 4; rtpro OpenSubdiv level {level}), {size}x{size}, "
      f"path length {depth}, {frames} spp, {runs} interleaved runs\n")
print(f"{'renderer':26} {'thr':>3} {'Mrays/s':>8} {'min-max':>13} {'Mpaths/s':>9} {'xEmbree':>7} {'refine ms':>9} "
      f"{'build ms':>8} {'B/tri':>8} {'triangles':>9}")
for t in threads:
    e = [embree(t, r) for r in range(1, runs + 1)]
    em = statistics.median(x[0] for x in e)
    seconds, total_bytes = embree_build(t)
    rows = {b: [rtpro("rtpro", b, t, r) for r in range(1, runs + 1)] for b in ("embree", "native")}
    triangles = rows["embree"][0][5]
    row("Embree pathtracer", t, e, build=(None, seconds, total_bytes / triangles, triangles))
    for prefix, label in (("rtpro", f"level {level}"), ("rtpro-fine", f"level {fine}")):
        for backend in ("embree", "native"):
            rs = rows[backend] if prefix == "rtpro" else [rtpro(prefix, backend, t, r) for r in range(1, runs + 1)]
            med = lambda i: statistics.median(x[i] for x in rs)
            row(f"rtpro {backend} {label}", t, rs, em, (med(2), med(3), med(4), rs[0][5]))
print("\nrefine ms: OpenSubdiv's refinement (rtpro's load above the level-0 load; Embree tessellates in its build)")
print(f"logs, scenes and statistics: {out}")
PY
