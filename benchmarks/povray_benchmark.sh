#!/usr/bin/env bash
# POV-Ray 3.7 as a measured peer on two Whitted scenes written for both renderers: the demo at
# 800x600, 64 spp and the 10,000-sphere scene at 480x360, 16 spp, max depth 5. POV-Ray renders the
# committed benchmarks/povray/*.pov (scripts/yaml_to_pov.py output) with their .ini; rtpro renders
# the shipped scenes/*.yaml with the same size, samples and depth. For each scene and thread count
# the runs are interleaved (povray, rtpro embree, rtpro native, N times) and timed as whole
# processes; the table gives medians, min-max, POV time / rtpro time, and rays by kind per second
# of render (rtpro: --stats-json over seconds.render; POV-Ray: its own statistics over Trace Time).
# One-thread runs share one CPU (pin_for, release_tree.sh).
# Usage: benchmarks/povray_benchmark.sh [--runs N] [--threads "1 2"]
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"
command -v povray >/dev/null || { echo "povray not found: apt-get install povray (Debian package, 3.7)" >&2; exit 2; }

build_release rtpro

out=$(mktemp -d "${TMPDIR:-/tmp}/rtpro-povray.XXXXXX")
# name | rtpro scene | size | spp | max depth: the values the committed .pov/.ini were made with
scenes=("demo|scenes/demo.yaml|800x600|64|5" "many_spheres|scenes/many_spheres.yaml|480x360|16|5")

for entry in "${scenes[@]}"; do
  IFS='|' read -r name yaml size spp depth <<<"$entry"
  # The committed POV-Ray files must still be the translation of today's scene.
  (cd "$root" && python3 scripts/yaml_to_pov.py "$yaml" "$out/$name.pov" --size "$size" --spp "$spp" --max-depth "$depth")
  cmp -s "$out/$name.pov" "$root/benchmarks/povray/$name.pov" ||
    echo "warning: benchmarks/povray/$name.pov is not the translation of $yaml; regenerate it with scripts/yaml_to_pov.py" >&2
  for t in $threads; do
    pin_for "$t"
    for r in $(seq "$runs"); do
      (cd "$out" && /usr/bin/time -f "%e %U %S %M" -o "$out/$name-povray-t$t-r$r.time" \
        "${pin[@]}" povray "$root/benchmarks/povray/$name.ini" +I"$root/benchmarks/povray/$name.pov" +O"$name-povray.exr" \
        +WT"$t" -V >"$out/$name-povray-t$t-r$r.log" 2>&1) || echo "povray failed on $name, see $out" >&2
      for backend in embree native; do
        /usr/bin/time -f "%e %U %S %M" -o "$out/$name-$backend-t$t-r$r.time" "${pin[@]}" "$build/rtpro" render "$root/$yaml" \
          -o "$out/$name-$backend.exr" --size "$size" --spp "$spp" --max-depth "$depth" --backend "$backend" \
          --threads "$t" --quiet --stats-json "$out/$name-$backend-t$t-r$r.json" || echo "rtpro $backend failed on $name" >&2
      done
    done
  done
done

python3 - "$out" "$runs" "$threads" "${scenes[@]}" <<'PY'
import json, re, statistics, sys
out, runs, threads, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4:]
KINDS = ("camera", "shadow", "reflection", "total")

def wall(name, who, t):
    """Whole-process wall seconds, CPU seconds (user + system) and peak RSS (MiB) of each run."""
    runs_ = [open(f"{out}/{name}-{who}-t{t}-r{r}.time").read().split()[-4:] for r in range(1, runs + 1)]
    return ([float(e) for e, _, _, _ in runs_], [float(u) + float(s) for _, u, s, _ in runs_],
            max(int(kb) for *_, kb in runs_) / 1024)

def rtpro_rays(name, backend, t, r):
    s = json.load(open(f"{out}/{name}-{backend}-t{t}-r{r}.json"))
    return {k: s["rays"][k] for k in KINDS}, s["seconds"]["render"]

