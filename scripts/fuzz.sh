#!/usr/bin/env bash
# Runs rtpro's fuzz targets (tests/fuzz/) with libFuzzer.
#
#   scripts/fuzz.sh [--build DIR] [--seconds N | --runs N] [--timeout S] [--parallel] [TARGET...]
#
# TARGET is scene, obj, ply, image, gltf, journal, vdb, hair (default: all). Each target replays its seed corpus and its
# regressions, then fuzzes for N seconds (default 600) or N executions, with its dictionary and
# the limits below, which turn a slow or fat input into a finding (timeout / out-of-memory
# artifact). New interesting inputs go to DIR/fuzz/corpus/TARGET (kept between runs, never
# committed); findings go to DIR/fuzz/findings/TARGET/ and make the script exit 1. Copy a finding
# into tests/fuzz/regressions/TARGET/ once it is fixed: FuzzCorpus.TARGET replays it in every build.
#
# DIR (default build-fuzz) must be configured with -DRTPRO_FUZZ=ON, e.g.
#   CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DRTPRO_FUZZ=ON -DRTPRO_SANITIZE=address,undefined
# The script builds the targets it runs. Fuzzers run under `nice -n 19`; their PIDs are written to
# /tmp/rtpro-fuzz.pid (one per line). Never starve them: libFuzzer's -timeout is wall time, so a
# SIGSTOP pause, or the idle scheduling class (`chrt --idle`) on a machine busy with a build or a
# test run, ends the campaign with a false "timeout" finding (both happened here; the inputs ran in
# milliseconds). Keep heavy work off the machine while a campaign runs, or stop the campaign, or
# give it a longer --timeout (seconds per input, default 10): a nice-19 fuzzer beside two nice-0
# compile jobs gets ~1.5% of a core, so a 200 ms input under ASan then takes ~14 s of wall time.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-fuzz
seconds=600
runs=""
parallel=0
timeout=10
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --parallel) parallel=1; shift ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(scene obj ply image gltf journal vdb hair)

# Per input: 10 s of wall time (generous: a sanitizer build at nice 19 on a busy machine; the
# corpus replay and the hostile-input tests hold inputs to far tighter limits), 2 GB of resident
# memory (ASan's own shadow and quarantine included) and no single allocation over 512 MB.
limits=(-timeout="$timeout" -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=16384 -print_final_stats=1)

binaries=()
for target in "${targets[@]}"; do binaries+=("rtpro_fuzz_$target"); done
cmake --build "$build" --target "${binaries[@]}" >/dev/null

# Keep the PIDs of fuzzers still running from another invocation, drop stale ones (a reused PID
# must never be paused by mistake).
pid_file=/tmp/rtpro-fuzz.pid
if [ -f "$pid_file" ]; then
  live=$(while read -r p; do
    case "$(ps -o comm= -p "$p" 2>/dev/null)" in rtpro_fuzz_*) echo "$p" ;; esac
  done < "$pid_file")
  printf '%s\n' $live > "$pid_file"
fi
run_target() {
  local target="$1" corpus="$build/fuzz/corpus/$1" findings="$build/fuzz/findings/$1"
  mkdir -p "$corpus" "$findings"
  local budget=(-max_total_time="$seconds")
  [ -z "$runs" ] || budget=(-runs="$runs")
  local inputs=(tests/fuzz/corpus/"$target")
  [ -d tests/fuzz/regressions/"$target" ] && inputs+=(tests/fuzz/regressions/"$target")
  nice -n 19 "$build/tests/fuzz/rtpro_fuzz_$target" "${limits[@]}" "${budget[@]}" \
    -dict=tests/fuzz/dict/"$target".dict -artifact_prefix="$findings/" \
    "$corpus" "${inputs[@]}" > "$build/fuzz/$target.log" 2>&1 &
  local pid=$!
  echo "$pid" >> "$pid_file"
  wait "$pid"
}

summary() {
  local target="$1" log="$build/fuzz/$1.log"
  local runs_done coverage
  runs_done=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  coverage=$(grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE)' "$log" | tail -1 | grep -o 'cov: [0-9]* ft: [0-9]*' || echo "cov: ? ft: ?")
  echo "$target: $runs_done executions, $coverage, findings: $(ls "$build/fuzz/findings/$target" | wc -l)"
}

status=0
if [ "$parallel" = 1 ]; then
  pids=()
  for target in "${targets[@]}"; do run_target "$target" & pids+=($!); done
  for i in "${!pids[@]}"; do wait "${pids[$i]}" || status=1; done
else
  for target in "${targets[@]}"; do run_target "$target" || status=1; done
fi
for target in "${targets[@]}"; do
  summary "$target"
  [ -z "$(ls "$build/fuzz/findings/$target")" ] || status=1
done
[ "$status" = 0 ] || echo "fuzz: findings or failures; see $build/fuzz/*.log and $build/fuzz/findings/" >&2
exit "$status"
