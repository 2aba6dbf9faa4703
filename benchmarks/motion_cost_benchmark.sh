#!/usr/bin/env bash
# The cost of motion blur on the Stanford dragon (871,414 triangles), each blurred frame against the
# same frame with the shutter closed (--shutter 0,0), both backends, both integrators, in one run:
#   transform: the dragon as an instance turning 20° about y and sliding 0.02 units during the
#              shutter (YAML keyframes; rtpro takes as many transform steps as keep the turn on its
#              arc);
#   deform:    the dragon as a glTF file with a morph target whose weight rises linearly from 0 to
#              0.5 during the shutter (benchmarks/make_morph_dragon.py): its vertices move on
#              straight lines, so rtpro takes 2 vertex time steps;
#   curved:    the same with the weight rising along a curve (keyed 33 times), which takes more
#              steps (the count is reported).
# Reported: seconds.render (median over the runs, and its spread), the ratio blurred / static,
# CPU seconds of the whole process, and memory: the --stats-json geometry and acceleration bytes
# and the peak RSS, each as bytes per triangle more than the static frame's.
# Usage: benchmarks/motion_cost_benchmark.sh [--runs N] [--threads T]
#   --runs N (or RTPRO_BENCH_RUNS=N) repeats every render N times, interleaved (default 3);
#   --threads T (or RTPRO_BENCH_THREADS=T) renders on T threads (default every core);
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/;
#   RTPRO_BENCH_SIZE=WxH, RTPRO_BENCH_SPP=N (default 480x360, 4 spp);
#   RTPRO_BENCH_INTEGRATORS="whitted path" (default both).
set -euo pipefail
default_runs=${RTPRO_BENCH_RUNS:-3}
default_threads=${RTPRO_BENCH_THREADS:-$(nproc)}
source "$(dirname "$0")/options.sh"
single_thread_count
out="$build/benchmark-results/motion_cost"
size=${RTPRO_BENCH_SIZE:-480x360}
spp=${RTPRO_BENCH_SPP:-4}
integrators=${RTPRO_BENCH_INTEGRATORS:-whitted path}

"$root/scripts/fetch-dragon.sh" >/dev/null
build_release rtpro
mkdir -p "$out"
mesh="$root/assets/dragon.obj"
[ -s "$out/dragon_morph.gltf" ] || python3 "$root/benchmarks/make_morph_dragon.py" "$mesh" "$out/dragon_morph.gltf"
[ -s "$out/dragon_curved.gltf" ] ||
  python3 "$root/benchmarks/make_morph_dragon.py" "$mesh" "$out/dragon_curved.gltf" 0.05 0.041666667 curved

# scenes/dragon.yaml's camera, lights and materials; the dragon placed by a keyframed instance.
# At frame 1 with the shutter [-0.25, 0.25] the instance turns from -10° to +10°.
cat >"$out/transform.yaml" <<YAML
rtpro: 1
camera: {position: [-0.16, 0.2, 0.3], look_at: [0.0, 0.115, 0.0], fov: 38, resolution: [640, 480]}
render: {spp: 16, max_depth: 3, ambient: 0.15, background: [0.55, 0.65, 0.8]}
materials:
  jade: {color: [0.35, 0.7, 0.45], specular: 0.6, shininess: 40, reflectivity: 0.08}
  floor: {color: [0.75, 0.72, 0.68], specular: 0.1, reflectivity: 0.25}
lights:
  - {type: point, position: [-0.6, 1.2, 0.8], color: [1.0, 0.96, 0.9], intensity: 0.9}
  - {type: directional, direction: [0.6, -1.0, -0.3], color: [0.6, 0.7, 0.9], intensity: 0.35}
objects:
  dragon: [{type: mesh, file: $mesh, material: jade, normals: smooth}]
