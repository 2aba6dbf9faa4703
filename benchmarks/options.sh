# Sourced by the benchmark scripts: the Release tree they use (RTPRO_BUILD_DIR, else
# build-release/ beside the sources) and the options they share, --runs N and --threads "1 2".
# Sets root, build, runs and threads; build_release_rtpro configures (once) and builds rtpro there.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${RTPRO_BUILD_DIR:-$root/build-release}
runs=3
threads="1 2"
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) echo "usage: $0 [--runs N] [--threads \"1 2\"]" >&2; exit 2 ;;
  esac
done

build_release_rtpro() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTPRO_BUILD_TESTS=OFF >/dev/null
  fi
  grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt" || { echo "$build is not a Release tree" >&2; exit 2; }
  cmake --build "$build" --target rtpro >/dev/null
}
