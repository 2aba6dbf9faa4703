#!/usr/bin/env bash
# Rough glass in a white furnace, rtpro beside Cycles (Debian's Blender 3.4): a glass sphere of ior
# 1.5 filling the image under a uniform sky of radiance 1, which a glass that neither creates nor
# loses light leaves at 1 in every pixel. Cycles renders its Principled BSDF with Transmission 1 and
# multiple-scattering GGX (benchmarks/cycles/render_glass_furnace.py builds the scene and states
# its settings); rtpro its `principled` (transmission_weight 1) and `dielectric` glass, both
# energy-compensated, on one backend (the other gives the same pixels: the sphere is analytic on
# both). All at the same size, samples per pixel, path length and roughnesses.
# Reported per roughness and renderer: the image's mean and its largest pixel (a firefly shows
# there first), and, for Cycles, the seconds of its render call.
# Usage: benchmarks/cycles_glass_furnace_benchmark.sh [--threads "2"]
#   SIZE=64 SPP=256 MAX_DEPTH=64 ROUGHNESS="0 0.1 0.3 0.5 0.7 1" BACKEND=native pick the work;
#   RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-64}
spp=${SPP:-256}
max_depth=${MAX_DEPTH:-64}
roughness=${ROUGHNESS:-0 0.1 0.3 0.5 0.7 1}
backend=${BACKEND:-native}
t=${threads##* }
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-glass-furnace.XXXXXX")

echo "Cycles: ${size}x$size, $spp spp, roughness $roughness ..." >&2
# shellcheck disable=SC2086  # one argument per roughness
run_blender render_glass_furnace.py "$out/cycles.log" "$out/cycles" "$size" "$spp" "$max_depth" "$t" $roughness
for r in $roughness; do
  keep_rgb "cycles-$r"
  for kind in principled dielectric; do
    material="{type: dielectric, ior: 1.5, roughness: $r}"
    [ "$kind" = principled ] &&
      material="{type: principled, color: [1, 1, 1], transmission_weight: 1, ior: 1.5, roughness: $r}"
    cat >"$out/$kind-$r.yaml" <<YAML
rtpro: 1
camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 20, resolution: [$size, $size]}
render: {integrator: path, spp: $spp, max_depth: $max_depth, background: [1, 1, 1]}
materials:
  glass: $material
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: glass}
YAML
    "$build/rtpro" render "$out/$kind-$r.yaml" -o "$out/$kind-$r.exr" --backend "$backend" --threads "$t" \
      --quiet --no-journal
  done
done

python3 - "$out" "$size" "$spp" "$max_depth" "$backend" "$t" $roughness <<'PY'
import re, subprocess, sys
out, size, spp, depth, backend, t = sys.argv[1:7]
roughnesses = sys.argv[7:]
def stats(name):
    """The mean and the largest value of the image's pixels over its R, G and B channels."""
    text = subprocess.run(["iinfo", "--stats", f"{out}/{name}.exr"], check=True, capture_output=True, text=True).stdout
    channels = lambda key: [float(v) for v in re.search(rf"Stats {key}: ([^(]+)", text).group(1).split()]
    return sum(channels("Avg")) / 3, max(channels("Max"))
seconds = [float(s) for s in re.findall(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles.log").read())]
print(f"rough glass furnace (ior 1.5, radiance 1), {size}x{size}, {spp} spp, max depth {depth} "
      f"(Cycles {int(depth) - 1} bounces), {t} thread(s); rtpro on {backend}")
print("| roughness | Cycles Principled MULTI_GGX: mean, max | rtpro principled: mean, max | rtpro dielectric: mean, max | Cycles s |")
print("|---|---|---|---|---|")
for r, s in zip(roughnesses, seconds):
    cells = [stats(f"{who}-{r}") for who in ("cycles", "principled", "dielectric")]
    print(f"| {r} | " + " | ".join(f"{m:.4f}, {x:.4f}" for m, x in cells) + f" | {s:.1f} |")
print(f"images and logs: {out}")
PY
