# Sourced by the benchmark scripts that take the shared options: --runs N, --threads "1 2", and
# --help (the script's opening comment). Sets runs and threads, and, through release_tree.sh, root,
# build, build_release and compare_each. A script whose defaults differ sets default_runs and
# default_threads before sourcing it.
source "$(dirname "${BASH_SOURCE[0]}")/release_tree.sh"
runs=${default_runs:-3}
threads=${default_threads:-1 2}
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    -h | --help) sed -n '2,/^set /{/^set /d; s/^# \{0,1\}//; p}' "$0"; exit 0 ;;
    *) echo "usage: $0 [--runs N] [--threads \"$threads\"] (--help: what it measures)" >&2; exit 2 ;;
  esac
done
check_runs
[[ $threads =~ ^\ *[1-9][0-9]*(\ +[1-9][0-9]*)*\ *$ ]] ||
  { echo "$0: --threads takes positive counts, not '$threads'" >&2; exit 2; }
# single_thread_count: stops a script that renders at one thread count when given several.
single_thread_count() {
  [[ $threads =~ ^\ *([1-9][0-9]*)\ *$ ]] || { echo "$0: --threads takes one count here, not '$threads'" >&2; exit 2; }
  threads=${BASH_REMATCH[1]}
}
