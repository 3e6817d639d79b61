#!/usr/bin/env bash
# The truncated modal engine (issue 21, docs/model.md §12): accuracy against every mode, and
# cost against N.
#
#   scripts/study_modal.sh [accuracy|scale|all]   (default all; EXE=path/to/beamimpact, OUT=dir)
#
# accuracy: one impact with -ts_type modal on the paper's beam (1.1 m free-free, superball,
#   x = 0.9 m), the R161 Timoshenko bat and the hollow aluminium bat (baseball, 40 m/s at
#   0.7 m), at N = 161, 641, 2561 (NS="161 641" for fewer: the dense decomposition of a bat's
#   5122 dofs at N = 2561 takes tens of minutes): -modal_modes auto at -modal_tolerance 1e-6 and 1e-9 against
#   -modal_modes all (the dense decomposition). Prints the modes kept and the differences in
#   ACOR, contact time and peak force (relative for the last two).
# scale: one impact on the paper's beam at N = 641, 2561, 10241, 40961 with -modal_tolerance
#   1e-6: process time, modes kept, ACOR and its observed order in h (from three successive N).
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
  for scene in paper r161 aluminium; do
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
  echo "## scale: the paper's beam, -modal_tolerance 1e-6 (process time includes the set-up)"
  printf "%6s %10s %18s %8s %8s\n" N modes ACOR order t/s
  acors=()
  for N in 641 2561 10241 40961; do
    read -r -a r <<<"$(run "scale-$N" $(beam_args paper) -beam_nodes $N -modal_tolerance 1e-6)"
    acors+=("${r[0]}")
    order=$("$PY" -c "
import math
a = [float(x) for x in '${acors[*]}'.split()]
print('%.2f' % (math.log2(abs(a[-3] - a[-2]) / abs(a[-2] - a[-1])) / 2) if len(a) >= 3 else '-')" 2>/dev/null || echo -)
    printf "%6d %10s %18s %8s %8s\n" "$N" "${r[3]}" "${r[0]}" "$order" "${r[4]}"
  done
fi
