#!/usr/bin/env bash
# Sweep throughput benchmark (not a test): the default scene's ACOR sweep
# (1.1 m free-free aluminium beam, 111 points 1 cm apart, RK4 at a fixed step)
# at 1 and 2 MPI ranks; prints points per second and the parallel efficiency
#   E(P) = rate(P) / (P * rate(1)).
#
#   scripts/bench_sweep.sh [path/to/beamimpact] [beamimpact options ...]
#
# Options given after the executable are appended to the defaults (the last
# value of an option wins). Environment:
#   BENCH_RANKS   rank counts to run (default "1 2")
#   BENCH_REPEAT  runs per rank count, interleaved (default 3); the median and
#                 the best rate are reported (other jobs on the machine make
#                 single runs noisy)
#   MPIEXEC       launcher (default mpiexec); MPIEXEC_FLAGS extra launcher flags
# The rate is the program's own "computed N points in T s" (start-up of MPI
# and PETSc excluded, the final file write included); "ranks busy" is the
# share of that time the ranks spent in cases (load balance).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
exe=""
if [[ $# -gt 0 && -x "$1" && ! -d "$1" ]]; then
  exe="$1"
  shift
else
  for c in "$root/build/release/beamimpact" "$root"/build/*/beamimpact; do
    if [[ -x "$c" ]]; then exe="$c"; break; fi
  done
fi
if [[ -z "$exe" ]]; then
  echo "bench_sweep.sh: no beamimpact executable found; pass its path or build one (cmake --preset release && cmake --build --preset release)" >&2
  exit 2
fi

ranks=${BENCH_RANKS:-"1 2"}
repeat=${BENCH_REPEAT:-3}
mpiexec=${MPIEXEC:-mpiexec}
# Open MPI refuses to run as root without these; harmless elsewhere.
source "$(dirname "${BASH_SOURCE[0]}")/mpi-env.sh"

defaults=(-beam_length 1.1 -beam_left free -beam_right free -ball_law linear
          -ts_type rk -ts_rk_type 4 -ts_adapt_type none
          -sweep_x 0:1.1:111 -sweep_progress_interval 1e9)
work="$(mktemp -d "${TMPDIR:-/tmp}/bench_sweep.XXXXXX")"
trap 'rm -rf "$work"' EXIT

echo "executable: $exe"
echo "options:    ${defaults[*]} $*"
echo "machine:    $(nproc) cores, $(uname -n); repeats: $repeat"
declare -A rates busy
for ((r = 1; r <= repeat; ++r)); do
  for p in $ranks; do
    log="$work/np$p.run$r.log"
    # shellcheck disable=SC2086
    if ! "$mpiexec" ${MPIEXEC_FLAGS:-} -n "$p" "$exe" -task sweep "${defaults[@]}" "$@" -sweep_restart -output "$work/np$p.h5" >"$log" 2>&1; then
      echo "bench_sweep.sh: the sweep at $p rank(s) failed:" >&2
      cat "$log" >&2
      exit 1
    fi
    line=$(grep -E "^sweep: computed" "$log" || true)
    rate=$(sed -nE 's/.*\(([0-9.eE+-]+) points\/s\).*/\1/p' <<<"$line")
    b=$(sed -nE 's/^sweep: ranks busy ([0-9.]+)%.*/\1/p' "$log")
    printf "  run %d, %d rank(s): %s  (ranks busy %s%%)\n" "$r" "$p" "${line#sweep: }" "$b"
    rates[$p]+="$rate "
    busy[$p]+="$b "
  done
done

median() { tr ' ' '\n' <<<"$1" | sed '/^$/d' | sort -g | awk '{v[NR]=$1} END {print (NR%2 ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2)}'; }
best() { tr ' ' '\n' <<<"$1" | sed '/^$/d' | sort -g | tail -1; }
first=${ranks%% *}
m1=$(median "${rates[$first]}")
b1=$(best "${rates[$first]}")
echo
printf "%6s  %18s  %18s  %14s  %14s  %10s\n" ranks "points/s (median)" "points/s (best)" "eff. (median)" "eff. (best)" "busy %"
for p in $ranks; do
  m=$(median "${rates[$p]}")
  b=$(best "${rates[$p]}")
  em=$(awk -v r="$m" -v r1="$m1" -v p="$p" -v p1="$first" 'BEGIN {printf "%.3f", r * p1 / (p * r1)}')
  eb=$(awk -v r="$b" -v r1="$b1" -v p="$p" -v p1="$first" 'BEGIN {printf "%.3f", r * p1 / (p * r1)}')
  printf "%6s  %18.1f  %18.1f  %14s  %14s  %10s\n" "$p" "$m" "$b" "$em" "$eb" "$(median "${busy[$p]}")"
done
