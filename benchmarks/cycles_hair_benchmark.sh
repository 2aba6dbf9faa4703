#!/usr/bin/env bash
# Hair, rtpro beside Cycles (Debian's Blender 3.4): the 2000 strands of scenes/meshes/fur_ball.hair
# (6 points each, tapering; scripts/make_fur_ball_hair.py) as round Catmull-Rom curves through the
# points, of a hair fibre with σa = SIGMA_A (per unit radius; [0.25, 0.4, 0.8]: light brown), β_m =
# BETA_M (0.3), β_n = BETA_N (0.3), α = ALPHA (2°) and ior 1.55. rtpro renders `type: curves` with
# `type: hair`; Cycles the same strands as a Curves object with the Principled Hair BSDF (Chiang,
# Absorption Coefficient parametrization, coat 0, Offset −α: Cycles tilts the cuticle the other
# way; benchmarks/cycles/render_hair.py builds the strands in Blender and says how the rest is
# matched). Lit by a uniform sky of 0.5 and a sun of
# irradiance 2 from the camera's upper left, the sky hidden from the camera (black behind the hair).
# Reported: each renderer's image mean per channel and rtpro / Cycles (the floor: within 5%), relMSE
# of rtpro's image against Cycles' (both at SPP), the silhouettes' agreement (Cycles' alpha
# against rtpro's coverage, the albedo AOV of the fibres made white), and the seconds at equal
# samples (Cycles' render call; rtpro's whole run and its phases), medians and spread of RUNS
# interleaved runs.
# Usage: benchmarks/cycles_hair_benchmark.sh [--runs N] [--threads "2"]
#   SIZE=200 SPP=64 MAX_DEPTH=32 BACKEND=embree SIGMA_A=0.25,0.4,0.8 BETA_M=0.3 BETA_N=0.3 ALPHA=2;
#   RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-200}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-32}
backend=${BACKEND:-embree}
sigma_a=${SIGMA_A:-0.25,0.4,0.8}
beta_m=${BETA_M:-0.3}
beta_n=${BETA_N:-0.3}
alpha=${ALPHA:-2}
ior=1.55
t=${threads##* }
sky=0.5
sun_direction="0.6,-0.7,0.5"
sun=2
camera="0,0.5,-3.6"
target="0,0.35,0"
fov=40
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-hair.XXXXXX")
cp "$root/scenes/meshes/fur_ball.hair" "$out/strands.hair"

rtpro_scene() {  # rtpro_scene NAME MATERIAL LIGHTING DEPTH
  cat >"$out/$1.yaml" <<YAML
rtpro: 1
camera: {position: [$camera], look_at: [$target], fov: $fov, resolution: [$size, $size]}
render: {integrator: path, spp: $spp, max_depth: $4, seed: 0, light_units: radiometric, background: [0, 0, 0]}
materials: {fibre: $2}
$3
world: [{type: curves, file: strands.hair, basis: catmull-rom, shape: round, material: fibre}]
YAML
}
rtpro_scene rtpro "{type: hair, sigma_a: [$sigma_a], beta_m: $beta_m, beta_n: $beta_n, alpha: $alpha, ior: $ior}" \
  "environment: {color: [$sky, $sky, $sky], visible: false}
lights: [{type: directional, direction: [$sun_direction], intensity: $sun}]" "$max_depth"
rtpro_scene coverage "{type: diffuse, color: [1, 1, 1]}" "" 1

interleaved_runs render_hair.py "$out/strands.hair" "$sigma_a" "$beta_m" "$beta_n" "$alpha" "$ior" \
  "$sky" "$sun_direction" "$sun" "$camera" "$target" "$fov"
coverage_and_compare --backend "$backend" --threads "$t"

python3 "$root/benchmarks/cycles/peer_report.py" "$out" "$runs" \
  "2000 hair strands (σa $sigma_a, β_m $beta_m, β_n $beta_n, α $alpha°), ${size}x$size, $spp spp, max depth $max_depth, $t thread(s), rtpro on $backend"
