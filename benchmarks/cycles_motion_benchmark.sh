#!/usr/bin/env bash
# Motion blur against Cycles (Debian's Blender 3.4): scenes/animated_shot.gltf (a box spinning,
# sliding and squashed by a morph target, scripts/make_animated_gltf.py) imported by Blender's glTF
# importer with its animation, its two materials made Lambertian in both renderers
# (KHR_materials_specular's specularFactor 0: Cycles' Diffuse BSDF, rtpro's glTF Lambert base, the
# pair benchmarks/cycles/render_gltf.py compares), rendered at frame FRAME with the shutter SHUTTER
# (rtpro's camera.shutter in frames about the frame; Cycles' motion_blur_shutter and
# motion_blur_position set to the same interval, object and deformation blur on). The default frame
# 6 keeps the camera's dolly still (its keys start at frame 12): rtpro does not blur camera motion.
# Everything else is benchmarks/cycles_benchmark.sh: interleaved runs at each thread count, median
# times (Cycles' render call, rtpro's whole process), image means per channel and relMSE against a
# long Cycles render.
# Usage: benchmarks/cycles_motion_benchmark.sh [--runs N] [--threads "1 2"]
#   FRAME=6 SHUTTER=-0.5,0.5 SIZE=240x160 SPP=64 MAX_DEPTH=8 REF_SPP=1024; RTPRO_BUILD_DIR=DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
variant=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-motion-scene.XXXXXX")/animated_shot_lambert.gltf
python3 - "$root/scenes/animated_shot.gltf" "$variant" <<'PY'
import json, sys
gltf = json.load(open(sys.argv[1]))
if "KHR_materials_specular" not in gltf.setdefault("extensionsUsed", []):
    gltf["extensionsUsed"].append("KHR_materials_specular")
for material in gltf["materials"]:
    material.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0.0}
json.dump(gltf, open(sys.argv[2], "w"))
PY
SCENE=$variant FRAME=${FRAME:-6} SHUTTER=${SHUTTER:--0.5,0.5} SIZE=${SIZE:-240x160} \
  exec "$root/benchmarks/cycles_benchmark.sh" "$@"
