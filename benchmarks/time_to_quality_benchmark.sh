#!/usr/bin/env bash
# Time to a clean image against Cycles (issue: noise under control): how long rtpro takes to reach
# the relMSE that Cycles (Debian's Blender 3.4, which cannot denoise) reaches at CYCLES_SPP samples,
# on the same glTF file, size and path length. Both are measured against one long Cycles render
# (REF_SPP samples). Cycles renders CYCLES_SPP samples RUNS times (its render call timed, without
# Blender's start-up and glTF import); rtpro renders with --denoise and adaptive sampling
# (relmse metric) under time limits of FRACTIONS of Cycles' median time, each timed as a whole
# process (load, BVH, render, denoise, write). Reported: Cycles' time and relMSE, and for each
# rtpro run its time, the ratio to Cycles' time and its relMSE; the first run at or below
# Cycles' relMSE answers the question. Cycles' runs come first, not interleaved with rtpro's: rtpro's
# time limits are fractions of their median.
# Usage: benchmarks/time_to_quality_benchmark.sh [--runs N] [--threads "2"]   (both on the last count given)
#   SCENE=scenes/cornell_box.gltf SIZE=256 CYCLES_SPP=1024 REF_SPP=4096 MAX_DEPTH=8
#   FRACTIONS="0.05 0.1 0.15 0.2 0.25" THRESHOLD=0.0015 WORKDIR=DIR (keeps the reference)
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$root/benchmarks/cycles/blender.sh"
scene=${SCENE:-scenes/cornell_box.gltf}
size=${SIZE:-256}
cycles_spp=${CYCLES_SPP:-1024}
ref_spp=${REF_SPP:-4096}
max_depth=${MAX_DEPTH:-8}
fractions=${FRACTIONS:-0.05 0.1 0.15 0.2 0.25}
threshold=${THRESHOLD:-0.0015}
out=${WORKDIR:-$(mktemp -d "${TMPDIR:-/tmp}/rtpro-ttq.XXXXXX")}
mkdir -p "$out"
build_release rtpro
t=${threads##* }

cycles() {  # NAME SPP: $out/NAME.exr, on $t threads
  render_with_cycles render_gltf.py "$root/$scene" "$1" "$out/$1.log" "$size" "$2" "$max_depth" "$t"
}
rel_mse() {  # IMAGE: relMSE of its R,G,B against the reference
  oiiotool "$1" --ch R,G,B -o "$out/rgb.exr"
  { "$build/rtpro" compare "$out/reference.exr" "$out/rgb.exr" --json 2>/dev/null || true; } |  # exit 1: not identical
    python3 -c 'import json, sys; print(json.load(sys.stdin)["rel_mse"])'
}

[ -f "$out/reference.exr" ] || { echo "long Cycles reference: ${size}x$size, $ref_spp spp ..." >&2; RTPRO_CYCLES_SEED=1 cycles reference "$ref_spp"; }
cycles_times=()
cycles_errors=()
for r in $(seq "$runs"); do
  # A seed a run (the reference has 1), so that the runs' relMSE is a spread of noise, not one image.
  RTPRO_CYCLES_SEED=$((r + 1)) cycles "cycles-$r" "$cycles_spp"
  cycles_times+=("$(sed -n 's/.*cycles_render_seconds \([0-9.]*\).*/\1/p' "$out/cycles-$r.log")")
  cycles_errors+=("$(rel_mse "$out/cycles-$r.exr")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
tc=$(median "${cycles_times[@]}")
ec=$(median "${cycles_errors[@]}")
echo "$scene, ${size}x$size, max depth $max_depth, $t threads; reference: Cycles at $ref_spp spp"
echo "Cycles $cycles_spp spp: ${tc} s (runs: ${cycles_times[*]}), relMSE $ec (runs: ${cycles_errors[*]})"
for f in $fractions; do
  limit=$(python3 -c "print($f * $tc)")
  start=$(date +%s.%N)
  "$build/rtpro" render "$root/$scene" -o "$out/rtpro-$f.exr" --size "${size}x$size" --max-depth "$max_depth" \
    --threads "$t" --spp 65536 --time-limit "$limit" --noise-threshold "$threshold" --noise-metric relmse --denoise \
    --quiet --no-journal --stats-json "$out/rtpro-$f.json"
  seconds=$(python3 -c "print(round($(date +%s.%N) - $start, 2))")
  error=$(rel_mse "$out/rtpro-$f.exr")
  passes=$(python3 -c "import json; print(json.load(open('$out/rtpro-$f.json'))['passes']['done'])")
  echo "rtpro --time-limit $limit (${f} of Cycles'): ${seconds} s whole process ($(python3 -c "print(round($seconds / $tc, 3))")x Cycles), $passes passes, relMSE $error ($(python3 -c "print('at or below' if $error <= $ec else 'above')") Cycles')"
done
echo "images and logs: $out"
