#!/usr/bin/env bash
# The truncated modal engine (issue 21, docs/model.md §12): accuracy against every mode, and
# cost against N.
#
#   scripts/study_modal.sh [accuracy|scale|all]   (default all; EXE=path/to/beamimpact, OUT=dir)
#
# accuracy: one impact with -ts_type modal on the paper's beam (1.1 m free-free, superball,
#   x = 0.9 m), the R161 Timoshenko bat and the hollow aluminium bat (baseball, 40 m/s at
#   0.7 m), at N = 161, 641, 2561 (SCENES="r161 aluminium" for some scenes, NS="161 641" for fewer: the dense decomposition of a bat's
#   5122 dofs at N = 2561 takes tens of minutes): -modal_modes auto at -modal_tolerance 1e-6 and 1e-9 against
#   -modal_modes all (the dense decomposition). Prints the modes kept and the differences in
#   ACOR, contact time and peak force (relative for the last two).
# scale: one impact on the paper's beam at x = 0.88 m (a node of every grid) at N = 641, 2561,
#   10241, 40961 (SCALE_NS): -ts_type modal at -modal_tolerance 1e-8 (SCALE_TOL) (from N = 10241
#   on the modes come from the factored form: docs/convergence.md), and -ts_type cn at two fixed
#   steps extrapolated in time on every grid: process times, modes kept, the ACOR, its
#   differences and the observed order in h; then a 5 x 5 two-axis sweep with -ts_type modal
#   at N = 641, 2561, 10241, 40961 (SWEEP_NS): its time against N.
# Timings depend on the load of the machine: the script prints `uptime` first.
set -euo pipefail
cd "$(dirname "$0")/.."
EXE=${EXE:-build/dev/beamimpact}
OUT=${OUT:-out/modal}
PY=/usr/bin/python3
what=${1:-all}
mkdir -p "$OUT"
source scripts/mpi-env.sh
echo "# $(uptime)"

# run NAME ARGS...: one impact, prints "acor contact_time peak_force modes seconds"
run() {
  local name=$1
  shift
  local t0 t1 line
  t0=$(date +%s.%N)
  line=$("$EXE" -task impact -ts_type modal -ts_view -output "$OUT/$name.h5" -output_overwrite "$@" 2>&1 | grep -o "modal engine: [0-9]* of [0-9]*" | head -1 || true)
  t1=$(date +%s.%N)
  "$PY" - "$OUT/$name.h5" "$line" "$t0" "$t1" <<'EOF'
import sys, h5py
r = h5py.File(sys.argv[1], 'r')['results']
words = sys.argv[2].split()
modes = f"{words[2]}/{words[4]}" if len(words) >= 5 else "?"
print(f"{r['acor'][0]:.15f} {r['contact_time'][0]:.15e} {r['peak_force'][0]:.15e} {modes} {float(sys.argv[4]) - float(sys.argv[3]):.2f}")
EOF
}

# run_ts TYPE NAME ARGS...: the same with a stepped integrator (no modes): "acor contact_time peak_force - seconds"
run_ts() {
  local ts=$1 name=$2
  shift 2
  local t0 t1
  t0=$(date +%s.%N)
  rm -f "$OUT/$name.h5" # a run that fails (cn's Newton at N = 40961 can meet a NaN) gives nan, not the last run's numbers
  "$EXE" -task impact -ts_type "$ts" -ts_adapt_type none -impact_cost_warn 0 -output "$OUT/$name.h5" -output_overwrite "$@" >/dev/null 2>&1 || true
  t1=$(date +%s.%N)
  "$PY" - "$OUT/$name.h5" "$t0" "$t1" <<'EOF'
import os, sys, h5py
if not os.path.exists(sys.argv[1]):
    print(f"nan nan nan failed {float(sys.argv[3]) - float(sys.argv[2]):.2f}")
    sys.exit()
r = h5py.File(sys.argv[1], 'r')['results']
print(f"{r['acor'][0]:.15f} {r['contact_time'][0]:.15e} {r['peak_force'][0]:.15e} - {float(sys.argv[3]) - float(sys.argv[2]):.2f}")
EOF
}

beam_args() { # scene name -> its options
  case $1 in
    paper) echo "-options_file options/base/aluminium-6mm.opts -options_file options/base/superball-linear.opts -beam_length 1.1 -beam_left free -beam_right free -impact_x 0.9 -impact_window 0" ;;
    r161) echo "-options_file options/bats/r161.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -ball_speed 40 -impact_x 0.7 -impact_window 0" ;;
    aluminium) echo "-options_file options/bats/aluminium-bat.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -ball_speed 40 -impact_x 0.7 -impact_window 0" ;;
  esac
}

if [[ $what == accuracy || $what == all ]]; then
  echo "## accuracy: -modal_modes auto against all (-ts_type modal, default step)"
  printf "%-10s %6s %6s %10s %10s %10s %10s %8s %8s\n" scene N tol modes dACOR dTc/Tc dF/F t_all/s t_auto/s
  for scene in ${SCENES:-paper r161 aluminium}; do
    for N in ${NS:-161 641 2561}; do
      read -r -a ref <<<"$(run "$scene-$N-all" $(beam_args $scene) -beam_nodes $N -modal_modes all)"
      for tol in 1e-6 1e-9; do
        read -r -a tr <<<"$(run "$scene-$N-$tol" $(beam_args $scene) -beam_nodes $N -modal_tolerance $tol)"
        "$PY" -c "
