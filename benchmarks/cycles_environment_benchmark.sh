#!/usr/bin/env bash
# rtpro's environment light against Cycles' (Debian's Blender 3.4) on the same scene: a clay and a
# white rough metal sphere on a ground sphere lit only by scenes/environments/sunset.exr (its sun
# turned as in scenes/lookdev.yaml: benchmarks/scenes/sunset_spheres.yaml), rendered by both at the
# same size, samples per pixel and path length; benchmarks/cycles/render_environment.py builds
# Cycles' scene and states its settings.
# Reported: the means per channel of a long render by each (REF_SPP samples: issue 29's goal is
# rtpro's within 1% of Cycles'), and at SPP samples (interleaved runs) each renderer's median mean,
# relMSE against the long Cycles render and time (rtpro: the whole process; Cycles: its render call).
# Usage: benchmarks/cycles_environment_benchmark.sh [--runs N] [--threads "2"]
#   SIZE=160 SPP=64 MAX_DEPTH=6 REF_SPP=1024 pick the work; RTPRO_BUILD_DIR=DIR an existing
#   Release tree.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
size=${SIZE:-160}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-6}
ref_spp=${REF_SPP:-1024}
t=${threads##* }
height=$((size * 5 / 8))
hdri=$root/scenes/environments/sunset.exr
spheres=("$root/benchmarks/scenes/sunset_spheres.yaml" --size "${size}x$height" --max-depth "$max_depth")
build_release rtpro
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-cycles-env.XXXXXX")

cycles() {  # NAME SPP LOG: $out/NAME.exr
  render_with_cycles render_environment.py "$hdri" "$1" "$3" "$size" "$height" "$2" "$max_depth" "$t"
}

echo "long Cycles reference: ${size}x$height, $ref_spp spp ..." >&2
RTPRO_CYCLES_SEED=1 cycles reference "$ref_spp" "$out/reference.log"
echo "long rtpro render: $ref_spp spp ..." >&2
"$build/rtpro" render "${spheres[@]}" -o "$out/rtpro-reference.exr" --spp "$ref_spp" --threads "$t" --quiet --no-journal
for r in $(seq "$runs"); do
  RTPRO_CYCLES_SEED=$((r + 1)) cycles "cycles-r$r" "$spp" "$out/cycles-r$r.log"  # a seed a run: the reference has 1
  /usr/bin/time -f "%e" -o "$out/rtpro-r$r.seconds" "$build/rtpro" render "${spheres[@]}" -o "$out/rtpro-r$r.exr" \
    --spp "$spp" --threads "$t" --quiet --no-journal --set render.seed="$r"
done
compare_each "$out/reference.exr" "$out"/cycles-r*.exr "$out"/rtpro-r*.exr "$out"/rtpro-reference.exr

PYTHONPATH="$root/benchmarks/cycles" python3 - "$out" "$runs" "$size" "$height" "$spp" "$max_depth" "$ref_spp" "$t" <<'PY'
import json, re, statistics, sys
from equal_quality import equal_quality_ratios, equal_quality_text
out, runs, width, height, spp, depth, ref_spp, t = sys.argv[1:9]
runs = int(runs)
def report(name): return json.load(open(f"{out}/{name}.compare.json"))
def seconds(who, r):
    if who == "cycles":
        return float(re.search(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles-r{r}.log").read()).group(1))
    return float(open(f"{out}/rtpro-r{r}.seconds").read().split()[-1])
ref = report("cycles-r1")["means"]["reference"]
print(f"sunset.exr spheres, {width}x{height}, {spp} spp, max depth {depth} (Cycles {int(depth) - 1} bounces), "
      f"{t} thread(s), {runs} interleaved runs\nCycles at {ref_spp} spp: mean " + " ".join(f"{m:.5f}" for m in ref))
means = {}
for who in ("cycles", "rtpro"):
    reports = [report(f"{who}-r{r}") for r in range(1, runs + 1)]
    means[who] = [statistics.median(rep["means"]["test"][c] for rep in reports) for c in range(3)]
    times = [seconds(who, r) for r in range(1, runs + 1)]
    rel = statistics.median(rep["rel_mse"] for rep in reports)
    print(f"  {who:6} mean " + " ".join(f"{m:.5f}" for m in means[who]) + "  vs the long render "
          + " ".join(f"{100 * (m / r - 1):+.2f}%" for m, r in zip(means[who], ref))
          + f"  relMSE {rel:.4f}  time median {statistics.median(times):.2f} s ({min(times):.2f}-{max(times):.2f})")
long_rtpro = report("rtpro-reference")
print(f"rtpro at {ref_spp} spp: mean " + " ".join(f"{m:.5f}" for m in long_rtpro["means"]["test"])
      + "  against Cycles at " + ref_spp + " spp " + " ".join(f"{100 * (a / b - 1):+.2f}%" for a, b in zip(long_rtpro["means"]["test"], ref))
      + f"  relMSE {long_rtpro['rel_mse']:.5f}")
print(f"at {spp} spp, rtpro's median mean against Cycles': "
      + " ".join(f"{100 * (a / b - 1):+.2f}%" for a, b in zip(means["rtpro"], means["cycles"])))
rs = range(1, runs + 1)
ratios = equal_quality_ratios([seconds("rtpro", r) for r in rs], [report(f"rtpro-r{r}")["rel_mse"] for r in rs],
                              [seconds("cycles", r) for r in rs], [report(f"cycles-r{r}")["rel_mse"] for r in rs])
print("rtpro's time to reach Cycles' relMSE (each run's seconds x relMSE, rtpro's over Cycles'): "
      + equal_quality_text(ratios))
print(f"images, logs and comparisons: {out}")
PY
