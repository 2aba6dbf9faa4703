#!/usr/bin/env bash
# Random-walk subsurface scattering, rtpro beside Cycles (Debian's Blender 3.4): a sphere of radius 1
# filling the image under a uniform sky of radiance 1, its material a coloured subsurface medium
# (surface albedo [0.8, 0.5, 0.3], radius [1, 0.5, 0.25] × scale 0.5, anisotropy 0.3, ior 1.4) with
# each of Cycles' two random walks: `random_walk` (the radius scaled by the albedo) and
# `random_walk_fixed_radius`. Cycles renders its Subsurface Scattering node
# (benchmarks/cycles/render_subsurface.py builds the scene and states why that node); rtpro a
# `principled` material of subsurface 1 and specular_weight 0, the same model. Both at the same
# size, samples per pixel and path length, on the same thread count.
# Reported per method: each renderer's image mean per channel, their ratio, and the seconds of the
# render (Cycles' render call; rtpro's whole run, scene load included).
# Usage: benchmarks/cycles_subsurface_benchmark.sh [--threads "2"]
#   SIZE=64 SPP=64 MAX_DEPTH=64 BACKEND=native pick the work; RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-64}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-64}
backend=${BACKEND:-native}
t=${threads##* }
color="0.8,0.5,0.3"
radius="0.5,0.25,0.125"  # [1, 0.5, 0.25] × 0.5
anisotropy=0.3
ior=1.4
methods="RANDOM_WALK RANDOM_WALK_FIXED_RADIUS"
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-subsurface.XXXXXX")

echo "Cycles: ${size}x$size, $spp spp ..." >&2
# shellcheck disable=SC2086  # one argument per method
run_blender render_subsurface.py "$out/cycles.log" "$out/cycles" "$size" "$spp" "$max_depth" "$t" "$color" \
  "$radius" "$anisotropy" "$ior" $methods
for method in $methods; do
  keep_rgb "cycles-$method"
  cat >"$out/rtpro-$method.yaml" <<YAML
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 20, resolution: [$size, $size]}
render: {integrator: path, spp: $spp, max_depth: $max_depth, background: [1, 1, 1]}
materials:
  skin:
    type: principled
    color: [$color]
    specular_weight: 0
    ior: $ior
    subsurface: 1
    subsurface_radius: [1, 0.5, 0.25]
    subsurface_scale: 0.5
    subsurface_anisotropy: $anisotropy
    subsurface_method: $(echo "$method" | tr '[:upper:]' '[:lower:]')
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: skin}
YAML
  start=$(date +%s.%N)
  "$build/rtpro" render "$out/rtpro-$method.yaml" -o "$out/rtpro-$method.exr" --backend "$backend" --threads "$t" \
    --quiet --no-journal
  echo "rtpro_seconds $method $(echo "$(date +%s.%N) - $start" | bc)" >>"$out/rtpro.log"
done

python3 - "$out" "$size" "$spp" "$max_depth" "$backend" "$t" $methods <<'PY'
import re, subprocess, sys
out, size, spp, depth, backend, t = sys.argv[1:7]
methods = sys.argv[7:]
def means(name):
    text = subprocess.run(["iinfo", "--stats", f"{out}/{name}.exr"], check=True, capture_output=True, text=True).stdout
    return [float(v) for v in re.search(r"Stats Avg: ([^(]+)", text).group(1).split()][:3]
cycles_seconds = [float(s) for s in re.findall(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles.log").read())]
rtpro_seconds = dict(re.findall(r"rtpro_seconds (\S+) ([\d.]+)", open(f"{out}/rtpro.log").read()))
print(f"subsurface sphere under a uniform sky, {size}x{size}, {spp} spp, max depth {depth}, {t} thread(s); "
      f"rtpro on {backend}")
print("| method | Cycles mean R, G, B | rtpro mean R, G, B | rtpro / Cycles | Cycles s | rtpro s |")
print("|---|---|---|---|---|---|")
for method, s in zip(methods, cycles_seconds):
    c, r = means(f"cycles-{method}"), means(f"rtpro-{method}")
    ratio = ", ".join(f"{b / a:.3f}" for a, b in zip(c, r))
    print(f"| {method.lower()} | " + ", ".join(f"{v:.4f}" for v in c) + " | " + ", ".join(f"{v:.4f}" for v in r) +
          f" | {ratio} | {s:.2f} | {float(rtpro_seconds[method]):.2f} |")
print(f"images and logs: {out}")
PY
