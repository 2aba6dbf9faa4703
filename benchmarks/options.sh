# Sourced by the benchmark scripts that take the shared options: --runs N, --threads "1 2", and
# --help (the script's opening comment). Sets runs and threads, and, through release_tree.sh, root,
# build, build_release and compare_each.
source "$(dirname "${BASH_SOURCE[0]}")/release_tree.sh"
runs=3
threads="1 2"
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    -h | --help) sed -n '2,/^set /{/^set /d; s/^# \{0,1\}//; p}' "$0"; exit 0 ;;
    *) echo "usage: $0 [--runs N] [--threads \"1 2\"] (--help: what it measures)" >&2; exit 2 ;;
  esac
done
