#!/usr/bin/env bash
# rtpro's grid medium against Cycles' (Debian's Blender 3.4) on the same OpenVDB cloud:
# benchmarks/scenes/smoke_hdri.yaml (scenes/volumes/smoke.vdb, a Principled Volume of the same
# density, albedo and anisotropy, lit by one sun and the HDRI scenes/environments/sunset.exr;
# benchmarks/cycles/render_volume.py builds Cycles' scene and states how its settings map). Both
# render at the same size, samples per pixel and path length on 1 and 2 threads, the runs
# interleaved (Cycles, rtpro, Cycles, rtpro, ...) with the load average recorded beside each.
# Reported per thread count: each renderer's image mean per channel (median over runs) and its
# ratio; the time at equal spp (median and spread over runs; rtpro: the whole process, reading the
# VDB included; Cycles: its render call, scene sync and volume build included); relMSE at equal
# spp and at equal time, each renderer against its own long render (REF_SPP), so that relMSE is
# noise alone (rtpro at equal time: the spp that Cycles' median time buys at rtpro's median speed;
# its images do not depend on the thread count, so they are rendered on the most threads).
# Cycles ray-marches heterogeneous volumes (a step a voxel) while rtpro tracks them without bias:
# the means differ by that bias, not only by noise (the two references' means are printed).
# Usage: benchmarks/cycles_volume_benchmark.sh [--runs N] [--threads "1 2"]
#   SIZE=160 SPP=64 MAX_DEPTH=64 REF_SPP=512 pick the work; RTPRO_BUILD_DIR=DIR an existing Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-160}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-64}
ref_spp=${REF_SPP:-512}
vdb=$root/scenes/volumes/smoke.vdb
hdri=$root/scenes/environments/sunset.exr
smoke=("$root/benchmarks/scenes/smoke_hdri.yaml" --size "${size}x$size" --max-depth "$max_depth")
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-cycles-volume.XXXXXX")

cycles() {  # NAME SPP LOG THREADS SEED: $out/NAME.exr
  render_with_cycles render_volume.py "$vdb" "$1" "$3" "$size" "$size" "$2" "$max_depth" "$4" "$5" "$hdri"
}
rtpro() {  # NAME SPP THREADS SEED: $out/NAME.exr, its seconds in $out/NAME.seconds
  /usr/bin/time -f "%e" -o "$out/$1.seconds" "${pin[@]}" "$build/rtpro" render "${smoke[@]}" -o "$out/$1.exr" --spp "$2" \
    --threads "$3" --quiet --no-journal --set render.seed="$4"
}

t_last=${threads##* }
echo "references: ${size}x$size, $ref_spp spp ..." >&2
cycles cycles-reference "$ref_spp" "$out/cycles-reference.log" "$t_last" 1000
rtpro rtpro-reference "$ref_spp" "$t_last" 1000
for t in $threads; do
  pin_for "$t"  # one-thread runs of both on one CPU
  for r in $(seq "$runs"); do
    cut -d' ' -f1 /proc/loadavg >"$out/load-t$t-r$r.cycles"
    cycles "cycles-t$t-r$r" "$spp" "$out/cycles-t$t-r$r.log" "$t" "$r"
    cut -d' ' -f1 /proc/loadavg >"$out/load-t$t-r$r.rtpro"
    rtpro "rtpro-t$t-r$r" "$spp" "$t" "$r"
  done
  # Equal time: the spp Cycles' median time buys at rtpro's median speed.
  equal_spp=$(python3 -c "
import re, statistics, sys
out, t, runs, spp = '$out', '$t', $runs, $spp
c = statistics.median(float(re.search(r'cycles_render_seconds ([\d.]+)', open(f'{out}/cycles-t{t}-r{r}.log').read()).group(1)) for r in range(1, runs + 1))
p = statistics.median(float(open(f'{out}/rtpro-t{t}-r{r}.seconds').read().split()[-1]) for r in range(1, runs + 1))
print(max(1, round(spp * c / p)))")
  echo "$equal_spp" >"$out/equal-spp-t$t"
  pin_for "$t_last"
  for r in $(seq "$runs"); do rtpro "rtpro-equal-t$t-r$r" "$equal_spp" "$t_last" "$r"; done
done
compare_each "$out/cycles-reference.exr" "$out"/cycles-t*.exr
compare_each "$out/rtpro-reference.exr" "$out"/rtpro-t*.exr "$out"/rtpro-equal-t*.exr
"$build/rtpro" compare "$out/cycles-reference.exr" "$out/rtpro-reference.exr" --json >"$out/references.compare.json" || true

python3 - "$out" "$runs" "$size" "$spp" "$max_depth" "$ref_spp" "$threads" <<'PY'
import json, re, statistics, sys
out, runs, size, spp, depth, ref_spp, threads = sys.argv[1:8]
runs = int(runs)
def report(name): return json.load(open(f"{out}/{name}.compare.json"))
def seconds(who, t, r):
    if who == "cycles":
        return float(re.search(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles-t{t}-r{r}.log").read()).group(1))
    return float(open(f"{out}/rtpro-t{t}-r{r}.seconds").read().split()[-1])
def fmt(v): return " ".join(f"{m:.5f}" for m in v)
refs = report("references")["means"]
print(f"smoke.vdb under a sun and sunset.exr, {size}x{size}, {spp} spp, max depth {depth} "
      f"(Cycles {int(depth) - 1} bounces), {runs} interleaved runs\n"
      f"references at {ref_spp} spp: Cycles mean {fmt(refs['reference'])}, rtpro mean {fmt(refs['test'])}, "
      "rtpro/Cycles " + " ".join(f"{100 * (a / b - 1):+.2f}%" for a, b in zip(refs["test"], refs["reference"])))
for t in threads.split():
    means, times = {}, {}
    for who in ("cycles", "rtpro"):
        reports = [report(f"{who}-t{t}-r{r}") for r in range(1, runs + 1)]
        means[who] = [statistics.median(rep["means"]["test"][c] for rep in reports) for c in range(3)]
        ts = [seconds(who, t, r) for r in range(1, runs + 1)]
        times[who] = statistics.median(ts)
        loads = [float(open(f"{out}/load-t{t}-r{r}.{who}").read()) for r in range(1, runs + 1)]
        rel = statistics.median(rep["rel_mse"] for rep in reports)
        print(f"  {t} thread(s) {who:6} mean {fmt(means[who])}  relMSE {rel:.5f}  time {times[who]:.2f} s "
              f"(runs {min(ts):.2f}-{max(ts):.2f}, load {min(loads):.2f}-{max(loads):.2f})")
    equal_spp = int(open(f"{out}/equal-spp-t{t}").read())
    rel_equal = statistics.median(report(f"rtpro-equal-t{t}-r{r}")["rel_mse"] for r in range(1, runs + 1))
    print(f"  {t} thread(s) rtpro at equal time ({equal_spp} spp): relMSE {rel_equal:.5f}")
    print(f"  {t} thread(s) rtpro/Cycles: mean " + " ".join(f"{100 * (a / b - 1):+.2f}%" for a, b in
          zip(means["rtpro"], means["cycles"])) + f", time {times['rtpro'] / times['cycles']:.2f}x")
print(f"images, logs and comparisons: {out}")
PY