world:
  - {type: instance, object: dragon,
     transform: {rotate: {axis: [0, 1, 0], angle: {keyframes: {0: -40, 2: 40}}},
                 translate: {keyframes: {0: [-0.04, 0, 0], 2: [0.04, 0, 0]}}}}
  - {type: sphere, center: [0, -999.9473, 0], radius: 1000, material: floor}
YAML
# The same with the morphed glTF in place of the instance; rendered at frame 0.25, whose shutter
# [-0.25, 0.25] spans 0 to 1/48 s: the weight goes from 0 to 0.5.
sed -e "s#  - {type: instance, object: dragon,#  - {type: mesh, file: dragon_morph.gltf, material: jade}#" \
  -e '/transform: {rotate/d' -e '/translate: {keyframes/d' -e '/^objects:/d' -e '/^  dragon:/d' \
  "$out/transform.yaml" >"$out/deform.yaml"
sed -e "s#dragon_morph.gltf#dragon_curved.gltf#" "$out/deform.yaml" >"$out/curved.yaml"

for run in $(seq "$runs"); do
  for integrator in $integrators; do
    for backend in embree native; do
      for scene in transform deform curved; do
        frame=1; [ "$scene" != transform ] && frame=0.25
        for shutter in static blurred; do
          range=0,0; [ "$shutter" = blurred ] && range=-0.25,0.25
          name="$scene-$shutter-$integrator-$backend-$run"
          /usr/bin/time -f "%e %U %S %M" -o "$out/$name.time" "$build/rtpro" render "$out/$scene.yaml" \
            -o "$out/$scene-$shutter-$integrator-$backend.exr" -D frame=$frame --shutter=$range \
            --integrator "$integrator" --backend "$backend" --size "$size" --spp "$spp" --threads "$threads" \
            --quiet --stats-json "$out/$name.json"
        done
      done
    done
  done
done

python3 - "$out" "$runs" "$integrators" <<'PY'
import json, statistics, sys
out, runs, integrators = sys.argv[1], int(sys.argv[2]), sys.argv[3].split()
def load(name):
    stats = [json.load(open(f"{out}/{name}-{r}.json")) for r in range(1, runs + 1)]
    times = [open(f"{out}/{name}-{r}.time").read().split() for r in range(1, runs + 1)]
    render = [s["seconds"]["render"] for s in stats]
    cpu = [float(t[1]) + float(t[2]) for t in times]
    rss = max(int(t[3]) * 1024 for t in times)
    return {"render": render, "cpu": cpu, "rss": rss, "stats": stats[0]}
def spread(values):
    return f"{statistics.median(values):.2f} s ({min(values):.2f}-{max(values):.2f})"
print(f"motion cost, {runs} interleaved runs; load average {open('/proc/loadavg').read().split()[0]} at the end")
floors = {"transform": 1.3, "deform": 1.6, "curved": 1.6}
for integrator in integrators:
    for backend in ["embree", "native"]:
        for scene in ["transform", "deform", "curved"]:
            s = load(f"{scene}-static-{integrator}-{backend}")
            b = load(f"{scene}-blurred-{integrator}-{backend}")
            ratio = statistics.median(b["render"]) / statistics.median(s["render"])
            cpu_ratio = statistics.median(b["cpu"]) / statistics.median(s["cpu"])
            triangles = s["stats"]["triangles"]
            mem_s, mem_b = s["stats"]["memory_bytes"], b["stats"]["memory_bytes"]
            per = lambda key: (mem_b[key] - mem_s[key]) / triangles
            verdict = "meets" if ratio <= floors[scene] else "MISSES"
            print(f"{integrator:7} {backend:6} {scene:9} static {spread(s['render'])}  blurred {spread(b['render'])}"
                  f"  ratio {ratio:.2f} ({verdict} <= {floors[scene]}), process CPU ratio {cpu_ratio:.2f};"
                  f" bytes/triangle more: geometry {per('geometry'):.1f}, acceleration {per('acceleration'):.1f},"
                  f" peak RSS {(b['rss'] - s['rss']) / triangles:.1f}")
PY
