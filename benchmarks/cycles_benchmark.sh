#!/usr/bin/env bash
# Cycles (Debian's Blender 3.4) as a measured peer of the path integrator, as POV-Ray is of the
# Whitted one: the same glTF file rendered by both at the same size, samples per pixel and path
# length (benchmarks/cycles/render_gltf.py states Cycles' settings and why), interleaved runs at
# each thread count. Reported per renderer and thread count: the median time and its spread
# (rtpro: the whole process; Cycles: its render call, scene sync, BVH and sampling, without
# Blender's start-up and glTF import), rtpro's time over Cycles', each image's mean per channel
# and its relMSE against a long Cycles render (REF_SPP samples). Run r renders with seed r + 1 in
# Cycles (the reference has 1) and r in rtpro, so that the runs' relMSE is a spread of noise, not
# one image's.
# Usage: benchmarks/cycles_benchmark.sh [--runs N] [--threads "1 2"]
#   SCENE=scenes/cornell_box.gltf SIZE=256 (or WxH) SPP=64 MAX_DEPTH=8 REF_SPP=1024 pick the work;
#   FRAME=F SHUTTER=OPEN,CLOSE render an animated file's frame F with that shutter (motion blur in
#   both: benchmarks/cycles_motion_benchmark.sh), SHUTTER_OPENING=A,B with a trapezoid shutter
#   (rtpro's camera.shutter_opening; Cycles' shutter curve drawn through the same corners);
#   ENVIRONMENT=scenes/environments/sunset.exr lights the scene by an HDRI too, in both;
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
scene=${SCENE:-scenes/cornell_box.gltf}
size=${SIZE:-256}
spp=${SPP:-64}
max_depth=${MAX_DEPTH:-8}
ref_spp=${REF_SPP:-1024}
scene_file=$scene
[[ $scene = /* ]] || scene_file=$root/$scene
pixels=$size
[[ $size = *x* ]] || pixels=${size}x$size
rtpro_motion=() cycles_motion=() rtpro_options=()
if [ -n "${FRAME:-}" ]; then
  rtpro_motion=(-D "frame=$FRAME" "--shutter=${SHUTTER:-0,0}")
  cycles_motion=("$FRAME" "$(echo "${SHUTTER:-0,0}" | cut -d, -f1)" "$(echo "${SHUTTER:-0,0}" | cut -d, -f2)")
  if [ -n "${SHUTTER_OPENING:-}" ]; then
    rtpro_motion+=(--set "camera.shutter_opening=[${SHUTTER_OPENING}]")
    cycles_motion+=("$(echo "$SHUTTER_OPENING" | cut -d, -f1)" "$(echo "$SHUTTER_OPENING" | cut -d, -f2)")
  fi
fi
# ENVIRONMENT=HDRI lights the scene by that image too, in both (an HDRI-lit glTF).
if [ -n "${ENVIRONMENT:-}" ]; then
  environment=$ENVIRONMENT
  [[ $environment = /* ]] || environment=$root/$environment
  rtpro_options+=(--environment "$environment")
  export RTPRO_CYCLES_ENVIRONMENT=$environment
fi

build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-cycles.XXXXXX")
cycles() {  # NAME SPP THREADS LOG: $out/NAME.exr
  render_with_cycles render_gltf.py "$scene_file" "$1" "$4" "$pixels" "$2" "$max_depth" "$3" "${cycles_motion[@]}"
}

echo "long Cycles reference: $pixels, $ref_spp spp ..." >&2
RTPRO_CYCLES_SEED=1 cycles reference "$ref_spp" 2 "$out/reference.log"
for t in $threads; do
  pin_for "$t"  # one-thread runs of both on one CPU
  for r in $(seq "$runs"); do
    RTPRO_CYCLES_SEED=$((r + 1)) cycles "cycles-t$t-r$r" "$spp" "$t" "$out/cycles-t$t-r$r.log"
    /usr/bin/time -f "%e" -o "$out/rtpro-t$t-r$r.seconds" "${pin[@]}" "$build/rtpro" render "$scene_file" \
      -o "$out/rtpro-t$t-r$r.exr" --size "$pixels" --spp "$spp" --max-depth "$max_depth" --threads "$t" \
      "${rtpro_motion[@]}" "${rtpro_options[@]}" --set render.seed="$r" --quiet --no-journal \
      --stats-json "$out/rtpro-t$t-r$r.json"
  done
done
compare_each "$out/reference.exr" "$out"/cycles-t*-r*.exr "$out"/rtpro-t*-r*.exr

PYTHONPATH="$root/benchmarks/cycles" python3 - "$out" "$runs" "$threads" "$scene${FRAME:+ frame $FRAME, shutter [${SHUTTER:-0,0}]}${SHUTTER_OPENING:+ opening [$SHUTTER_OPENING]}" "$pixels" "$spp" \
  "$max_depth" "$ref_spp" <<'PY'
import json, re, statistics, sys
from equal_quality import equal_quality_ratios, equal_quality_text
out, runs, threads, scene, size, spp, depth, ref_spp = sys.argv[1:9]
runs, threads = int(runs), threads.split()

def seconds(who, t, r):
    if who == "cycles":
        return float(re.search(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles-t{t}-r{r}.log").read()).group(1))
    return float(open(f"{out}/rtpro-t{t}-r{r}.seconds").read().split()[-1])

def compared(who, t, r):
    return json.load(open(f"{out}/{who}-t{t}-r{r}.compare.json"))

ref_means = compared("cycles", threads[0], 1)["means"]["reference"]
print(f"{scene}, {size}, {spp} spp, max depth {depth} (rtpro) / {int(depth) - 1} bounces (Cycles), "
      f"{runs} interleaved runs\nreference: Cycles at {ref_spp} spp, mean "
      + " ".join(f"{m:.5f}" for m in ref_means) + "\n")
header = f"{'renderer':8} {'thr':>3} {'median s':>9} {'min-max s':>13} {'rtpro/Cycles':>12} {'mean R G B':>26} {'vs ref %':>17} {'relMSE':>9}"
print(header)
print("-" * len(header))
for t in threads:
    cycles_median = statistics.median(seconds("cycles", t, r) for r in range(1, runs + 1))
    for who in ("cycles", "rtpro"):
        times = [seconds(who, t, r) for r in range(1, runs + 1)]
        reports = [compared(who, t, r) for r in range(1, runs + 1)]
        means = [statistics.median(rep["means"]["test"][c] for rep in reports) for c in range(3)]
        off = " ".join(f"{100 * (m / rm - 1):+5.2f}" for m, rm in zip(means, ref_means))
        ratio = f"{statistics.median(times) / cycles_median:11.2f}x" if who == "rtpro" else ""
        rel = statistics.median(rep["rel_mse"] for rep in reports)
        print(f"{who:8} {t:>3} {statistics.median(times):9.2f} {min(times):6.2f}-{max(times):<6.2f} {ratio:>12} "
              f"{means[0]:8.5f} {means[1]:8.5f} {means[2]:8.5f} {off:>17} {rel:9.5f}")
print("\nrtpro's time to reach Cycles' relMSE (each run's seconds x relMSE, rtpro's over Cycles'):")
for t in threads:
    rs = range(1, runs + 1)
    ratios = equal_quality_ratios([seconds("rtpro", t, r) for r in rs], [compared("rtpro", t, r)["rel_mse"] for r in rs],
                                  [seconds("cycles", t, r) for r in rs], [compared("cycles", t, r)["rel_mse"] for r in rs])
    print(f"  {t} thread(s): {equal_quality_text(ratios)}")
print(f"\nimages, logs and comparisons: {out}")
PY
