#!/usr/bin/env bash
# 1 -> 2 threads on every shipped scene, both backends, as a user renders them (the scene's own
# size and samples, an EXR output): whole-process wall time and the render phase (seconds.render
# of --stats-json), medians over N interleaved runs (1 and 2 threads alternate, so both see the
# same machine), and the speed-up of each.
# Usage: benchmarks/thread_scaling.sh [--runs N] [--threads "1 2"]
#   RTPRO_BUILD_DIR=DIR uses an existing Release tree instead of build-release/.
set -euo pipefail
source "$(dirname "$0")/options.sh"

"$root/scripts/fetch-dragon.sh" >/dev/null
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTPRO_BUILD_TESTS=OFF >/dev/null
fi
grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt" || { echo "$build is not a Release tree" >&2; exit 2; }
cmake --build "$build" --target rtpro >/dev/null
out=$(mktemp -d /tmp/rtpro-scaling.XXXXXX)

for scene in "$root"/scenes/*.yaml; do
  name=$(basename "$scene" .yaml)
  for run in $(seq "$runs"); do
    for backend in embree native; do
      for t in $threads; do
        /usr/bin/time -f "%e" -o "$out/$name-$backend-t$t-r$run.time" "$build/rtpro" render "$scene" \
          -o "$out/$name-$backend.exr" --backend "$backend" --threads "$t" --quiet --no-journal \
          --stats-json "$out/$name-$backend-t$t-r$run.json"
      done
    done
  done
done

python3 - "$out" "$runs" "$threads" "$root"/scenes/*.yaml <<'PY'
import json, os, statistics, sys
out, runs, threads, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(), sys.argv[4:]
low, high = threads[0], threads[-1]
print(f"{low} -> {high} threads, medians of {runs} interleaved runs (seconds; speed-up = {low}-thread time / {high}-thread time)")
print(f"{'scene':16} {'backend':8} {'whole ' + low + 't':>9} {'whole ' + high + 't':>9} {'speed-up':>9}"
      f" {'render ' + low + 't':>10} {'render ' + high + 't':>10} {'speed-up':>9}")
worst = None
for scene in scenes:
    name = os.path.basename(scene)[:-5]
    for backend in ("embree", "native"):
        def median(t, key):
            values = []
            for r in range(1, runs + 1):
                if key == "whole":
                    values.append(float(open(f"{out}/{name}-{backend}-t{t}-r{r}.time").read().split()[-1]))
                else:
                    values.append(json.load(open(f"{out}/{name}-{backend}-t{t}-r{r}.json"))["seconds"]["render"])
            return statistics.median(values)
        w1, w2, r1, r2 = median(low, "whole"), median(high, "whole"), median(low, "render"), median(high, "render")
        print(f"{name:16} {backend:8} {w1:9.3f} {w2:9.3f} {w1 / w2:8.2f}x {r1:10.3f} {r2:10.3f} {r1 / r2:8.2f}x")
        worst = min(worst or (w1 / w2, name, backend), (w1 / w2, name, backend))
print(f"lowest whole-process speed-up: {worst[0]:.2f}x ({worst[1]}, {worst[2]}); logs and statistics: {out}")
PY
