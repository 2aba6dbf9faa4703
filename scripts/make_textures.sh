#!/usr/bin/env bash
# Makes the image textures the shipped scenes use (scenes/textures/), with OpenImageIO's oiiotool
# (Debian's openimageio-tools): nothing is downloaded. See third_party_notes/textures.md.
set -euo pipefail
out="$(cd "$(dirname "$0")/.." && pwd)/scenes/textures"
mkdir -p "$out"
# A UV grid: red grows along u (left to right), green along v (bottom to top), blue constant, under
# a light/dark checker of 8 x 8 squares, so orientation and seams show. 8-bit sRGB PNG.
oiiotool --pattern fill:topleft=0.1,0.9,0.6:topright=0.9,0.9,0.6:bottomleft=0.1,0.1,0.6:bottomright=0.9,0.1,0.6 256x256 3 \
  --pattern checker:width=32:height=32:color1=1,1,1:color2=0.55,0.55,0.55 256x256 3 --mul \
  -d uint8 -o "$out/uv_grid.png"
