#!/usr/bin/env bash
# Distributed rendering and the resume journal, measured on this machine:
#   1. ranks against threads: for the demo (640x480, 16 spp) and the dragon (871k triangles), one
#      process with 2 threads against `mpirun -n 2` with 1 thread per rank, interleaved N times;
#      whole-process wall time and render time, medians with min-max, and the ratio
#      (1x2 time / 2x1 time: above 1, the two ranks were faster);
#   2. the scheduler's own cost: 2, 8 and 16 ranks of 1 thread (oversubscribed) on a scene that
#      costs almost nothing per pixel, at tile sizes 4, 8 and 16: tiles per second through rank 0
#      and bytes per tile, from --stats-json;
#   3. the journal: the demo with and without it, one process, interleaved; the median overhead.
# Usage: benchmarks/distributed_benchmark.sh [--runs N]
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
runs=5
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: $0 [--runs N]" >&2; exit 2 ;;
  esac
done
command -v mpirun >/dev/null || { echo "mpirun not found: apt-get install openmpi-bin libopenmpi-dev" >&2; exit 2; }
build_release rtpro rtpro_mpi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mpi=(mpirun --bind-to none)
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-distributed.XXXXXX")
rtpro="$build/rtpro"

timed() {  # timed NAME command...: wall seconds into $out/NAME.time
  local name=$1; shift
  /usr/bin/time -f "%e" -o "$out/$name.time" "$@" >/dev/null 2>"$out/$name.log" || { echo "failed: $*" >&2; cat "$out/$name.log" >&2; }
}

# 1. ranks against threads
for scene in demo dragon; do
  [ "$scene" = dragon ] && [ ! -f "$root/assets/dragon_vrip.ply" ] && { echo "dragon not fetched (scripts/fetch-dragon.sh): skipped" >&2; continue; }
  for r in $(seq "$runs"); do
    timed "$scene-1x2-$r" "$rtpro" render "$root/scenes/$scene.yaml" -o "$out/$scene-1x2.exr" --threads 2 -q \
      --no-journal --stats-json "$out/$scene-1x2-$r.json"
    timed "$scene-2x1-$r" "${mpi[@]}" -n 2 "$rtpro" render "$root/scenes/$scene.yaml" -o "$out/$scene-2x1.exr" \
      --threads 1 -q --no-journal --stats-json "$out/$scene-2x1-$r.json"
  done
  cmp -s "$out/$scene-1x2.exr" "$out/$scene-2x1.exr" || echo "note: $scene images differ in bytes (metadata holds the render time)" >&2
done

# 2. the scheduler's cost: a 512x512 image of one sphere at 1 spp, 1 thread per rank.
cat >"$out/cheap.yaml" <<'YAML'
rtpro: 1
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 30, resolution: [512, 512]}
render: {spp: 1, max_depth: 1}
lights: [{type: point, position: [2, 3, 4], intensity: 1}]
world: [{type: sphere, center: [0, 0, 0], radius: 1}]
YAML
for r in $(seq 3); do
  for ranks in 2 8 16; do
    for tile in 4 8 16; do
      timed "cheap-$ranks-$tile-$r" "${mpi[@]}" -n "$ranks" "$rtpro" render "$out/cheap.yaml" -o "$out/cheap.exr" \
        --threads 1 --tile-size "$tile" -q --no-journal --stats-json "$out/cheap-$ranks-$tile-$r.json"
    done
  done
done

# 3. the journal
for r in $(seq "$runs"); do
  timed "journal-on-$r" "$rtpro" render "$root/scenes/demo.yaml" -o "$out/journal.exr" -q --stats-json "$out/journal-on-$r.json"
  timed "journal-off-$r" "$rtpro" render "$root/scenes/demo.yaml" -o "$out/journal.exr" -q --no-journal --stats-json "$out/journal-off-$r.json"
done

python3 - "$out" "$runs" <<'PY'
import json, os, statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
def wall(name): return float(open(f"{out}/{name}.time").read().split()[-1])
def stats(name): return json.load(open(f"{out}/{name}.json"))
def spread(values): return f"{statistics.median(values):7.3f} ({min(values):.3f}-{max(values):.3f})"
print("1. one process x 2 threads against 2 ranks x 1 thread (seconds: median (min-max))")
print(f"{'scene':8} {'layout':7} {'whole process':>22} {'render phase':>22} {'imbalance':>9}")
for scene in ("demo", "dragon"):
    if not os.path.exists(f"{out}/{scene}-1x2-1.time"): continue
    med = {}
    for layout in ("1x2", "2x1"):
        w = [wall(f"{scene}-{layout}-{r}") for r in range(1, runs + 1)]
        s = [stats(f"{scene}-{layout}-{r}") for r in range(1, runs + 1)]
        rend = [x["seconds"]["render"] for x in s]
        imb = [x.get("load_imbalance", 1.0) for x in s]
        med[layout] = (statistics.median(w), statistics.median(rend))
        print(f"{scene:8} {layout:7} {spread(w):>22} {spread(rend):>22} {statistics.median(imb):9.3f}")
    print(f"{scene:8} ratio 1x2/2x1: whole process {med['1x2'][0] / med['2x1'][0]:.3f}, render {med['1x2'][1] / med['2x1'][1]:.3f}")
print()
print("2. scheduler: 512x512 at 1 spp, 1 thread per rank, oversubscribed (medians of 3)")
print("   remote: tiles other ranks rendered and sent to rank 0; rank 0 CPU: its talking thread's CPU time")
print("   per remote tile (hand-out and take-in, idle polling included); capacity: 1 / that")
print(f"{'ranks':>5} {'tile':>4} {'tiles':>6} {'render s':>9} {'remote':>7} {'remote/s':>9} {'bytes/tile':>10} {'rank0 us/tile':>13} {'capacity/s':>10}")
for ranks in (2, 8, 16):
    for tile in (4, 8, 16):
        s = [stats(f"cheap-{ranks}-{tile}-{r}") for r in range(1, 4)]
        tiles = (512 // tile) ** 2
        rend = statistics.median(x["seconds"]["render"] for x in s)
        remote = statistics.median(x["scheduler"]["remote_tiles"] for x in s)
        per_tile = statistics.median(x["scheduler"]["cpu_seconds"] / max(1, x["scheduler"]["remote_tiles"]) for x in s)
        sent = statistics.median(sum(k["bytes_sent"] for k in x["ranks"][1:]) / max(1, sum(k["tiles"] for k in x["ranks"][1:])) for x in s)
        print(f"{ranks:5} {tile:4} {tiles:6} {rend:9.3f} {remote:7.0f} {remote / rend:9.0f} {sent:10.0f} {per_tile * 1e6:13.1f} {1 / per_tile if per_tile > 0 else 0:10.0f}")
print()
on = [stats(f"journal-on-{r}")["seconds"]["render"] for r in range(1, runs + 1)]
off = [stats(f"journal-off-{r}")["seconds"]["render"] for r in range(1, runs + 1)]
won = [wall(f"journal-on-{r}") for r in range(1, runs + 1)]
woff = [wall(f"journal-off-{r}") for r in range(1, runs + 1)]
print("3. journal on the demo, one process (seconds: median (min-max))")
print(f"   render with journal {spread(on)}, without {spread(off)}: overhead {100 * (statistics.median(on) / statistics.median(off) - 1):+.1f}%")
print(f"   whole process with  {spread(won)}, without {spread(woff)}: overhead {100 * (statistics.median(won) / statistics.median(woff) - 1):+.1f}%")
PY
echo "outputs: $out"
