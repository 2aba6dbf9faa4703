#!/bin/sh
# Adaptive sampling against uniform sampling at equal time (issue: noise under control): for each
# scene, an adaptive render (--noise-threshold THRESHOLD --noise-metric METRIC, at most MAX_SPP
# samples a pixel), then a
# uniform one given the adaptive render's own time (--time-limit: whole passes, every pixel alike),
# both against a long reference (4·MAX_SPP spp), as relMSE (rtpro compare: mean of
# (x − ref)² / (ref² + 0.01) over pixels and channels). Runs are interleaved, ROUNDS times with
# different seeds; printed per scene: each strategy's median relMSE (the lower middle one for an
# even ROUNDS) beside every round's, the adaptive renders' seconds, and uniform ÷ adaptive.
#
#   benchmarks/adaptive_sampling_benchmark.sh RTPRO WORKDIR [MAX_SPP] [ROUNDS] [THRESHOLD] [METRIC]
#
# METRIC is relmse (default; THRESHOLD default 0.0015) or cycles (THRESHOLD default 0.02).
#
# Needs oiiotool (Debian: openimageio-tools). WORKDIR keeps the reference (render --skip-existing).
set -eu
rtpro=$(realpath "$1")
scenes=$(realpath "$(dirname "$0")/../scenes")
cornell_glass=$(realpath "$(dirname "$0")/scenes/cornell_glass.yaml")  # the box with a glass sphere
max_spp=${3:-1024}
rounds=${4:-3}
metric=${6:-relmse}
default_threshold=0.0015
[ "$metric" = cycles ] && default_threshold=0.02
threshold=${5:-$default_threshold}
mkdir -p "$2"
cd "$2"
rel_mse() {  # TEST REFERENCE
  oiiotool "$1" --ch R,G,B -o rgb_test.exr
  oiiotool "$2" --ch R,G,B -o rgb_reference.exr
  "$rtpro" compare rgb_reference.exr rgb_test.exr --json 2>/dev/null | sed -n 's/.*"rel_mse": \([^,]*\),*/\1/p'
}
seconds() { sed -n 's/.*"render": \([0-9.e+-]*\).*/\1/p' "$1" | head -1; }
median() { sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
measure() {  # NAME SCENE ARGS...
  name=$1
  shift
  "$rtpro" render "$@" --spp $((max_spp * 4)) --seed 1000 -o "${name}_reference.exr" --skip-existing --resume -q 2>/dev/null
  : > "${name}_uniform.txt"
  : > "${name}_adaptive.txt"
  round=1
  while [ "$round" -le "$rounds" ]; do
    "$rtpro" render "$@" --spp "$max_spp" --seed "$round" --noise-threshold "$threshold" --noise-metric "$metric" \
      --aov spp -o "${name}_adaptive.exr" --stats-json a.json -q
    limit=$(seconds a.json)
    "$rtpro" render "$@" --spp "$max_spp" --seed "$round" --time-limit "$limit" -o "${name}_uniform.exr" \
      --stats-json u.json -q
    echo "$(rel_mse "${name}_adaptive.exr" "${name}_reference.exr") $limit" >> "${name}_adaptive.txt"
    echo "$(rel_mse "${name}_uniform.exr" "${name}_reference.exr") $(seconds u.json)" >> "${name}_uniform.txt"
    round=$((round + 1))
  done
  u=$(cut -d' ' -f1 "${name}_uniform.txt" | median)
  a=$(cut -d' ' -f1 "${name}_adaptive.txt" | median)
  echo "$name: adaptive ($metric, threshold $threshold, at most $max_spp spp) relMSE $a in" \
       "$(cut -d' ' -f2 "${name}_adaptive.txt" | tr '\n' ' ')s (runs: $(cut -d' ' -f1 "${name}_adaptive.txt" | tr '\n' ' '))," \
       "uniform in the same time relMSE $u (runs: $(cut -d' ' -f1 "${name}_uniform.txt" | tr '\n' ' '))," \
       "ratio $(echo "$u $a" | awk '{printf "%.2f", $1 / $2}')"
}

measure cornell_glass "$cornell_glass" --size 128x128 --threads 2
measure dragon_sunset "$scenes/dragon.yaml" --integrator path --size 160x120 --threads 2 \
  --set "environment={file: $scenes/environments/sunset.exr}"
