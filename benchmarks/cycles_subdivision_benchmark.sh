#!/usr/bin/env bash
# A subdivided, displaced cube, rtpro beside Cycles (Debian's Blender 3.4): the unit cube cage
# benchmarks/cycles/uv_cube_cage.obj (each face its own uv square) refined LEVEL=5 times
# (Catmull-Clark to the limit surface) and displaced along the normal by SCALE=0.2 x a texture,
# h(u, v) = sin²(πu) sin²(πv) (0.5 + u) (0.5 + v): a lopsided pillow on every face, 0 on the
# cube's edges so both sides of a uv seam move alike, and lopsided so a flipped u or v would show.
# rtpro renders `subdivision: {level}` with `displacement: {texture, scale}`; Cycles a Subdivision Surface
# modifier of the same render level with true displacement (a Displacement node of Midlevel 0:
# Blender's default 0.5 would pull the surface in by half the scale; benchmarks/cycles/
# render_subdivision.py says how the rest is matched). A clay Lambert surface under a uniform sky
# of 0.3 and a sun of irradiance 2, the sky hidden from the camera (black behind the object in both).
# Reported: each renderer's image mean per channel and rtpro / Cycles (the floor: within 2%), the
# relMSE between the two images (both noisy at SPP), the silhouettes' agreement (Cycles' alpha
# against rtpro's coverage, the albedo AOV of the surface made white: soft
# IoU = Σ min / Σ max, and the fraction of the pixels either covers by more than half that only one
# does), and the seconds at equal samples (Cycles' render call, modifier and displacement included;
# rtpro's whole run, and its load, refinement, build and render phases alone), medians and spread of
# RUNS interleaved runs.
# Usage: benchmarks/cycles_subdivision_benchmark.sh [--runs N] [--threads "2"]
#   SIZE=256 SPP=64 MAX_DEPTH=8 LEVEL=5 SCALE=0.2 BACKEND=embree; RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-256}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-8}
level=${LEVEL:-5}
scale=${SCALE:-0.2}
backend=${BACKEND:-embree}
t=${threads##* }
color="0.8,0.5,0.3"
sky=0.3
sun_direction="-0.5,-1,0.7"
sun=2
camera="1.7,1.4,-2.4"
target="0,0,0"
fov=32
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-subdivision.XXXXXX")
cp "$root/benchmarks/cycles/uv_cube_cage.obj" "$out/cage.obj"

# The displacement texture, 256 x 256 (a PFM, which plain Python writes, made an EXR).
python3 - "$out/bump.pfm" <<'PY'
import array, math, sys
n = 256
rows = array.array("f")
for row in range(n):  # PFM rows run from the bottom (v = 0) up
    v = (row + 0.5) / n
    for column in range(n):
        u = (column + 0.5) / n
        rows.extend([math.sin(math.pi * u) ** 2 * math.sin(math.pi * v) ** 2 * (0.5 + u) * (0.5 + v)] * 3)
with open(sys.argv[1], "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (n, n))
    rows.tofile(f)  # little-endian on x86, as the -1.0 scale says
PY
oiiotool "$out/bump.pfm" -d float -o "$out/bump.exr"

rtpro_scene() {  # rtpro_scene NAME MATERIAL LIGHTING DEPTH
  cat >"$out/$1.yaml" <<YAML
rtpro: 1
camera: {position: [$camera], look_at: [$target], fov: $fov, resolution: [$size, $size]}
render: {integrator: path, spp: $spp, max_depth: $4, seed: 0, light_units: radiometric, background: [0, 0, 0]}
materials: {clay: $2}
$3
world:
  - {type: mesh, file: cage.obj, material: clay, subdivision: {level: $level},
     displacement: {texture: bump.exr, scale: $scale}}
YAML
}
rtpro_scene rtpro "{type: diffuse, color: [$color]}" "environment: {color: [$sky, $sky, $sky], visible: false}
lights: [{type: directional, direction: [$sun_direction], intensity: $sun}]" "$max_depth"
rtpro_scene coverage "{type: diffuse, color: [1, 1, 1]}" "" 1

interleaved_runs render_subdivision.py "$out/cage.obj" "$out/bump.exr" "$level" "$scale" "$color" \
  "$sky" "$sun_direction" "$sun" "$camera" "$target" "$fov"
coverage_and_compare --backend "$backend" --threads "$t"

python3 "$root/benchmarks/cycles/peer_report.py" "$out" "$runs" \
  "subdivided, displaced cube (level $level, scale $scale), ${size}x$size, $spp spp, max depth $max_depth, $t thread(s), rtpro on $backend"
