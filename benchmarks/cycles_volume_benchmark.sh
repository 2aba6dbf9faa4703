#!/usr/bin/env bash
# rtpro's grid medium against Cycles' (Debian's Blender 3.4) on the same OpenVDB cloud:
# scenes/smoke.yaml (scenes/volumes/smoke.vdb, a Principled Volume of the same density, albedo and
# anisotropy, one sun and a constant sky; benchmarks/cycles/render_volume.py builds Cycles' scene
# and states how its settings map). Both render at the same size, samples per pixel and path length
# on 1 and 2 threads (interleaved runs).
# Reported per thread count: each renderer's image mean per channel (median over runs), the means'
# ratio, relMSE against a longer Cycles render (REF_SPP), and time at equal spp (rtpro: the whole
# process, reading the VDB included; Cycles: its render call, scene sync and volume build included).
# Cycles ray-marches heterogeneous volumes (a step a voxel) while rtpro tracks them without bias:
# the means differ by that bias, not only by noise.
# Usage: benchmarks/cycles_volume_benchmark.sh [--runs N] [--threads "1 2"]
#   SIZE=160 SPP=64 MAX_DEPTH=64 REF_SPP=256 pick the work; RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-160}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-64}
ref_spp=${REF_SPP:-256}
vdb=$root/scenes/volumes/smoke.vdb
smoke=("$root/scenes/smoke.yaml" --size "${size}x$size" --max-depth "$max_depth")
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-cycles-volume.XXXXXX")

cycles() {  # NAME SPP LOG THREADS SEED: $out/NAME.exr
  render_with_cycles render_volume.py "$vdb" "$1" "$3" "$size" "$size" "$2" "$max_depth" "$4" "$5"
}

t_last=${threads##* }
echo "Cycles reference: ${size}x$size, $ref_spp spp ..." >&2
cycles reference "$ref_spp" "$out/reference.log" "$t_last" 1000
for t in $threads; do
  for r in $(seq "$runs"); do
    cycles "cycles-t$t-r$r" "$spp" "$out/cycles-t$t-r$r.log" "$t" "$r"
    /usr/bin/time -f "%e" -o "$out/rtpro-t$t-r$r.seconds" "$build/rtpro" render "${smoke[@]}" \
      -o "$out/rtpro-t$t-r$r.exr" --spp "$spp" --threads "$t" --quiet --no-journal --set render.seed="$r"
  done
done
compare_each "$out/reference.exr" "$out"/cycles-t*.exr "$out"/rtpro-t*.exr

python3 - "$out" "$runs" "$size" "$spp" "$max_depth" "$ref_spp" "$threads" <<'PY'
import json, re, statistics, sys
out, runs, size, spp, depth, ref_spp, threads = sys.argv[1:8]
runs = int(runs)
def report(name): return json.load(open(f"{out}/{name}.compare.json"))
def seconds(who, t, r):
    if who == "cycles":
        return float(re.search(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles-t{t}-r{r}.log").read()).group(1))
    return float(open(f"{out}/rtpro-t{t}-r{r}.seconds").read().split()[-1])
ref = report(f"cycles-t{threads.split()[0]}-r1")["means"]["reference"]
print(f"smoke.vdb, {size}x{size}, {spp} spp, max depth {depth} (Cycles {int(depth) - 1} bounces), {runs} runs\n"
      f"Cycles at {ref_spp} spp: mean " + " ".join(f"{m:.5f}" for m in ref))
for t in threads.split():
    means, times = {}, {}
    for who in ("cycles", "rtpro"):
        reports = [report(f"{who}-t{t}-r{r}") for r in range(1, runs + 1)]
        means[who] = [statistics.median(rep["means"]["test"][c] for rep in reports) for c in range(3)]
        times[who] = statistics.median(seconds(who, t, r) for r in range(1, runs + 1))
        rel = statistics.median(rep["rel_mse"] for rep in reports)
        print(f"  {t} thread(s) {who:6} mean " + " ".join(f"{m:.5f}" for m in means[who])
              + f"  relMSE {rel:.4f}  time {times[who]:.2f} s")
    print(f"  {t} thread(s) rtpro/Cycles: mean " + " ".join(f"{100 * (a / b - 1):+.2f}%" for a, b in
          zip(means["rtpro"], means["cycles"])) + f", time {times['rtpro'] / times['cycles']:.2f}x")
print(f"images, logs and comparisons: {out}")
PY
