#!/usr/bin/env bash
# Sweep benchmarks (not tests). Two modes:
#
#   scripts/bench_sweep.sh [path/to/beamimpact] [beamimpact options ...]
#
# throughput: the default scene's ACOR sweep (1.1 m free-free aluminium beam, 111 points
# 1 cm apart, RK4 at a fixed step) at 1 and 2 MPI ranks; prints points per second and the
# parallel efficiency E(P) = rate(P) / (P * rate(1)).
#
#   scripts/bench_sweep.sh --farm [path/to/beamimpact] [beamimpact options ...]
#
# the farm's overhead: a two-axis sweep of 10 000 cheap points (11-node beam, 2 ms window
# after the contact: ~5 ms a point) on all local cores (nproc), and the same with a quarter
# of the points; prints, per point, the compute time and the farm's overhead (hand-out from
# the counter, journal appends, rank 0's live rewrites of the file, idle ranks at the end)
# from the program's own summary, with the set-up before the farm (every point's options
# read and checked, the probe, the store) per point, and checks that this overhead stays
# below 5% of the compute and that it does not grow with the point count (its share of the
# compute at 10 000 points within 25% of that at 2 500: a total cost linear in the points).
# The share, not the milliseconds, is compared: on a shared machine the compute per point
# and the overhead both move with whatever else runs. Environment: BENCH_FARM_POINTS (default "2500 10000"; each a multiple of 100),
# BENCH_FARM_RANKS (default: nproc).
#
#   scripts/bench_sweep.sh --perpoint [path/to/beamimpact] [beamimpact options ...]
#
# the cost of a point against its contact's own stepping: the default scene's sweep
# (options/default.opts, with rk4) with 2000 points (BENCH_PERPOINT_POINTS) on 1 rank at N = 41, 161
# (BENCH_PERPOINT_NODES) with -log_view, and the same with -ts_type cn, bdf, alpha2 and modal
# (BENCH_PERPOINT_TYPES) at N = 161 and 641 (BENCH_PERPOINT_CN_NODES; rk4's h^2-bound step
# would take ~1 s a point at 641). Per point it
# prints the compute (the farm's busy time), the stages of -log_view (set-up, contact, free
# flight, output; the rest is the sweep's own work: options, row) and the overhead = compute -
# contact - free flight, also as a share of the contact's stepping, and the sweep's reuse lines
# (integrator contexts built; scenarios read whole or only the point's parts; beam systems
# built: docs/sweep.md). With BENCH_BEFORE=path to
# another executable (e.g. a build of ade16c0) each sweep runs with it too, back to back. Then a
# two-axis sweep (impact_x x ball_speed, N = 41) at 500 and 2000 points: its time per point at
# 2000 over that at 500 (a total linear in the points: 1). Prints the load average.
#
# Options given after the executable are appended to the defaults (the last
# value of an option wins). Environment of the throughput mode:
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
farm=0
perpoint=0
if [[ ${1:-} == --farm ]]; then
  farm=1
  shift
elif [[ ${1:-} == --perpoint ]]; then
  perpoint=1
  shift
