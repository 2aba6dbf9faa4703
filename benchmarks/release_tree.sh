# Sourced by the benchmark scripts: the Release tree they measure (RTPRO_BUILD_DIR, else
# build-release/ beside the sources). Sets root and build, and defines build_release, check_runs,
# compare_each and pin_for.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${RTPRO_BUILD_DIR:-$root/build-release}

# build_release TARGET...: configures the tree once (an existing one keeps its own settings, but a
# tree that is not Release stops the script: its figures would not be rtpro's) and builds TARGETs.
build_release() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTPRO_BUILD_TESTS=OFF >/dev/null
  fi
  grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt" || { echo "$build is not a Release tree" >&2; exit 2; }
  cmake --build "$build" --target "$@" >/dev/null
}

# check_runs: stops the script unless runs is a positive count.
check_runs() {
  [[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "$0: --runs takes a positive count, not '$runs'" >&2; exit 2; }
}

# compare_each REFERENCE IMAGE...: `rtpro compare REFERENCE IMAGE --json` into IMAGE.compare.json
# beside each IMAGE.exr; its exit status is not checked (1 says only that the images differ).
compare_each() {
  local reference=$1 image
  shift
  for image in "$@"; do
    "$build/rtpro" compare "$reference" "$image" --json >"${image%.exr}.compare.json" || true
  done
}

# pin_for THREADS: sets `pin` to the prefix of a command run with THREADS threads: for one thread,
# taskset onto one CPU (RTPRO_BENCH_CPU, default 0; "none" leaves it to the scheduler), for more,
# nothing. Both peers of a one-thread comparison then run on the same core: the shared VMs' two
# vCPUs differ in speed by up to 30% as their hosts' load moves (Embree's pathtracer on its Cornell
# box 8.9-9.2 Mrays/s on one, 7.0-9.0 on the other, interleaved), which unpinned runs turn into
# noise in every ratio.
pin=()
pin_for() {
  local cpu=${RTPRO_BENCH_CPU:-0}
  pin=()
  if [ "$1" = 1 ] && [ "$cpu" != none ] && command -v taskset >/dev/null; then pin=(taskset -c "$cpu"); fi
}
