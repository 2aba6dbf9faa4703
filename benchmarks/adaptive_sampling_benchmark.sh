#!/bin/sh
# Adaptive sampling against uniform sampling at equal time (issue: noise under control): for each
# scene, an adaptive render (--noise-threshold THRESHOLD, at most MAX_SPP samples a pixel), then a
# uniform one given the adaptive render's own time (--time-limit: whole passes, every pixel alike),
# both against a long reference (4·MAX_SPP spp), as relMSE (rtpro compare: mean of
# (x − ref)² / (ref² + 0.01) over pixels and channels). Runs are interleaved, ROUNDS times with
# different seeds; the medians are printed.
#
#   benchmarks/adaptive_sampling_benchmark.sh RTPRO WORKDIR [MAX_SPP] [ROUNDS] [THRESHOLD]
#
# Needs oiiotool (Debian: openimageio-tools). WORKDIR keeps the reference (render --skip-existing).
set -eu
rtpro=$(realpath "$1")
scenes=$(realpath "$(dirname "$0")/../scenes")
max_spp=${3:-1024}
rounds=${4:-3}
threshold=${5:-0.02}
mkdir -p "$2"
cd "$2"
# The Cornell box with its short block replaced by a glass sphere (as in denoiser_benchmark.sh).
cat > cornell_glass.yaml <<EOF2
rtpro: 1
camera: {position: [278, 273, -800], look_at: [278, 273, 0], fov: 39.3077, resolution: [128, 128]}
render: {integrator: path, spp: 16, max_depth: 8, seed: 0}
materials:
  white: {type: diffuse, color: [0.725, 0.71, 0.68]}
  red: {type: diffuse, color: [0.63, 0.065, 0.05]}
  green: {type: diffuse, color: [0.14, 0.45, 0.091]}
  light: {type: diffuse, color: [0.78, 0.78, 0.78], emission: [17, 12, 4]}
  glass: {type: dielectric, ior: 1.5}
world:
  - {type: mesh, file: $scenes/meshes/cornell_white.obj, material: white}
  - {type: mesh, file: $scenes/meshes/cornell_red.obj, material: red}
  - {type: mesh, file: $scenes/meshes/cornell_green.obj, material: green}
  - {type: mesh, file: $scenes/meshes/cornell_tall_block.obj, material: white}
  - {type: mesh, file: $scenes/meshes/cornell_light.obj, material: light}
  - {type: sphere, center: [186, 100, 169], radius: 100, material: glass}
EOF2
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
    "$rtpro" render "$@" --spp "$max_spp" --seed "$round" --noise-threshold "$threshold" \
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
  echo "$name: adaptive (threshold $threshold, at most $max_spp spp) relMSE $a in" \
       "$(cut -d' ' -f2 "${name}_adaptive.txt" | tr '\n' ' ')s (runs: $(cut -d' ' -f1 "${name}_adaptive.txt" | tr '\n' ' '))," \
       "uniform in the same time relMSE $u (runs: $(cut -d' ' -f1 "${name}_uniform.txt" | tr '\n' ' '))," \
       "ratio $(echo "$u $a" | awk '{printf "%.2f", $1 / $2}')"
}

measure cornell_glass cornell_glass.yaml --threads 2
measure dragon_sunset "$scenes/dragon.yaml" --integrator path --size 160x120 --threads 2 \
  --set "environment={file: $scenes/environments/sunset.exr}"
