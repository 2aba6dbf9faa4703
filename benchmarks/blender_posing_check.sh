#!/usr/bin/env bash
# glTF posing against Blender's glTF importer (Debian's Blender 3.4): each animated sample is posed
# by rtpro (benchmarks/gltf_pose_dump.cpp: the pose `rtpro render F.gltf -D frame=N` renders, at
# render.fps 24) and by Blender's importer (benchmarks/cycles/pose_check.py: the evaluated mesh at
# the same frame, scene at 24 fps), at three or four frames each, and the posed vertices compared as point
# sets: the symmetric Hausdorff distance, the bounding boxes' corners and the centroids, each
# relative to the diagonal of rtpro's posed bounding box. No rendering. Prints a table; a pose
# above TOLERANCE (default 1e-4 of the diagonal) is flagged and the script exits 1, unless Blender
# is expected to differ there: its importer keys a LINEAR rotation as one linear F-curve per
# quaternion component (normalised lerp) where glTF slerps. nlerp_deg is the largest angle between
# the two at that frame (0 at the keys), slerped/diag the Hausdorff distance once Blender's rotation
# keys are slerped at that frame: a row off only by the interpolation is marked "nlerp", not failed.
# The models: Khronos' animated samples shipped with assimp's test models (simple_skin: a skin of
# two joints keyed by rotation; AnimatedMorphCube: two morph targets keyed by weights) and
# scenes/animated_shot.gltf (node translation, LINEAR rotation, CUBICSPLINE morph weights, STEP
# and LINEAR camera dolly), and a rig benchmarks/make_posing_rig.py writes (8 joints under a moved,
# turned and scaled skeleton root, every vertex weighted to all 8 through JOINTS_1/WEIGHTS_1,
# rotations LINEAR and STEP, a non-uniform scale, translations, a morph target under the skin, and
# a translated skinned-mesh node that the specification says to ignore). The importer ignores
# CUBICSPLINE tangents (Bezier F-curves with automatic handles): such channels agree only at keys
# or where the tangents are flat, as in animated_shot's morph weights.
# Usage: benchmarks/blender_posing_check.sh   (RTPRO_BUILD_DIR=DIR, TOLERANCE=1e-4)
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-posing.XXXXXX")
source "$root/benchmarks/cycles/blender.sh"
dump="$build/benchmarks/rtpro_gltf_pose_dump"
build_release rtpro_gltf_pose_dump
models=/usr/share/assimp/models/glTF2
tolerance=${TOLERANCE:-1e-4}
# name file frames (the first frame, one between keys, one near the end)
cases="simple_skin $models/simple_skin/simple_skin.gltf 0 37 90
AnimatedMorphCube $models/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf 0 17 40
animated_shot $root/scenes/animated_shot.gltf 3 13 21
posing_rig $out/posing_rig.gltf 0 12 15 24"
python3 "$root/benchmarks/make_posing_rig.py" "$out/posing_rig.gltf"
status=0
printf '%-18s %6s %8s %9s %12s %10s %12s %9s %14s\n' model frame rtpro_v blender_v hausdorff/diag bbox/diag centroid/diag nlerp_deg slerped/diag
while read -r name file frames; do
  [ -f "$file" ] || { echo "$name: $file missing, skipped" >&2; continue; }
  mkdir -p "$out/$name"
  for frame in $frames; do "$dump" "$file" "$frame" >"$out/$name/$frame.txt"; done
  # shellcheck disable=SC2086
  run_blender pose_check.py "$out/$name.log" "$file" "$out/$name" $frames
  while read -r _ frame ours theirs hausdorff box centroid nlerp slerped; do
    flag=$(python3 -c "print('' if max($hausdorff, $box, $centroid) <= $tolerance else '  nlerp' if $slerped <= $tolerance else '  DISAGREES')")
    [ "$flag" != "  DISAGREES" ] || status=1
    printf '%-18s %6s %8s %9s %12s %10s %12s %9s %14s%s\n' "$name" "$frame" "$ours" "$theirs" "$hausdorff" "$box" "$centroid" "$nlerp" "$slerped" "$flag"
  done < <(grep '^pose ' "$out/$name.log")
done <<<"$cases"
echo "logs and dumps in $out"
exit $status
