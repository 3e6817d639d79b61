#!/usr/bin/env bash
# After-separation benchmark (issue 12; not a test): what the post-separation window costs.
# For the 1.1 m paper sweeps (options/scenes/acor-6mm.opts: free-free and clamped at x = 0,
# RK4 at the scene's fixed step) at each grid size, the sweep time with the default window
# (two fundamental periods after each separation, followed exactly in the beam's modes:
# -impact_after modal, the default) against -impact_window 0 (the run stops at the first
# separation), and their ratio (target <= 1.5). With BENCH_TIME=1 also the default window
# integrated in time (-impact_after time: the cost before issue 12; slow on fine grids).
#
#   scripts/bench_after.sh [path/to/beamimpact]
# Environment:
#   BENCH_NODES   grid sizes (default "161 641")
#   BENCH_POINTS  impact points per sweep, spread over the beam (default 12)
#   BENCH_TIME    1: add the -impact_after time column
#   BENCH_REPEAT  runs of each, the fastest kept (default 3: other jobs make single runs noisy)
# The time is the program's own "computed N points in T s" on one rank, start-up excluded;
# the default includes the beam's modal decomposition, done once per sweep (solvers/beam_modes).
# A point where the beam catches the ball again integrates that contact too (window 0 stops
# at the first separation and misses it): that extra is physics, not overhead.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
source "$here/find-exe.sh"
exe=$(find_beamimpact bench_after.sh "${1:-}") || exit 1
source "$here/mpi-env.sh"
cd "$root"
nodes=${BENCH_NODES:-"161 641"}
npts=${BENCH_POINTS:-12}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# seconds SUPPORT N OPTIONS...: the sweep's own time, the fastest of BENCH_REPEAT runs
seconds() {
  local left=$1 n=$2 first best="" t r
  shift 2
  first=$([[ $left == clamped ]] && echo 0.05 || echo 0.0)
  for ((r = 0; r < ${BENCH_REPEAT:-3}; ++r)); do
    "$exe" -options_file options/scenes/acor-6mm.opts -beam_left "$left" -beam_nodes "$n" -sweep_x "$first:1.1:$npts" "$@" -output "$tmp/out.h5" >"$tmp/log" 2>&1 ||
      { echo "run failed:" >&2; tail -3 "$tmp/log" >&2; exit 1; }
    rm -rf "$tmp/out.h5" "$tmp/out.h5.parts"
    t=$(sed -n 's/.*computed [0-9]* points in \([0-9.e+-]*\) s.*/\1/p' "$tmp/log")
    best=$(awk -v a="$t" -v b="$best" 'BEGIN { print (b == "" || a < b) ? a : b }')
  done
  echo "$best"
}

printf "%-8s %5s %7s %14s %14s %7s" beam N points "window 0 (s)" "default (s)" ratio
[[ ${BENCH_TIME:-0} == 1 ]] && printf " %14s %7s" "time after (s)" ratio
printf "\n"
for n in $nodes; do
  for left in free clamped; do
    w0=$(seconds "$left" "$n" -impact_window 0)
    wm=$(seconds "$left" "$n")
    printf "%-8s %5s %7s %14.3f %14.3f %7.2f" "$left" "$n" "$npts" "$w0" "$wm" "$(awk -v a="$wm" -v b="$w0" 'BEGIN { print a / b }')"
    if [[ ${BENCH_TIME:-0} == 1 ]]; then
      wt=$(seconds "$left" "$n" -impact_after time)
      printf " %14.3f %7.2f" "$wt" "$(awk -v a="$wt" -v b="$w0" 'BEGIN { print a / b }')"
    fi
    printf "\n"
  done
done
