#!/usr/bin/env bash
# Renders every shipped scene (the dragons aside) small, on both backends and under both
# integrators, into a folder of EXRs: the before/after evidence that a refactor changed no pixel.
#   scripts/render-fingerprints.sh RTPRO_BINARY OUT_DIR [RENDER_OPTION...]  # e.g. --tile-size 7
#   scripts/render-fingerprints.sh --compare DIR_A DIR_B   # every image pair identical, bit for bit
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = "--compare" ]; then
  a=$2 b=$3 failed=0 count=0
  for image in "$a"/*.exr; do
    name=$(basename "$image")
    count=$((count + 1))
    if ! idiff -q -fail 0 -failpercent 0 -warn 0 "$image" "$b/$name" >/dev/null 2>&1; then
      echo "differs: $name"
      failed=$((failed + 1))
    fi
  done
  echo "$((count - failed)) identical, $failed differ"
  [ "$failed" -eq 0 ]
  exit
fi

binary=$1 out=$2
shift 2  # what is left goes to every render, after the script's own options
mkdir -p "$out"
scenes=(scenes/*.yaml scenes/*.gltf benchmarks/embree/cornell_box.yaml benchmarks/scenes/*.yaml)
for scene in "${scenes[@]}"; do
  case "$scene" in *dragon*) continue ;; esac
  # Embree's Cornell box reads its mesh from Debian's embree-tools, when installed.
  [ "$scene" = benchmarks/embree/cornell_box.yaml ] && [ ! -f /usr/share/doc/embree3/models/cornell_box.obj ] && continue
  stem=$(basename "${scene%.*}")
  [ "$scene" = benchmarks/embree/cornell_box.yaml ] && stem=embree_cornell_box
  for backend in native embree; do
    for integrator in whitted path; do
      "$binary" render "$scene" -o "$out/$stem.$backend.$integrator.exr" --size 160x120 --spp 4 \
        --backend "$backend" --integrator "$integrator" --threads 2 -q --no-journal "$@"
    done
  done
done
echo "rendered $(ls "$out"/*.exr | wc -l) images into $out"
