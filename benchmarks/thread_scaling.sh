#!/usr/bin/env bash
# 1 -> 2 threads on every shipped scene, both backends, as a user renders them (the scene's own
# size and samples, an EXR output): whole-process wall time and the render phase (seconds.render
# of --stats-json), medians over N interleaved runs (1 and 2 threads alternate, so both see the
# same machine), and the speed-up of each.
# Usage: benchmarks/thread_scaling.sh [--runs N] [--threads "1 2"]
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
#   SCENES="demo mesh" measures only those of scenes/*.yaml.
set -euo pipefail
source "$(dirname "$0")/options.sh"

"$root/scripts/fetch-dragon.sh" >/dev/null
build_release rtpro
out=$(mktemp -d /tmp/rtpro-scaling.XXXXXX)

scenes=()
for name in ${SCENES:-$(cd "$root/scenes" && ls *.yaml | sed 's/\.yaml$//')}; do scenes+=("$root/scenes/$name.yaml"); done

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .yaml)
  for run in $(seq "$runs"); do
    for backend in embree native; do
      for t in $threads; do
        # Bash's microsecond clock: GNU time's %e has 10 ms steps, 5% of a 0.2 s render.
        start=$EPOCHREALTIME
        "$build/rtpro" render "$scene" -o "$out/$name-$backend.exr" --backend "$backend" --threads "$t" \
          --quiet --no-journal --stats-json "$out/$name-$backend-t$t-r$run.json"
        end=$EPOCHREALTIME
        python3 -c "print($end - $start)" > "$out/$name-$backend-t$t-r$run.time"
      done
    done
  done
done

python3 - "$out" "$runs" "$threads" "${scenes[@]}" <<'PY'
import json, os, statistics, sys
out, runs, threads, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4:]
low, high = threads[0], threads[-1]
print(f"{low} -> {high} threads, medians of {runs} interleaved runs (seconds; speed-up = {low}-thread time / {high}-thread time;")
print("spread = lowest and highest speed-up of the runs' own pairs, each pair run back to back;")
print("best = fastest 1-thread run / fastest 2-thread run: noise on this shared machine only ever adds time)")
print(f"{'scene':16} {'backend':8} {'whole ' + low + 't':>9} {'whole ' + high + 't':>9} {'speed-up':>9} {'spread':>11}"
      f" {'best':>6} {'render ' + low + 't':>10} {'render ' + high + 't':>10} {'speed-up':>9} {'best':>6}")
worst = None
for scene in scenes:
    name = os.path.basename(scene)[:-5]
    for backend in ("embree", "native"):
        def times(t, key):
            if key == "whole":
                return [float(open(f"{out}/{name}-{backend}-t{t}-r{r}.time").read()) for r in range(1, runs + 1)]
            return [json.load(open(f"{out}/{name}-{backend}-t{t}-r{r}.json"))["seconds"]["render"] for r in range(1, runs + 1)]
        whole_low, whole_high = times(low, "whole"), times(high, "whole")
        pairs = [a / b for a, b in zip(whole_low, whole_high)]
        w1, w2 = statistics.median(whole_low), statistics.median(whole_high)
        render_low, render_high = times(low, "render"), times(high, "render")
        r1, r2 = statistics.median(render_low), statistics.median(render_high)
        spread = f"{min(pairs):.2f}-{max(pairs):.2f}"
        best_whole = min(whole_low) / min(whole_high)
        best_render = min(render_low) / min(render_high)
        print(f"{name:16} {backend:8} {w1:9.3f} {w2:9.3f} {w1 / w2:8.2f}x {spread:>11} {best_whole:5.2f}x"
              f" {r1:10.3f} {r2:10.3f} {r1 / r2:8.2f}x {best_render:5.2f}x")
        worst = min(worst or (w1 / w2, name, backend), (w1 / w2, name, backend))
print(f"lowest whole-process speed-up: {worst[0]:.2f}x ({worst[1]}, {worst[2]}); logs and statistics: {out}")
PY