fi
source "$here/find-exe.sh"
arg=""
if [[ $# -gt 0 && -x "$1" && ! -d "$1" ]]; then arg=$1; shift; fi
exe=$(find_beamimpact bench_sweep.sh "$arg") || exit 2

ranks=${BENCH_RANKS:-"1 2"}
repeat=${BENCH_REPEAT:-3}
mpiexec=${MPIEXEC:-mpiexec}
# Open MPI refuses to run as root without these; harmless elsewhere.
source "$(dirname "${BASH_SOURCE[0]}")/mpi-env.sh"

work="$(mktemp -d "${TMPDIR:-/tmp}/bench_sweep.XXXXXX")"
trap 'rm -rf "$work"' EXIT

if ((farm)); then
  np=${BENCH_FARM_RANKS:-$(nproc)}
  farm_opts=(-beam_length 1.1 -beam_left free -beam_right free -beam_youngs_modulus 7e10 -beam_density 2700 -beam_thickness 0.006 -beam_width 0.032
             -beam_nodes 11 -ball_law linear -ball_mass 0.042 -ball_speed 1 -ball_k 2e4 -ball_loss_factor 0.85 -impact_window 0.002
             -ts_type rk -ts_rk_type 4 -ts_adapt_type none -sweep_progress_interval 1e9)
  echo "executable: $exe"
  echo "options:    ${farm_opts[*]} $*"
  echo "machine:    $(nproc) cores, $(uname -n); ranks: $np"
  declare -A cost over comp share
  status=0
  for n in ${BENCH_FARM_POINTS:-2500 10000}; do
    log="$work/farm$n.log"
    # shellcheck disable=SC2086
    if ! "$mpiexec" ${MPIEXEC_FLAGS:-} -n "$np" "$exe" -task sweep "${farm_opts[@]}" -sweep "impact_x=0:1.1:$((n / 100)),ball_speed=0.5:4:100" "$@" -sweep_restart -output "$work/farm$n.h5" >"$log" 2>&1; then
      echo "bench_sweep.sh: the $n-point sweep failed:" >&2
      cat "$log" >&2
      exit 1
    fi
    grep -E "^sweep: (computed|ranks busy|per point)" "$log" | sed "s/^sweep: /  $n points: /"
    line=$(grep -E "^sweep: per point" "$log")
    elapsed=$(sed -nE 's/^sweep: computed [0-9]+ points in ([0-9.eE+-]+) s.*/\1/p' "$log")
    cost[$n]=$(awk -v t="$elapsed" -v p="$np" -v n="$n" 'BEGIN {printf "%.4g", 1e3 * t * p / n}')
    comp[$n]=$(sed -nE 's/.*per point: compute ([0-9.eE+-]+) ms;.*/\1/p' <<<"$line")
    farm_ms=$(sed -nE 's/.*farm overhead ([0-9.eE+-]+) ms .*/\1/p' <<<"$line")
    setup=$(sed -nE 's/.*set-up ([0-9.eE+-]+) s$/\1/p' <<<"$line")
    over[$n]=$(awk -v f="$farm_ms" -v s="$setup" -v p="$np" -v n="$n" 'BEGIN {printf "%.4g", f + 1e3 * s * p / n}')
  done
  echo
  printf "%8s  %18s  %18s  %26s  %12s\n" points "rank-ms per point" "compute ms/point" "overhead ms/point (+set-up)" "overhead %"
  first=""
  for n in ${BENCH_FARM_POINTS:-2500 10000}; do
    pct=$(awk -v o="${over[$n]}" -v c="${comp[$n]}" 'BEGIN {printf "%.2f", 100 * o / c}')
    share[$n]=$pct
    printf "%8s  %18s  %18s  %26s  %12s\n" "$n" "${cost[$n]}" "${comp[$n]}" "${over[$n]}" "$pct"
    awk -v o="$pct" 'BEGIN {exit !(o < 5)}' || { echo "  overhead $pct% at $n points: above 5%"; status=1; }
    [[ -z $first ]] && first=$n
  done
  last=$n
  ratio=$(awk -v a="${share[$first]}" -v b="${share[$last]}" 'BEGIN {printf "%.3f", b / a}')
  echo "overhead share at $last points / at $first points: $ratio (linear total cost: 1; allowed below 1.25)"
  awk -v r="$ratio" 'BEGIN {exit !(r < 1.25)}' || { echo "  the overhead per point grows with the point count"; status=1; }
  ((status)) || echo "farm overhead below 5% and linear in the point count"
  exit $status
fi

if ((perpoint)); then
  points=${BENCH_PERPOINT_POINTS:-2000}
  exes=("$exe")
  [[ -n ${BENCH_BEFORE:-} ]] && exes+=("$BENCH_BEFORE")
  # The seconds of stage "$2" in the -log_view file $1 (0 if absent).
  stage() { awk -v s="beamimpact: $2:" 'index($0, s) { sub(/.*: /, "", $0); split($0, f, " "); t = f[1] } END { printf "%.6g", t + 0 }' "$1"; }
  echo "executable: ${exes[*]}"
  echo "machine:    $(nproc) cores, $(uname -n); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  printf "%-10s %5s %6s  %10s  %10s %10s %10s %10s %10s  %12s %10s\n" build N ts "compute" "set-up" "contact" "flight" "output" "rest" "overhead" "of contact"
  run_point_sweep() { # exe label N ts-options...
    local x=$1 label=$2 n=$3
    shift 3
    local log="$work/pp.log" lv="$work/pp.logview"
    if ! (cd "$root/options" && "$x" -options_file default.opts -sweep_x "0:1.1:$points" -beam_nodes "$n" "$@" -sweep_progress_interval 1e9 -sweep_restart -output "$work/pp.h5" -log_view ":$lv" >"$log" 2>&1); then
      echo "bench_sweep.sh: the sweep at N = $n failed:" >&2
      cat "$log" >&2
      exit 1
    fi
    local comp su co ff out
    comp=$(sed -nE 's/.*per point: compute ([0-9.eE+-]+) ms;.*/\1/p' "$log")
    su=$(stage "$lv" set-up)
    co=$(stage "$lv" contact)
    ff=$(stage "$lv" "free flight")
    out=$(stage "$lv" output)
    awk -v b="$label" -v n="$n" -v ts="$ts_label" -v c="$comp" -v su="$su" -v co="$co" -v ff="$ff" -v o="$out" -v p="$points" 'BEGIN {
      s = 1e3 * su / p; k = 1e3 * co / p; f = 1e3 * ff / p; w = 1e3 * o / p; over = c - k - f
      printf "%-10s %5d %6s  %7.4f ms  %7.4f ms %7.4f ms %7.4f ms %7.4f ms %7.4f ms  %9.4f ms %9.1f%%\n", b, n, ts, c, s, k, f, w, c - s - k - f - w, over, 100 * over / k }'
    grep -E "^sweep: (integrator contexts|per structure)" "$log" | sed 's/^/             /' || true
  }
  for n in ${BENCH_PERPOINT_NODES:-41 161}; do
    for x in "${exes[@]}"; do
      ts_label=rk4
      label=$([[ $x == "$exe" ]] && echo this || echo before)
      run_point_sweep "$x" "$label" "$n" -options_file integrators/rk4.opts "$@" # the default scene's integrator until 2026-11
    done
  done
  for n in ${BENCH_PERPOINT_CN_NODES:-161 641}; do
    for ts in ${BENCH_PERPOINT_TYPES:-cn bdf alpha2 modal}; do
      for x in "${exes[@]}"; do
        ts_label=$ts
        label=$([[ $x == "$exe" ]] && echo this || echo before)
        run_point_sweep "$x" "$label" "$n" -ts_type "$ts" "$@" # its default step, T_r/200 (bdf: adaptive)
      done
    done
  done
  echo "(ms per point; compute: the farm's busy time per point; set-up/contact/flight/output: the -log_view stages;"
  echo " rest: the sweep's own work per point (options, rows); overhead = compute - contact - flight)"
  echo
  echo "two-axis sweep (impact_x x ball_speed, N = 41, rk4):"
  for x in "${exes[@]}"; do
    label=$([[ $x == "$exe" ]] && echo this || echo before)
    declare -A per=()
    for m in 500 2000; do
      log="$work/two$m.log"
      if ! (cd "$root/options" && "$x" -options_file base/default-scene.opts -options_file integrators/rk4.opts -task sweep -sweep "impact_x=0:1.1:$((m / 20)),ball_speed=0.5:4:20" "$@" -sweep_progress_interval 1e9 -sweep_restart -output "$work/two$m.h5" >"$log" 2>&1); then
        echo "bench_sweep.sh: the two-axis sweep of $m points failed:" >&2
        cat "$log" >&2
        exit 1
      fi
      el=$(sed -nE 's/^sweep: computed [0-9]+ points in ([0-9.eE+-]+) s.*/\1/p' "$log")
      per[$m]=$(awk -v t="$el" -v m="$m" 'BEGIN {printf "%.4g", 1e3 * t / m}')
      printf "  %-7s %5d points: %s s, %s ms a point\n" "$label" "$m" "$el" "${per[$m]}"
    done
    awk -v a="${per[500]}" -v b="${per[2000]}" -v l="$label" 'BEGIN {printf "  %-7s time per point at 2000 / at 500: %.3f (linear: 1)\n", l, b / a}'
  done
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
  exit 0
fi

defaults=(-beam_length 1.1 -beam_left free -beam_right free -ball_law linear
          -ts_type rk -ts_rk_type 4 -ts_adapt_type none
          -sweep_x 0:1.1:111 -sweep_progress_interval 1e9)

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