def povray_rays(name, t, r):
    """POV-Ray's statistics: camera rays are the pixels' centre rays (plus the extra row and column
    each block traces for the anti-aliasing test) and the supersamples; 'Rays' counts camera and
    reflected rays, shadow rays are 'Shadow Ray Tests' (including its shadow-cache hits)."""
    log = open(f"{out}/{name}-povray-t{t}-r{r}.log").read()
    def number(label):
        return int(re.search(rf"{label}:\s+(\d+)", log).group(1))
    camera, shadow, reflection = number("Pixels") + number("Samples"), number("Shadow Ray Tests"), number("Reflected Rays")
    seconds = float(re.search(r"Trace Time:.*\(([\d.]+) seconds\)", log).group(1))
    return {"camera": camera, "shadow": shadow, "reflection": reflection, "total": number("Rays") + shadow}, seconds

def rates(samples):
    """Median over runs of rays of each kind per second of render, in millions."""
    return {k: statistics.median(c[k] / s / 1e6 for c, s in samples) for k in KINDS}

print(f"POV-Ray 3.7 vs rtpro: whole-process wall time over {runs} interleaved runs (median, min-max; cpu s: median"
      " user + system);\nMrays/s by kind = rays of each kind per second of render (rtpro: seconds.render of"
      " --stats-json; POV-Ray: its Trace Time).\n")
header = (f"{'scene':13} {'thr':>3} {'renderer':13} {'median s':>9} {'min-max s':>13} {'POV/rtpro':>9}"
          f" {'cpu s':>7} {'POV/rt cpu':>10} {'camera':>7} {'shadow':>7} {'refl':>7} {'total':>7} {'peak MiB':>8}")
print(header)
print("-" * len(header))
counts = {}
for entry in scenes:
    name, _, size, spp, depth = entry.split("|")
    for t in threads:
        pov_times, pov_cpu, _ = wall(name, "povray", t)
        pov_median, pov_cpu_median = statistics.median(pov_times), statistics.median(pov_cpu)
        for who in ("povray", "embree", "native"):
            times, cpu, peak = wall(name, who, t)
            samples = ([povray_rays(name, t, r) for r in range(1, runs + 1)] if who == "povray" else
                       [rtpro_rays(name, who, t, r) for r in range(1, runs + 1)])
            counts.setdefault(name, {})[who] = samples[0][0]
            median = statistics.median(times)
            ratio = "" if who == "povray" else f"{pov_median / median:8.2f}x"
            cpu_ratio = "" if who == "povray" else f"{pov_cpu_median / statistics.median(cpu):6.2f}x"
            m = rates(samples)
            label = "povray" if who == "povray" else f"rtpro {who}"
            print(f"{name:13} {t:>3} {label:13} {median:9.2f} {min(times):6.2f}-{max(times):<6.2f} {ratio:>9}"
                  f" {statistics.median(cpu):7.2f} {cpu_ratio:>10} {m['camera']:7.2f} {m['shadow']:7.2f} {m['reflection']:7.2f} {m['total']:7.2f} {peak:8.0f}")
    print(f"{'':13} rays per image (millions), povray / rtpro: " + ", ".join(
        f"{k} {counts[name]['povray'][k] / 1e6:.2f} / {counts[name]['embree'][k] / 1e6:.2f}" for k in KINDS))
    print(f"{'':13} ({size}, {spp} spp, max depth {depth})")
    # Reading the scene: POV-Ray's Parse Time against rtpro's seconds.load (scene file, meshes and
    # render scene), medians over every run of this scene.
    def parse_seconds(t, r):
        log = open(f"{out}/{name}-povray-t{t}-r{r}.log").read()
        return float(re.search(r"Parse Time:.*\(([\d.]+) seconds\)", log).group(1))
    pov_parse = statistics.median(parse_seconds(t, r) for t in threads for r in range(1, runs + 1))
    loads = {b: statistics.median(json.load(open(f"{out}/{name}-{b}-t{t}-r{r}.json"))["seconds"]["load"]
                                  for t in threads for r in range(1, runs + 1)) for b in ("embree", "native")}
    print(f"{'':13} scene reading: povray parse {pov_parse:.3f} s, rtpro load {loads['embree']:.3f} s (embree runs),"
          f" {loads['native']:.3f} s (native runs): POV/rtpro {pov_parse / statistics.median(loads.values()):.2f}x")
print(f"\nlogs, statistics and images: {out}")
PY
