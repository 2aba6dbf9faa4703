#!/usr/bin/env bash
# Measures both backends side by side in one run and prints a table: BVH build time, primary-ray
# and whole-render Mrays/s (Google Benchmark, Release build), plus end-to-end time and peak RSS of
# `rtpro render` per scene. Usage: benchmarks/run_benchmarks.sh [scene.yaml ...]
# RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/release_tree.sh"
out="$build/benchmark-results"

build_release rtpro rtpro_backend_benchmark
mkdir -p "$out"

if [ $# -gt 0 ]; then
  scenes=("$@")
else
  scenes=("$root"/scenes/*.yaml)
fi
RTPRO_BENCH_SCENES=$(IFS=:; echo "${scenes[*]}") \
  "$build/benchmarks/rtpro_backend_benchmark" --benchmark_min_time=0.5 \
  --benchmark_out="$out/backend.json" --benchmark_out_format=json >"$out/backend.log" 2>&1

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .yaml)
  for backend in native embree; do
    # A failed render must not leave an earlier run's figures to be reported as its own.
    rm -f "$out/$name-$backend.rss" "$out/$name-$backend.json"
    /usr/bin/time -f "%M" -o "$out/$name-$backend.rss" "$build/rtpro" render "$scene" -o "$out/$name-$backend.exr" \
      --backend "$backend" --quiet --stats-json "$out/$name-$backend.json" ||
      { echo "render of $name with $backend failed" >&2; rm -f "$out/$name-$backend.rss" "$out/$name-$backend.json"; }
  done
done

python3 - "$out" "${scenes[@]}" <<'PY'
import json, os, sys
out, scenes = sys.argv[1], [os.path.basename(s)[:-5] for s in sys.argv[2:]]
bench = {b["name"].replace("/real_time", ""): b for b in json.load(open(f"{out}/backend.json"))["benchmarks"]}
def figure(kind, scene, backend, key):
    b = bench.get(f"{kind}/{scene}/{backend}")
    return None if b is None else (b["real_time"] if key == "ms" else b.get(key))
def ratio(a, b):
    return f"{a / b:5.2f}x" if a and b else "   - "
print(f"{'scene':14} {'backend':7} {'build ms':>9} {'primary Mrays/s':>16} {'render Mrays/s':>15} {'process s':>10} {'peak MiB':>9}")
for s in scenes:
    row = {}
    for backend in ("native", "embree"):
        stats_file, rss_file = f"{out}/{s}-{backend}.json", f"{out}/{s}-{backend}.rss"
        total = json.load(open(stats_file))["seconds"]["total"] if os.path.exists(stats_file) else None
        rss = int(open(rss_file).read().split()[-1]) / 1024 if os.path.exists(rss_file) else None
        row[backend] = (figure("build", s, backend, "ms"), figure("primary", s, backend, "Mrays/s"),
                        figure("render_1spp", s, backend, "Mrays/s"), total, rss)
        b, p, r, t, m = row[backend]
        fmt = lambda v, f: format(v, f) if v is not None else "-"
        print(f"{s:14} {backend:7} {fmt(b, '9.2f'):>9} {fmt(p, '16.2f'):>16} {fmt(r, '15.2f'):>15} {fmt(t, '10.2f'):>10} {fmt(m, '9.0f'):>9}")
    n, e = row["native"], row["embree"]
    print(f"{s:14} {'e/n':7} {ratio(e[0], n[0]):>9} {ratio(e[1], n[1]):>16} {ratio(e[2], n[2]):>15} {ratio(e[3], n[3]):>10} {ratio(e[4], n[4]):>9}")
PY
