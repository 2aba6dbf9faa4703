#!/usr/bin/env bash
# How much the light samplers of the path integrator buy, each against the strategy it replaces,
# as relMSE against a long reference of the same scene (rtpro compare --json), interleaved runs:
#   environment: a clay and a rough metal sphere (0.9 grey) on a ground under
#     scenes/environments/sunset.exr (benchmarks/scenes/sunset_spheres.yaml) at ENV_SPP spp, MIS
#     (environment importance sampling + BSDF sampling) against BSDF sampling alone; reference
#     REF_SPP spp with MIS, and the REF_SPP-spp means of the two strategies;
#   many lights: 10,000 small emissive spheres (powers over three decades) over a ground with a
#     few objects, the light tree against picking by power, at equal time: the tree at LIGHTS_SPP
#     spp, power at the spp that takes the same time (each one's time at LIGHTS_SPP measured
#     first, as whole processes, the scene's load included); reference: the tree at REF_SPP/4 spp.
# Usage: benchmarks/light_sampling_benchmark.sh [--runs N] [--threads "2"]   (the last count given)
#   SIZE=160 ENV_SPP=16 LIGHTS_SPP=16 REF_SPP=4096 pick the work; RTPRO_BUILD_DIR=DIR an existing
#   Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
size=${SIZE:-160}
env_spp=${ENV_SPP:-16}
lights_spp=${LIGHTS_SPP:-16}
ref_spp=${REF_SPP:-4096}
t=${threads##* }
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-lights.XXXXXX")
height=$((size * 5 / 8))

environment=("$root/benchmarks/scenes/sunset_spheres.yaml" --size "${size}x$height" -D "metal=[0.9, 0.9, 0.9]")

python3 - "$out/many_lights.yaml" "$size" "$height" <<'PY'
import random, sys
path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rng = random.Random(2024)
lines = ["rtpro: 1",
         f"camera: {{position: [0, 6, -32], look_at: [0, 0, 10], fov: 40, resolution: [{width}, {height}]}}",
         "render: {integrator: path, spp: 16, max_depth: 5}",
         "materials:",
         "  ground: {type: diffuse, color: [0.5, 0.5, 0.5]}",
         "  white: {type: diffuse, color: [0.8, 0.8, 0.8]}"]
colors = [(1.0, 0.6, 0.3), (0.4, 0.7, 1.0), (1.0, 1.0, 0.9), (0.9, 0.3, 0.6)]
for k, (r, g, b) in enumerate(colors):
    for decade in range(3):
        e = 10.0 ** (decade + 1)
        lines.append(f"  lamp_{k}_{decade}: {{type: diffuse, color: [0, 0, 0], emission: [{r * e:g}, {g * e:g}, {b * e:g}]}}")
lines.append("world:")
lines.append("  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: ground}")
for i in range(12):
    lines.append(f"  - {{type: sphere, center: [{rng.uniform(-20, 20):.3f}, 1.5, {rng.uniform(-10, 40):.3f}], radius: 1.5, material: white}}")
for i in range(10000):
    x, z, y = rng.uniform(-50, 50), rng.uniform(-20, 80), rng.uniform(0.3, 4.0)
    lines.append(f"  - {{type: sphere, center: [{x:.3f}, {y:.3f}, {z:.3f}], radius: 0.04, "
                 f"material: lamp_{rng.randrange(4)}_{rng.choices([0, 1, 2], [0.7, 0.25, 0.05])[0]}}}")
open(path, "w").write("\n".join(lines) + "\n")
PY

render() {  # OUT SPP SCENE [ARG...]: rtpro renders SCENE with the ARGs into $out/OUT.exr, timed
  local name=$1 spp=$2
  shift 2
  /usr/bin/time -f "%e" -o "$out/$name.seconds" "$build/rtpro" render "$@" -o "$out/$name.exr" \
    --spp "$spp" --threads "$t" --quiet --no-journal
}
many_lights=$out/many_lights.yaml

echo "references: $ref_spp spp ..." >&2
render env-reference "$ref_spp" "${environment[@]}"
render env-reference-bsdf "$ref_spp" "${environment[@]}" --set render.sampling=bsdf
render lights-reference "$((ref_spp / 4))" "$many_lights"

# The spp at which picking by power takes the tree's time.
render lights-probe-tree "$lights_spp" "$many_lights"
render lights-probe-power "$lights_spp" "$many_lights" --set render.light_sampler=power
power_spp=$(python3 -c "import sys; t=float(open('$out/lights-probe-tree.seconds').read().split()[-1]); \
p=float(open('$out/lights-probe-power.seconds').read().split()[-1]); print(max(1, round($lights_spp * t / p)))")

for r in $(seq "$runs"); do
  render "env-mis-r$r" "$env_spp" "${environment[@]}" --set render.seed="$r"
  render "env-bsdf-r$r" "$env_spp" "${environment[@]}" --set render.seed="$r" --set render.sampling=bsdf
  render "lights-tree-r$r" "$lights_spp" "$many_lights" --set render.seed="$r"
  render "lights-power-r$r" "$power_spp" "$many_lights" --set render.seed="$r" --set render.light_sampler=power
done
compare_each "$out/env-reference.exr" "$out"/env-*-r*.exr "$out"/env-reference-bsdf.exr
compare_each "$out/lights-reference.exr" "$out"/lights-*-r*.exr

python3 - "$out" "$runs" "$size" "$height" "$env_spp" "$lights_spp" "$power_spp" "$ref_spp" "$t" <<'PY'
import json, statistics, sys
out, runs, width, height, env_spp, lights_spp, power_spp, ref_spp, t = sys.argv[1:10]
runs = int(runs)
def rep(name): return json.load(open(f"{out}/{name}.compare.json"))
def secs(name): return float(open(f"{out}/{name}.seconds").read().split()[-1])
def row(label, prefix):
    rel = [rep(f"{prefix}-r{r}")["rel_mse"] for r in range(1, runs + 1)]
    tm = [secs(f"{prefix}-r{r}") for r in range(1, runs + 1)]
    print(f"  {label:34} relMSE median {statistics.median(rel):.5f} ({min(rel):.5f}-{max(rel):.5f})   "
          f"time median {statistics.median(tm):.2f} s ({min(tm):.2f}-{max(tm):.2f})")
    return statistics.median(rel)
print(f"{width}x{height}, {t} thread(s), {runs} interleaved runs (seeds 1..{runs})\n")
print(f"environment (sunset.exr), {env_spp} spp, against MIS at {ref_spp} spp:")
mis = row("MIS (environment + BSDF sampling)", "env-mis")
bsdf = row("BSDF sampling alone", "env-bsdf")
print(f"  relMSE ratio BSDF / MIS: {bsdf / mis:.1f}x")
m = rep("env-reference-bsdf")["means"]
print("  {0}-spp means, MIS {1}  BSDF alone {2}  (differ {3} %)".format(ref_spp,
      " ".join(f"{x:.5f}" for x in m["reference"]), " ".join(f"{x:.5f}" for x in m["test"]),
      " ".join(f"{100 * (b / a - 1):+.3f}" for a, b in zip(m["reference"], m["test"]))))
print(f"\n10,000 emissive spheres, equal time: tree {lights_spp} spp, power {power_spp} spp, "
      f"against the tree at {int(ref_spp) // 4} spp:")
tree = row(f"light tree, {lights_spp} spp", "lights-tree")
power = row(f"by power, {power_spp} spp", "lights-power")
print(f"  relMSE ratio power / tree at equal time: {power / tree:.1f}x")
print(f"\nimages and comparisons: {out}")
PY
