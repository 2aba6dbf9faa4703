#!/usr/bin/env bash
# Start-up of the rtpro executable: wall time and peak RSS (/usr/bin/time) of `--version`,
# `info scenes/demo.yaml`, an input error (unknown output format) and a 64x48 render of the demo
# to PNG (written through libpng) and to TIFF (through OpenImageIO, which the render then loads),
# as the median and range of N runs. With other rtpro binaries given (e.g. one built from
# an older commit), every binary runs each command in turn, interleaved, so a busy machine affects
# all of them alike. Usage: benchmarks/startup_benchmark.sh [--runs N] [OTHER_RTPRO ...] (-n N too)
# (RTPRO_BUILD_DIR: use that build folder instead of build-release.)
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
runs=10
case "${1:-}" in -n | --runs) runs=$2; shift 2 ;; esac
check_runs
build_release rtpro
binaries=("$build/rtpro" "$@")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

demo="$root/scenes/demo.yaml"
commands=(
  "version|--version"
  "info|info $demo"
  "input-error|render $demo -o $out/x.unknownformat"
  "render-64x48-png|render -q $demo -o $out/demo.png --size 64x48"
  "render-64x48-tif|render -q $demo -o $out/demo.tif --size 64x48"
)
for ((run = 0; run < runs; run++)); do
  for entry in "${commands[@]}"; do
    name=${entry%%|*}
    args=${entry#*|}
    for b in "${!binaries[@]}"; do
      # shellcheck disable=SC2086  # the arguments are split on purpose
      /usr/bin/time -f "%e %M" -a -o "$out/$name.$b" "${binaries[$b]}" $args >/dev/null 2>&1 || true
    done
  done
done

python3 - "$out" "$runs" "${binaries[@]}" <<'PY'
import statistics, sys, pathlib
out, runs, binaries = pathlib.Path(sys.argv[1]), sys.argv[2], sys.argv[3:]
print(f"median [min-max] of {runs} interleaved runs; wall seconds, peak RSS MiB")
for name in ("version", "info", "input-error", "render-64x48-png", "render-64x48-tif"):
    for b, binary in enumerate(binaries):
        rows = [l.split() for l in (out / f"{name}.{b}").read_text().splitlines() if l[:1].isdigit()]
        t = [float(r[0]) for r in rows]; m = [int(r[1]) / 1024 for r in rows]
        print(f"{name:18s} {statistics.median(t):5.2f} s [{min(t):.2f}-{max(t):.2f}]  "
              f"{statistics.median(m):6.1f} MiB [{min(m):.0f}-{max(m):.0f}]  {binary}")
PY
