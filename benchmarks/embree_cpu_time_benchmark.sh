#!/usr/bin/env bash
# Rays per CPU second of Embree's own `pathtracer` and of rtpro, one thread, on Embree's Cornell box
# (benchmarks/embree/cornell_box.yaml, 512x512, path length 8), its furBall_A (SCENE=fur:
# benchmarks/fur_ball.yaml, 128x128, fibres matte as in fur_ball_benchmark.sh) or the Stanford
# dragon (SCENE=dragon: benchmarks/embree_dragon_path.sh, 512x512). For a machine
# shared with other work, where wall-clock rates follow the neighbours' load: the CPU time a
# process is charged barely moves with it. Each renderer runs twice per run, at LO and HI samples
# (Embree: --benchmark 0 LO and 0 HI frames of 1 spp), and the rate is the extra rays over the extra
# CPU seconds (user + system, /usr/bin/time), so loading, building and writing cancel out. Embree's
# rays a frame are its BENCHMARK_RENDER_MRAYPS_AVG / BENCHMARK_RENDER_AVG (frames a second); rtpro's
# from --stats-json. Runs are interleaved; the table gives medians, min-max and ratios to Embree.
# Usage: benchmarks/embree_cpu_time_benchmark.sh [--runs N]   (SCENE=box|fur|dragon LO=1 HI=5 (17
#   for the dragon)
#   CONFIGS="embree embree-not-robust native" EMBREE_ISA=default|avx2|...)
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
source "$(dirname "$0")/embree_fur_matte.sh"
source "$(dirname "$0")/embree_dragon_path.sh"
command -v pathtracer >/dev/null || { echo "pathtracer not found: apt-get install embree-tools" >&2; exit 2; }
models=/usr/share/doc/embree3/models
lo=${LO:-1}
# The dragon loads and builds for ~0.6 s; 4 extra samples were too few to stand out of that
# (the peer's rays per CPU second spread 4.57-8.54 over 3 runs, with 16: 5.07-5.21).
default_hi=5
[ "${SCENE:-box}" != dragon ] || default_hi=17
hi=${HI:-$default_hi}
configs=${CONFIGS:-embree embree-not-robust native}
build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-embree-cpu.XXXXXX")
case ${SCENE:-box} in
  box) size=512 peer_scene=(-c "$models/cornell_box.ecs") yaml=$root/benchmarks/embree/cornell_box.yaml ;;
  fur)
    size=128 peer_scene=(-c "$out/furBall_matte.ecs") yaml=$out/fur_ball.yaml
    embree_fur_matte "$out"
    sed "s#file: fur_ball.hair#file: $root/benchmarks/fur_ball.hair#" "$root/benchmarks/fur_ball.yaml" >"$yaml" ;;
  dragon) size=512 yaml=$out/dragon_path.yaml; embree_dragon_path "$out" "$size" ;;
  *) echo "SCENE must be box, fur or dragon" >&2; exit 2 ;;
esac
isa=()
[ "${EMBREE_ISA:-default}" = default ] || isa=(--rtcore "max_isa=$EMBREE_ISA")

# cpu_seconds LOG COMMAND...: runs COMMAND (output into LOG) and prints its user + system seconds.
cpu_seconds() {
  local log=$1
  shift
  /usr/bin/time -f "%U %S" -o "$log.time" "$@" >"$log" 2>&1
  awk '{print $1 + $2}' "$log.time"
}

pin_for 1  # every run on one CPU: the CPU time a process is charged depends on the core too
for r in $(seq "$runs"); do
  for n in $lo $hi; do
    (cd "$out" && cpu_seconds "$out/peer-$n-r$r.log" "${pin[@]}" pathtracer "${peer_scene[@]}" --size "$size" "$size" \
      --spp 1 --max-path-length 8 --threads 1 "${isa[@]}" --benchmark 0 "$n") >"$out/peer-$n-r$r.cpu"
    for config in $configs; do
      flags=(--backend "${config%%-*}")
      [[ $config != *-not-robust ]] || flags+=(--no-embree-robust)
      cpu_seconds "$out/$config-$n-r$r.log" "${pin[@]}" "$build/rtpro" render "$yaml" -o "$out/rtpro.exr" --size "${size}x$size" \
        --spp "$n" --max-depth 8 --threads 1 "${flags[@]}" --quiet --no-journal \
        --stats-json "$out/$config-$n-r$r.json" >"$out/$config-$n-r$r.cpu"
    done
  done
done
uptime >"$out/load"

python3 - "$out" "$runs" "$lo" "$hi" "$configs" "$size" <<'PY'
import json, re, statistics, sys
out, runs, lo, hi, configs, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5].split(), int(sys.argv[6])
def cpu(name, n, r): return float(open(f"{out}/{name}-{n}-r{r}.cpu").read())
def embree_rays(n, r):
    log = open(f"{out}/peer-{n}-r{r}.log").read()
    per_frame = float(re.search(r"BENCHMARK_RENDER_MRAYPS_AVG ([\d.]+)", log).group(1)) / float(
        re.search(r"BENCHMARK_RENDER_AVG ([\d.]+)", log).group(1))
    return per_frame * n
def rtpro_rays(config, n, r): return json.load(open(f"{out}/{config}-{n}-r{r}.json"))["rays"]["total"] / 1e6
def rate(name, rays, r):
    seconds = cpu(name, hi, r) - cpu(name, lo, r)
    return (rays(hi, r) - rays(lo, r)) / seconds, (hi - lo) * size * size / 1e6 / seconds
rows = {"Embree pathtracer": [rate("peer", embree_rays, r) for r in range(1, runs + 1)]}
for config in configs:
    rows[f"rtpro {config}"] = [rate(config, lambda n, r, c=config: rtpro_rays(c, n, r), r) for r in range(1, runs + 1)]
peer = [statistics.median(x[i] for x in rows["Embree pathtracer"]) for i in (0, 1)]
print(f"Mrays and Mpaths (camera samples) per CPU second, 1 thread, {hi - lo} extra samples, {runs} interleaved runs")
print(f"{'renderer':26} {'Mrays/s':>7} {'min-max':>13} {'x Embree':>9} {'Mpaths/s':>9} {'x Embree':>9}")
for name, values in rows.items():
    m, p = (statistics.median(x[i] for x in values) for i in (0, 1))
    low, high = min(x[0] for x in values), max(x[0] for x in values)
    print(f"{name:26} {m:7.2f} {low:6.2f}-{high:<6.2f} {m / peer[0]:8.2f}x {p:9.3f} {p / peer[1]:8.2f}x")
print(f"\nload: {open(out + '/load').read().strip()}\nlogs: {out}")
PY
