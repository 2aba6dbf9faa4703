#!/usr/bin/env bash
# Random-walk subsurface scattering, rtpro beside Cycles (Debian's Blender 3.4): a sphere of radius 1
# filling the image under a uniform sky of radiance 1, its material a coloured subsurface medium
# (surface albedo [0.8, 0.5, 0.3], radius [1, 0.5, 0.25] × scale 0.5, anisotropy 0.3, ior 1.4) with
# each of Cycles' two random walks: `random_walk` (the radius scaled by the albedo) and
# `random_walk_fixed_radius`. Cycles renders its Subsurface Scattering node
# (benchmarks/cycles/render_subsurface.py builds the scene and states why that node); rtpro a
# `principled` material of subsurface 1 and specular_weight 0, the same model. Both at the same
# size, samples per pixel and path length, on 1 and 2 threads, the runs interleaved (Cycles' two
# methods, then rtpro's, again and again) with the load average recorded beside each.
# Reported per method and thread count: each renderer's image mean per channel (median over runs)
# and their ratio; the time at equal spp (median and spread; Cycles' render call, BVH build
# included; rtpro's whole run, scene load included), in wall seconds and in CPU seconds of all
# threads (the steadier figure on a loaded machine); relMSE at equal spp and at equal time, each
# renderer against its own long render (REF_SPP), so that relMSE is noise alone (rtpro at equal
# time: the spp Cycles' median time buys at rtpro's median speed, rendered on the most threads:
# rtpro's images do not depend on the thread count).
# Usage: benchmarks/cycles_subsurface_benchmark.sh [--runs N] [--threads "1 2"]
#   SIZE=64 SPP=64 MAX_DEPTH=64 REF_SPP=1024 BACKEND=native pick the work; RTPRO_BUILD_DIR=DIR an
#   existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-64}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-64}
ref_spp=${REF_SPP:-1024}
backend=${BACKEND:-native}
t_last=${threads##* }
color="0.8,0.5,0.3"
radius="0.5,0.25,0.125"  # [1, 0.5, 0.25] × 0.5
anisotropy=0.3
ior=1.4
methods="RANDOM_WALK RANDOM_WALK_FIXED_RADIUS"
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-subsurface.XXXXXX")

for method in $methods; do
  cat >"$out/$method.yaml" <<YAML
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
done
cycles() {  # NAME SPP THREADS SEED: $out/NAME-METHOD.exr for each method, the log $out/NAME.log
  # shellcheck disable=SC2086  # one argument per method
  run_blender render_subsurface.py "$out/$1.log" "$out/$1" "$size" "$2" "$max_depth" "$3" "$color" "$radius" \
    "$anisotropy" "$ior" "$4" $methods
  for method in $methods; do keep_rgb "$1-$method"; done
}
rtpro() {  # NAME METHOD SPP THREADS SEED: $out/NAME-METHOD.exr, its seconds in $out/NAME-METHOD.seconds
  /usr/bin/time -f "%e %U %S" -o "$out/$1-$2.seconds" "${pin[@]}" "$build/rtpro" render "$out/$2.yaml" -o "$out/$1-$2.exr" \
    --spp "$3" --backend "$backend" --threads "$4" --quiet --no-journal --set render.seed="$5"
}

echo "references: ${size}x$size, $ref_spp spp ..." >&2
cycles cycles-reference "$ref_spp" "$t_last" 1000
for method in $methods; do rtpro rtpro-reference "$method" "$ref_spp" "$t_last" 1000; done
for t in $threads; do
  pin_for "$t"  # one-thread runs of both on one CPU
  for r in $(seq "$runs"); do
    cut -d' ' -f1 /proc/loadavg >"$out/load-t$t-r$r.cycles"
    cycles "cycles-t$t-r$r" "$spp" "$t" "$r"
    cut -d' ' -f1 /proc/loadavg >"$out/load-t$t-r$r.rtpro"
    for method in $methods; do rtpro "rtpro-t$t-r$r" "$method" "$spp" "$t" "$r"; done
  done
  pin_for "$t_last"  # the equal-time runs are on the most threads
  for method in $methods; do
    # Equal time: the spp Cycles' median time buys at rtpro's median speed.
    equal_spp=$(python3 -c "
import re, statistics
out, t, runs, spp, methods, method = '$out', '$t', $runs, $spp, '$methods'.split(), '$method'
c = statistics.median(float(re.findall(r'cycles_render_seconds ([\d.]+)', open(f'{out}/cycles-t{t}-r{r}.log').read())[methods.index(method)]) for r in range(1, runs + 1))
p = statistics.median(float(open(f'{out}/rtpro-t{t}-r{r}-{method}.seconds').read().split()[-3]) for r in range(1, runs + 1))
print(max(1, round(spp * c / p)))")
    echo "$equal_spp" >"$out/equal-spp-t$t-$method"
    for r in $(seq "$runs"); do rtpro "rtpro-equal-t$t-r$r" "$method" "$equal_spp" "$t_last" "$r"; done
  done
done
for method in $methods; do
  compare_each "$out/cycles-reference-$method.exr" "$out"/cycles-t*-"$method".exr
  compare_each "$out/rtpro-reference-$method.exr" "$out"/rtpro-t*-"$method".exr "$out"/rtpro-equal-t*-"$method".exr
  "$build/rtpro" compare "$out/cycles-reference-$method.exr" "$out/rtpro-reference-$method.exr" --json \
    >"$out/references-$method.compare.json" || true
done

python3 - "$out" "$runs" "$size" "$spp" "$max_depth" "$ref_spp" "$backend" "$threads" $methods <<'PY'
import json, re, statistics, sys
out, runs, size, spp, depth, ref_spp, backend, threads = sys.argv[1:9]
methods, runs = sys.argv[9:], int(runs)
def report(name): return json.load(open(f"{out}/{name}.compare.json"))
def seconds(who, t, r, method, cpu=False):
    """Wall seconds, or with cpu the CPU seconds of every thread (rtpro: user + system)."""
    if who == "cycles":
        log = open(f"{out}/cycles-t{t}-r{r}.log").read()
        key = "cycles_render_cpu_seconds" if cpu else "cycles_render_seconds"
        return float(re.findall(key + r" ([\d.]+)", log)[methods.index(method)])
    wall, user, system = (float(v) for v in open(f"{out}/rtpro-t{t}-r{r}-{method}.seconds").read().split()[-3:])
    return user + system if cpu else wall
def fmt(v): return " ".join(f"{m:.4f}" for m in v)
def pct(a, b): return " ".join(f"{100 * (x / y - 1):+.2f}%" for x, y in zip(a, b))
print(f"subsurface sphere under a uniform sky, {size}x{size}, {spp} spp, max depth {depth}, {runs} interleaved "
      f"runs; rtpro on {backend}")
for method in methods:
    refs = report(f"references-{method}")["means"]
    print(f"{method.lower()}: references at {ref_spp} spp: Cycles {fmt(refs['reference'])}, rtpro {fmt(refs['test'])}, "
          f"rtpro/Cycles {pct(refs['test'], refs['reference'])}")
    for t in threads.split():
        means, times, cpu_times = {}, {}, {}
        for who in ("cycles", "rtpro"):
            reports = [report(f"{who}-t{t}-r{r}-{method}") for r in range(1, runs + 1)]
            means[who] = [statistics.median(rep["means"]["test"][c] for rep in reports) for c in range(3)]
            ts = [seconds(who, t, r, method) for r in range(1, runs + 1)]
            times[who] = statistics.median(ts)
            cpus = [seconds(who, t, r, method, cpu=True) for r in range(1, runs + 1)]
            cpu_times[who] = statistics.median(cpus)
            loads = [float(open(f"{out}/load-t{t}-r{r}.{who}").read()) for r in range(1, runs + 1)]
            rel = statistics.median(rep["rel_mse"] for rep in reports)
            print(f"  {t} thread(s) {who:6} mean {fmt(means[who])}  relMSE {rel:.5f}  time {times[who]:.2f} s "
                  f"(runs {min(ts):.2f}-{max(ts):.2f}, load {min(loads):.2f}-{max(loads):.2f}), "
                  f"CPU {cpu_times[who]:.2f} s ({min(cpus):.2f}-{max(cpus):.2f})")
        equal_spp = int(open(f"{out}/equal-spp-t{t}-{method}").read())
        rel_equal = statistics.median(report(f"rtpro-equal-t{t}-r{r}-{method}")["rel_mse"] for r in range(1, runs + 1))
        print(f"  {t} thread(s) rtpro at equal time ({equal_spp} spp): relMSE {rel_equal:.5f}")
        print(f"  {t} thread(s) rtpro/Cycles: mean {pct(means['rtpro'], means['cycles'])}, "
              f"time {times['rtpro'] / times['cycles']:.2f}x, CPU time {cpu_times['rtpro'] / cpu_times['cycles']:.2f}x")
print(f"images, logs and comparisons: {out}")
PY