a, t = [float(x) for x in '${ref[*]:0:3}'.split()], [float(x) for x in '${tr[*]:0:3}'.split()]
print('%-10s %6d %6s %10s %10.2e %10.2e %10.2e %8s %8s' % ('$scene', $N, '$tol', '${tr[3]}', t[0] - a[0], t[1] / a[1] - 1, t[2] / a[2] - 1, '${ref[4]}', '${tr[4]}'))"
      done
    done
  done
fi

if [[ $what == scale || $what == all ]]; then
  # The impact point x = 0.88 m = 0.8 L is a node of every grid (N - 1 = 640 4^k: nested grids),
  # so the hat weights' point load is exact there and the spatial error is the stencil's, O(h^2).
  # -ts_type modal at SCALE_TOL (1e-8: the truncation below 1e-10 in the ACOR at N = 641, and
  # affordable at 10241; 1e-10 keeps 1052 modes at 2561, a dense 190 s) where the modes apply;
  # -ts_type cn at fixed steps T_r/1600 and T_r/3200 on every grid, extrapolated in time
  # (Richardson, order 2), with its time error estimate |A(dt) - A(dt/2)|/3: at N = 40961 cn's
  # elastic force is beyond double precision (docs/convergence.md), the factored modes are not.
  tol=${SCALE_TOL:-1e-8}
  scale_args="$(beam_args paper) -impact_x 0.88"
  echo "## scale: the paper's beam at x = 0.88 m (a node of every grid); -ts_type modal at -modal_tolerance $tol, cn extrapolated in time"
  printf "%6s %10s %18s %8s %11s %6s %18s %9s %11s %6s %8s %9s\n" N modes "ACOR modal" "t/s" "dACOR" order "ACOR cn (extrap.)" "time err" "dACOR (cn)" order "t cn/s" "modal-cn"
  prev="" prevd="" prevm="" prevmd=""
  for N in ${SCALE_NS:-641 2561 10241 40961}; do
    read -r -a r <<<"$(run "scale-$N" $scale_args -beam_nodes $N -modal_tolerance $tol)"
    read -r -a c1 <<<"$(run_ts cn "scale-cn1-$N" $scale_args -beam_nodes $N -ts_dt 2.74625e-06)"
    read -r -a c2 <<<"$(run_ts cn "scale-cn2-$N" $scale_args -beam_nodes $N -ts_dt 1.373125e-06)"
    line=$("$PY" -c "
import math
a1, a2 = float('${c1[0]}'), float('${c2[0]}')
ext = a2 + (a2 - a1) / 3
err = abs(a2 - a1) / 3
prev = '$prev'
d = ext - float(prev) if prev else float('nan')
pd = '$prevd'
order = math.log(abs(float(pd) / d)) / math.log(4) if pd and not math.isnan(d) and d != 0 else float('nan')
m = float('${r[0]}')
pm, pmd = '$prevm', '$prevmd'
dmod = m - float(pm) if pm else float('nan')
omod = math.log(abs(float(pmd) / dmod)) / math.log(4) if pmd and not math.isnan(dmod) and dmod != 0 else float('nan')
print('%.15f %.1e %.3e %.2f %.1e %r %.3e %.2f %r' % (ext, err, d, order, m - ext if not math.isnan(m) else float('nan'), d, dmod, omod, dmod))")
    read -r ext err d order dm dd dmod omod ddm <<<"$line"
    printf "%6d %10s %18s %8s %11s %6s %18s %9s %11s %6s %8s %9s\n" "$N" "${r[3]}" "${r[0]}" "${r[4]}" "$dmod" "$omod" "$ext" "$err" "$d" "$order" "$(awk -v a="${c1[4]}" -v b="${c2[4]}" 'BEGIN {print a + b}')" "$dm"
    prevd=$([[ $dd == nan ]] && echo "" || echo "$dd")
    prevmd=$([[ $ddm == nan ]] && echo "" || echo "$ddm")
    prev=$ext prevm=${r[0]}
  done
  echo "(dACOR, order: the modal ACOR's difference from the coarser grid and log4 of successive differences; cn at -ts_dt 2.746e-6 and 1.373e-6 s (T_r/1600, T_r/3200), extrapolated; t cn: both runs; its order likewise)"
  echo "## the two-axis sweep (impact_x x ball_speed, 5 x 5 points, -ts_type modal at -modal_tolerance $tol) against N"
  printf "%6s %10s %12s\n" N "t/s" "ms a point"
  for N in ${SWEEP_NS:-641 2561 10241 40961}; do
    t0=$(date +%s.%N)
    "$EXE" -task sweep $(beam_args paper) -beam_nodes $N -ts_type modal -modal_tolerance $tol -sweep "impact_x=0.2:1.0:5,ball_speed=0.5:2.5:5" \
      -sweep_progress_interval 1e9 -sweep_restart -output "$OUT/sweep-$N.h5" >"$OUT/sweep-$N.log" 2>&1 || { echo "the sweep at N = $N failed: $OUT/sweep-$N.log"; continue; }
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" -v n="$N" 'BEGIN {printf "%6d %10.2f %12.1f\n", n, b - a, 1e3 * (b - a) / 25}'
  done
fi
