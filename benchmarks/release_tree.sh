# Sourced by the benchmark scripts: the Release tree they measure (RTPRO_BUILD_DIR, else
# build-release/ beside the sources). Sets root and build, and defines build_release and
# compare_each.
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

# compare_each REFERENCE IMAGE...: `rtpro compare REFERENCE IMAGE --json` into IMAGE.compare.json
# beside each IMAGE.exr; its exit status is not checked (1 says only that the images differ).
compare_each() {
  local reference=$1 image
  shift
  for image in "$@"; do
    "$build/rtpro" compare "$reference" "$image" --json >"${image%.exr}.compare.json" || true
  done
}
