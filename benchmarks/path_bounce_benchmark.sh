#!/usr/bin/env bash
# Packets against single rays for each bounce of the path integrator (issue: incoherent secondary
# rays dominate path tracing). rtpro_path_bounce_benchmark records one 1-spp frame's batches per
# generation and traces each again one ray at a time ("single"), as the integrator asks past the
# camera ("scattered": packets of eight on both backends) and as camera rays go ("coherent":
# Embree's stream API, native packets). One thread; Google Benchmark repeats every case REPS
# times in random interleaving and the table gives the medians in Mrays/s and scattered / single.
# Usage: benchmarks/path_bounce_benchmark.sh [scene ...]   (REPS=5, SIZE=512x512; default scenes:
#   benchmarks/embree/cornell_box.yaml and scenes/cornell_box.gltf)
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
build_release rtpro_path_bounce_benchmark
out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-bounces.XXXXXX")
scenes=$(IFS=:; echo "$*")
RTPRO_BENCH_SCENES=$scenes RTPRO_BENCH_SIZE=${SIZE:-512x512} "$build/benchmarks/rtpro_path_bounce_benchmark" \
  --benchmark_repetitions="${REPS:-5}" --benchmark_enable_random_interleaving=true --benchmark_min_time=0.2 \
  --benchmark_report_aggregates_only=false --benchmark_out="$out/bounces.json" --benchmark_out_format=json >"$out/bounces.log" 2>&1

python3 - "$out/bounces.json" <<'PY'
import collections, json, statistics, sys
runs = collections.defaultdict(list)
count = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") != "iteration": continue
    scene, backend, batch, mode = b["run_name"].replace("/real_time", "").split("/")
    runs[(scene, backend, batch, mode)].append(b["Mrays/s"] / 1e6 if b["Mrays/s"] > 1e3 else b["Mrays/s"])
    count[(scene, backend, batch)] = int(b["rays"])
print(f"{'scene':22} {'backend':7} {'batch':8} {'rays':>8} {'single':>7} {'scattered':>9} {'coherent':>8} {'scat/single':>11} {'spread':>13}")
for (scene, backend, batch) in sorted(count, key=lambda k: (k[0], k[1], int(k[2].lstrip("bounceshadow")), k[2])):
    med = {m: statistics.median(runs[(scene, backend, batch, m)]) for m in ("single", "scattered", "coherent")}
    ratios = [s / t for s, t in zip(runs[(scene, backend, batch, "scattered")], runs[(scene, backend, batch, "single")])]
    print(f"{scene:22} {backend:7} {batch:8} {count[(scene, backend, batch)]:8d} {med['single']:7.2f} {med['scattered']:9.2f} "
          f"{med['coherent']:8.2f} {med['scattered'] / med['single']:10.2f}x {min(ratios):5.2f}-{max(ratios):5.2f}x")
PY
echo "log and JSON: $out"
