#!/usr/bin/env bash
# Scale: a displaced grid of 1, 10 and 100 million unique triangles (binary PLY written by
# rtpro_generate_grid_ply), each rendered at 1024x1024, 1 spp, with both backends, as a user runs
# it: `rtpro render` of a scene file naming the PLY, under /usr/bin/time. Reports per size and
# backend: load, build and render seconds, the time to the first pixel (the process's start to the
# render's start: load + build), peak RSS (and at the end of load and of build), bytes per
# triangle (rtpro's mesh arrays + the acceleration structure, and peak RSS over the triangles),
# and rtpro's up-front memory estimate beside the measured peak; then how each figure grows from
# one size to the next (linear: x10 triangles, x10 figure). A third run per size, embree-pieces,
# builds the grid with --embree-pieces (Embree's build records one piece's at a time).
# Usage: benchmarks/scale_benchmark.sh [--sizes "1 10 100"] [--threads N] [--max-memory MiB]
#                                      [--pieces TRIANGLES]
#   --sizes: millions of triangles (default "1 10 100"); the PLYs are kept in the results folder
#     (about 19 bytes a triangle: 1.9 GB for 100 M) and reused.
#   --max-memory: passed to rtpro (default: what rtpro allows by itself, the smaller of 4 GiB and
#     the available memory; 100 M triangles need about 14 GB, so pass e.g. --max-memory 20000).
#   --pieces: the piece size of the embree-pieces runs (default 1048576).
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
sizes="1 10 100"
threads=$(nproc)
max_memory=""
pieces=1048576
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-memory) max_memory=$2; shift 2 ;;
    --pieces) pieces=$2; shift 2 ;;
    -h | --help) sed -n '2,/^set /{/^set /d; s/^# \{0,1\}//; p}' "$0"; exit 0 ;;
    *) echo "usage: $0 [--sizes \"1 10 100\"] [--threads N] [--max-memory MiB] [--pieces TRIANGLES]" >&2; exit 2 ;;
  esac
done
out="$build/benchmark-results/scale"
build_release rtpro rtpro_generate_grid_ply
mkdir -p "$out"

memory_flag=()
[ -n "$max_memory" ] && memory_flag=(--max-memory "$max_memory")
for size in $sizes; do
  ply="$out/grid-${size}M.ply"
  [ -s "$ply" ] || "$build/benchmarks/rtpro_generate_grid_ply" "${size}M" "$ply"
  cat >"$out/grid-${size}M.yaml" <<EOF
rtpro: 1
camera: {position: [0.5, 0.55, -0.35], look_at: [0.5, 0.0, 0.45], fov: 50, resolution: [1024, 1024]}
render: {spp: 1, max_depth: 1, ambient: 0.1}
materials:
  clay: {color: [0.7, 0.6, 0.5]}
lights:
  - {type: directional, direction: [0.3, -1.0, 0.4], intensity: 1.0}
world:
  - {type: mesh, file: grid-${size}M.ply, material: clay}
EOF
  for config in embree native embree-pieces; do
    run="$out/grid-${size}M-$config"
    case $config in
      embree-pieces) settings=(--backend embree --embree-pieces "$pieces") ;;
      *) settings=(--backend "$config") ;;
    esac
    /usr/bin/time -f "%e %M" -o "$run.time" "$build/rtpro" render "$out/grid-${size}M.yaml" -o "$run.png" \
      "${settings[@]}" --threads "$threads" --stats-json "$run.json" "${memory_flag[@]}" -v 2>"$run.log" ||
      { echo "grid ${size}M, $config: failed (see $run.log)"; tail -3 "$run.log"; }
  done
done

python3 - "$out" "$sizes" <<'EOF'
import json, os, re, sys
out, sizes = sys.argv[1], sys.argv[2].split()
MiB = 1024 * 1024

def run(size, backend):
    base = f"{out}/grid-{size}M-{backend}"
    if not os.path.exists(base + ".json"):
        return None
    s = json.load(open(base + ".json"))
    wall, rss_kib = open(base + ".time").read().split()[-2:]
    log = open(base + ".log").read()
    estimate = re.search(r"estimated memory: ([0-9.]+) (MiB|GiB|KiB)", log)
    scale = {"KiB": 1 / 1024, "MiB": 1, "GiB": 1024}
    m = s["memory_bytes"]
    return {"load": s["seconds"]["load"], "build": s["seconds"]["build"], "render": s["seconds"]["render"],
            "first_pixel": s["seconds"]["load"] + s["seconds"]["build"], "wall": float(wall),
            "rss": int(rss_kib) * 1024 / MiB, "rss_load": m["peak_rss_after_load"] / MiB,
            "rss_build": m["peak_rss_after_build"] / MiB, "tri": s["triangles"],
            "b_tri": s["bytes_per_triangle"], "rss_tri": int(rss_kib) * 1024 / s["triangles"],
            "estimate": float(estimate.group(1)) * scale[estimate.group(2)] if estimate else float("nan")}

print("scale: a displaced grid, 1024x1024, 1 spp (seconds are not comparable across loaded machines)")
print(f"{'tris':>5} {'backend':13} {'load s':>7} {'build s':>8} {'render s':>9} {'1st px s':>9} "
      f"{'peak MiB':>9} {'@load':>7} {'@build':>7} {'B/tri':>6} {'RSS/tri':>8} {'estimate MiB':>13}")
results = {}
for size in sizes:
    for backend in ("embree", "native", "embree-pieces"):
        r = run(size, backend)
        results[(size, backend)] = r
        if r is None:
            print(f"{size + 'M':>5} {backend:13} failed")
            continue
        print(f"{size + 'M':>5} {backend:13} {r['load']:7.2f} {r['build']:8.2f} {r['render']:9.2f} {r['first_pixel']:9.2f} "
              f"{r['rss']:9.1f} {r['rss_load']:7.1f} {r['rss_build']:7.1f} {r['b_tri']:6.1f} {r['rss_tri']:8.1f} "
              f"{r['estimate']:13.1f}")
print("growth from one size to the next (figure ratio over triangle ratio; 1.00 is linear)")
for backend in ("embree", "native", "embree-pieces"):
    for a, b in zip(sizes, sizes[1:]):
        ra, rb = results[(a, backend)], results[(b, backend)]
        if not ra or not rb:
            continue
        k = rb["tri"] / ra["tri"]
        growth = {f: (rb[f] / ra[f]) / k for f in ("load", "build", "first_pixel", "rss")}
        growth["B/tri"] = rb["b_tri"] / ra["b_tri"]  # per triangle already: 1.00 when linear
        print(f"  {backend:13} {a}M -> {b}M: " + "  ".join(f"{f} {g:.2f}" for f, g in growth.items()))
EOF
