#!/bin/sh
# Measures `rtpro denoise` (a benchmark of quality and time): for each scene, relMSE against a long
# reference of the noisy 16-spp image, the denoised one and the noisy 128-spp one, the columns of
# docs/usage.md's "Denoising" table that need no other render.
#
#   benchmarks/denoiser_benchmark.sh RTPRO WORKDIR
#
# RTPRO is the rtpro binary, WORKDIR a folder for the renders (kept: a second run reuses them,
# render --skip-existing). Needs oiiotool (Debian: openimageio-tools) and the dragon
# (scripts/fetch-dragon.sh). CPU time: about 25 minutes on one core, almost all of it the
# references (4096 spp; 2048 for the textures).
#
# The 16-spp input is two 8-spp renders with different seeds, averaged, with the two renders as
# its half-buffers (half_a, half_b): what a film that keeps even and odd samples apart writes.
# relMSE is rtpro compare's: the mean over pixels and channels of (x - ref)² / (ref² + 0.01).
set -eu

rtpro=$(realpath "$1")
scenes=$(realpath "$(dirname "$0")/../scenes")
cornell_glass=$(realpath "$(dirname "$0")/scenes/cornell_glass.yaml")  # the box with a glass sphere
mkdir -p "$2"
cd "$2"


render() {  # OUTPUT SPP SEED SCENE ARGS... (sh has no local variables: positional ones only)
  set -- "$@" --spp "$2" --seed "$3" --aov albedo,normal,depth -o "$1.exr" --skip-existing -q
  shift 3
  "$rtpro" render "$@"
}

rel_mse() {  # TEST REFERENCE: relMSE of TEST's R,G,B
  oiiotool "$1" --ch R,G,B -o rgb_test.exr
  oiiotool "$2" --ch R,G,B -o rgb_reference.exr
  "$rtpro" compare rgb_reference.exr rgb_test.exr --json 2>/dev/null | sed -n 's/.*"rel_mse": \([^,]*\),*/\1/p'
}

measure() {  # NAME REFERENCE_SPP SCENE ARGS...
  name=$1 reference_spp=$2
  shift 2
  render "${name}_8a" 8 1 "$@"
  render "${name}_8b" 8 2 "$@"
  render "${name}_128" 128 7 "$@"
  render "${name}_reference" "$reference_spp" 100 "$@"
  oiiotool "${name}_8a.exr" "${name}_8b.exr" --add --mulc 0.5 -o "${name}_mean.exr"
  oiiotool "${name}_8a.exr" --ch R,G,B --chnames half_a.R,half_a.G,half_a.B -o "${name}_half_a.exr"
  oiiotool "${name}_8b.exr" --ch R,G,B --chnames half_b.R,half_b.G,half_b.B -o "${name}_half_b.exr"
  oiiotool "${name}_mean.exr" "${name}_half_a.exr" --chappend "${name}_half_b.exr" --chappend -o "${name}_16.exr"
  "$rtpro" denoise "${name}_16.exr" -o "${name}_16_denoised.exr" --threads 2
  echo "$name: noisy 16 spp $(rel_mse "${name}_16.exr" "${name}_reference.exr")," \
       "denoised 16 spp $(rel_mse "${name}_16_denoised.exr" "${name}_reference.exr")," \
       "noisy 128 spp $(rel_mse "${name}_128.exr" "${name}_reference.exr")"
}

measure cornell_glass 4096 "$cornell_glass"
measure dragon 4096 "$scenes/dragon.yaml" --integrator path --size 320x240
measure textures 2048 "$scenes/textures.yaml" --integrator path --size 256x192
