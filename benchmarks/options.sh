# Sourced by the benchmark scripts: the Release tree they use (RTPRO_BUILD_DIR, else
# build-release/ beside the sources) and the options they share, --runs N and --threads "1 2".
# Sets root, build, runs and threads.
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
