#!/usr/bin/env bash
# Embree's own `pathtracer` (Debian embree-tools 3.13) as a rays-per-second peer of the path
# integrator at 512x512 and the same path length, on its cornell_box.ecs (SCENE=box, the default)
# or on the Stanford dragon (SCENE=dragon: benchmarks/embree_dragon_path.sh). Embree renders 2
# warm-up and FRAMES timed frames of 1 spp (--benchmark 2 FRAMES) and reports its average Mrays/s;
# rtpro renders benchmarks/embree/cornell_box.yaml (or the dragon's scene) at FRAMES spp (the same
# samples) with each of its backends (embree: the same kernels as the peer; native: its own BVH),
# and once more with embree built as the peer builds its scene (--no-embree-robust; rtpro's
# default is Embree's robust mode, whose watertight triangle test costs more), and its rays are
# counted by kind in --stats-json (camera, shadow, bounce rays) over the render phase. Runs are
# interleaved per thread count; the table gives medians, the spread, rtpro / Embree, and paths
# (camera samples) per second, which does not depend on how either counts rays.
# Usage: benchmarks/embree_pathtracer_benchmark.sh [--runs N] [--threads "1 2"]   (FRAMES=10
#   SCENE=box|dragon)
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$(dirname "$0")/embree_dragon_path.sh"
command -v pathtracer >/dev/null || { echo "pathtracer not found: apt-get install embree-tools" >&2; exit 2; }
models=/usr/share/doc/embree3/models
frames=${FRAMES:-10}
build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-embree-pt.XXXXXX")
case ${SCENE:-box} in
  box) peer_scene=(-c "$models/cornell_box.ecs") yaml=$root/benchmarks/embree/cornell_box.yaml label=cornell_box.ecs ;;
  dragon) embree_dragon_path "$out" 512; yaml=$out/dragon_path.yaml label="the dragon" ;;
  *) echo "SCENE must be box or dragon" >&2; exit 2 ;;
esac
for t in $threads; do
  for r in $(seq "$runs"); do
    (cd "$out" && pathtracer "${peer_scene[@]}" --size 512 512 --spp 1 --max-path-length 8 --threads "$t" \
      --benchmark 2 "$frames" >"$out/embree-t$t-r$r.log" 2>&1)
    for config in embree native embree-not-robust; do
      flags=(--backend "${config%%-*}")
      [[ $config != *-not-robust ]] || flags+=(--no-embree-robust)
      "$build/rtpro" render "$yaml" -o "$out/rtpro.exr" --spp "$frames" --threads "$t" \
        "${flags[@]}" --quiet --no-journal --stats-json "$out/rtpro-$config-t$t-r$r.json"
    done
  done
done

python3 - "$out" "$runs" "$threads" "$frames" "$label" <<'PY'
import json, re, statistics, sys
out, runs, threads, frames, label = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), int(sys.argv[4]), sys.argv[5]
pixels = 512 * 512
def embree(t, r):
    log = open(f"{out}/embree-t{t}-r{r}.log").read()
    mrays = float(re.search(r"BENCHMARK_RENDER_MRAYPS_AVG ([\d.]+)", log).group(1))
    fps = float(re.search(r"BENCHMARK_RENDER_AVG ([\d.]+)", log).group(1))
    return mrays, fps * pixels / 1e6
def rtpro(backend, t, r):
    s = json.load(open(f"{out}/rtpro-{backend}-t{t}-r{r}.json"))
    seconds = s["seconds"]["render"]
    return s["rays"]["total"] / seconds / 1e6, frames * pixels / seconds / 1e6
print(f"Embree pathtracer vs rtpro path integrator, {label} at 512x512, path length 8, {runs} interleaved runs\n")
print(f"{'renderer':23} {'thr':>3} {'Mrays/s':>8} {'min-max':>13} {'Mpaths/s':>9} {'rtpro/Embree rays':>18} {'paths':>6}")
for t in threads:
    e = [embree(t, r) for r in range(1, runs + 1)]
    em, ep = statistics.median(x for x, _ in e), statistics.median(y for _, y in e)
    rows_of = {"Embree pathtracer": e}
    for config in ("embree", "native", "embree-not-robust"):
        rows_of[f"rtpro {config}"] = [rtpro(config, t, r) for r in range(1, runs + 1)]
    for name, rows in rows_of.items():
        m, q = statistics.median(x for x, _ in rows), statistics.median(y for _, y in rows)
        ratio = f"{m / em:17.2f}x {q / ep:5.2f}x" if name.startswith("rtpro") else ""
        print(f"{name:23} {t:>3} {m:8.2f} {min(x for x, _ in rows):6.2f}-{max(x for x, _ in rows):<6.2f} {q:9.3f} {ratio}")
print(f"\nlogs and statistics: {out}")
PY
