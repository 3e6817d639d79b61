#!/usr/bin/env bash
# The cost of the sweet-zone study (issue 38; a benchmark, not a test): options/uq/sweet-zone.opts
# (the R161 in Nathan's game swing, a batter's impact point and undercut, -flight) with N
# Saltelli base samples, N (2 + 2) impacts, on RANKS ranks (default 2), and its projection to
# 10,000 impacts (the issue's requirement: under 5 minutes on 2 cores).
#
#   scripts/bench_uq.sh [N] [path/to/beamimpact] [beamimpact options ...]
#
# N: base samples (default 64: 256 impacts; 2500 is 10,000 impacts). Prints the impacts, the
# wall time of the whole command (MPI and PETSc start-up, the beam's modes, the statistics and
# the file included), the program's own "computed P points in T s", the time per impact (and
# per impact per rank), the projected wall time of 10,000 impacts (start-up plus 10,000 times
# the time per impact), the -log_view stages per impact, and the load average before and after
# (the machine may be shared: a loaded core gives each rank less than a core). Environment:
# BENCH_RANKS (default 2), BENCH_KEEP=dir to keep the output file, log and -log_view there.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
source "$here/find-exe.sh"
n=64
if [[ $# -gt 0 && $1 =~ ^[0-9]+$ ]]; then n=$1; shift; fi
arg=""
if [[ $# -gt 0 && -x "$1" && ! -d "$1" ]]; then arg=$1; shift; fi
exe=$(find_beamimpact bench_uq.sh "$arg") || exit 2
source "$here/mpi-env.sh"
ranks=${BENCH_RANKS:-2}
work="$(mktemp -d "${TMPDIR:-/tmp}/bench_uq.XXXXXX")"
trap 'rm -rf "$work"' EXIT

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
t0=$(date +%s.%N)
(cd "$root" && mpirun -n "$ranks" "$exe" -options_file options/uq/sweet-zone.opts -sweep_samples "$n" -output "$work/sweet-zone.h5" -log_view "$@") >"$work/log" 2>&1 || {
  tail -20 "$work/log" >&2
  echo "bench_uq.sh: the run failed (log above)" >&2
  exit 1
}
t1=$(date +%s.%N)
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
[[ -n ${BENCH_KEEP:-} ]] && mkdir -p "$BENCH_KEEP" && cp "$work/log" "$work/sweet-zone.h5" "$BENCH_KEEP/"

line=$(grep -m1 '^sweep: computed' "$work/log") || { echo "bench_uq.sh: no 'sweep: computed' line in the log" >&2; exit 1; }
points=$(sed -E 's/^sweep: computed ([0-9]+) points in ([0-9.e+-]+) s.*/\1/' <<<"$line")
farm=$(sed -E 's/^sweep: computed ([0-9]+) points in ([0-9.e+-]+) s.*/\2/' <<<"$line")
awk -v p="$points" -v farm="$farm" -v t0="$t0" -v t1="$t1" -v r="$ranks" -v n="$n" -v lb="$load_before" -v la="$load_after" 'BEGIN {
  wall = t1 - t0; per = farm / p; start = wall - farm
  printf "bench_uq: options/uq/sweet-zone.opts, %d base samples: %d impacts on %d rank(s)\n", n, p, r
  printf "  wall time %.2f s (the farm %.2f s, start-up, modes, statistics and file %.2f s)\n", wall, farm, start
  printf "  per impact %.2f ms (%.1f ms per impact per rank)\n", 1e3 * per, 1e3 * per * r
  printf "  projected for 10,000 impacts: %.0f s (%.1f min)%s\n", start + 1e4 * per, (start + 1e4 * per) / 60, p == 10000 ? " (measured)" : ""
  printf "  load average before %s, after %s (the machine is shared: each rank gets a core only when the load is below the cores)\n", lb, la
}'
echo "  -log_view stages, rank-time per impact (their average over the ranks x ranks / impacts):"
sed -nE '/^Summary of Stages/,/^$/ s/^ *[0-9]+: +(.*): +([0-9.e+-]+) .*/\1|\2/p' "$work/log" |
  awk -F'|' -v p="$points" -v r="$ranks" '{ printf "    %-28s %8.2f ms\n", $1, 1e3 * $2 * r / p }'
