#!/usr/bin/env bash
# Embree's furBall_A (Debian embree-tools: 455,505 round linear segments) rendered by Embree's own
# `pathtracer` and by rtpro on both backends, side by side in one run: the same view (its
# furBall_A.ecs: camera, 50° fov, a directional light of 3 and an ambient light of 1), size, path
# length and samples. rtpro reads the fur through benchmarks/embree_fur_to_hair.py (a .hair file)
# and benchmarks/fur_ball.yaml. Embree's "Hair" material makes the Debian pathtracer abort past a
# path length of 1 (a NaN ray meets an assertion), so its copy of the XML gives the fibres Embree's
# "Matte" material of the same colour, as fur_ball.yaml does rtpro's.
# Reported: Mrays/s (Embree's BENCHMARK_RENDER_MRAYPS_AVG over FRAMES timed frames of 1 spp after 1
# warm-up; rtpro's rays over its render phase at FRAMES spp), medians of RUNS interleaved runs per
# thread count; the BVH build (Embree's builder as its verbose log times it, rtpro's build phase per
# backend) and the acceleration structure's bytes per curve segment.
# Usage: benchmarks/fur_ball_benchmark.sh [--runs N] [--threads "1 2"]   (SIZE=256 FRAMES=8 DEPTH=8)
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$(dirname "$0")/embree_fur_matte.sh"
command -v pathtracer >/dev/null || { echo "pathtracer not found: apt-get install embree-tools" >&2; exit 2; }
models=/usr/share/doc/embree3/models
size=${SIZE:-256}
frames=${FRAMES:-8}
depth=${DEPTH:-8}
build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-fur.XXXXXX")
embree_fur_matte "$out"

for t in $threads; do
  for r in $(seq "$runs"); do
    verbose=()
    [ "$r" != 1 ] || verbose=(--rtcore verbose=2)  # the builder's time and bytes, once per thread count
    (cd "$out" && pathtracer -c furBall_matte.ecs --size "$size" "$size" --spp 1 --max-path-length "$depth" \
      --threads "$t" "${verbose[@]}" --benchmark 1 "$frames" >"$out/embree-t$t-r$r.log" 2>&1)
    for backend in embree native; do
      "$build/rtpro" render "$root/benchmarks/fur_ball.yaml" -o "$out/rtpro-$backend.exr" --size "${size}x$size" \
        --spp "$frames" --max-depth "$depth" --threads "$t" --backend "$backend" --quiet --no-journal \
        --stats-json "$out/rtpro-$backend-t$t-r$r.json"
    done
  done
done

python3 - "$out" "$runs" "$threads" "$frames" "$size" "$depth" <<'PY'
import json, re, statistics, sys
out, runs, threads, frames, size, depth = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), *map(int, sys.argv[4:])
segments = 455505
def embree(t, r):
    log = open(f"{out}/embree-t{t}-r{r}.log").read()
    return float(re.search(r"BENCHMARK_RENDER_MRAYPS_AVG ([\d.]+)", log).group(1))
def embree_build(t):
    log = open(f"{out}/embree-t{t}-r1.log").read()
    ms = float(re.search(r"finished BVH\S* : ([\d.]+)ms", log).group(1))
    total = re.search(r"^\s*total\s*:.*#bytes/prim =\s*([\d.]+)", log, re.M)
    return ms / 1e3, float(total.group(1)) if total else float("nan")
def rtpro(backend, t, r):
    s = json.load(open(f"{out}/rtpro-{backend}-t{t}-r{r}.json"))
    return s["rays"]["total"] / s["seconds"]["render"] / 1e6, s["seconds"]["build"], s["memory_bytes"]["acceleration"]
print(f"furBall_A ({segments} round linear segments), {size}x{size}, path length {depth}, {frames} spp, "
      f"{runs} interleaved runs\n")
print(f"{'renderer':18} {'thr':>3} {'Mrays/s':>8} {'min-max':>13} {'x Embree':>8} {'build s':>8} {'B/segment':>10}")
for t in threads:
    e = [embree(t, r) for r in range(1, runs + 1)]
    em = statistics.median(e)
    seconds, per_prim = embree_build(t)
    print(f"{'Embree pathtracer':18} {t:>3} {em:8.3f} {min(e):6.3f}-{max(e):<6.3f} {'':>8} {seconds:8.2f} {per_prim:10.1f}")
    for backend in ("embree", "native"):
        rows = [rtpro(backend, t, r) for r in range(1, runs + 1)]
        m = statistics.median(x for x, _, _ in rows)
        build = statistics.median(b for _, b, _ in rows)
        print(f"{'rtpro ' + backend:18} {t:>3} {m:8.3f} {min(x for x, _, _ in rows):6.3f}-"
              f"{max(x for x, _, _ in rows):<6.3f} {m / em:7.2f}x {build:8.2f} {rows[0][2] / segments:10.1f}")
print(f"\nlogs and statistics: {out}")
PY
