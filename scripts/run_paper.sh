#!/usr/bin/env bash
# Runs every scene of R. Cross, Am. J. Phys. 67, 692 (1999) (options/scenes/*.opts, listed in
# docs/scenes.md) and draws every figure (scripts/paper_figures.py).
#
#   scripts/run_paper.sh [--quick] [--restart] [path/to/beamimpact]
#
# The executable defaults to build/release/beamimpact (cmake --preset release &&
# cmake --build --preset release). Sweeps run with `mpirun -n $(nproc)` ($MPIEXEC overrides
# mpirun, $NP the rank count); single impacts run $NP at a time.
# Output: out/paper/*.h5, *.log, *.png, summary.txt and runtimes.txt; with --quick (sweeps and
# the racket-energy points 5 cm apart instead of 1-2 cm) out/paper-quick/. The full set takes
# ~45 s on 2 cores, --quick ~25 s (mostly start-up of the many short runs).
# Sweeps resume: points already in out/paper/*.h5 are not recomputed. After changing a scene
# file, --restart starts its sweeps over (a sweep with other parameters is refused otherwise).
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0 restart=0 exe=""
for arg in "$@"; do
  case $arg in
    --quick) quick=1 ;;
    --restart) restart=1 ;;
    -h | --help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "run_paper.sh: unknown option $arg (use --quick, --restart, or the path to beamimpact)" >&2; exit 2 ;;
    *) exe=$arg ;;
  esac
done
exe=${exe:-build/release/beamimpact}
if [[ ! -x $exe ]]; then
  echo "run_paper.sh: no executable at $exe; build it first (cmake --preset release && cmake --build --preset release)" >&2
  echo "  or give its path: scripts/run_paper.sh path/to/beamimpact" >&2
  exit 2
fi
exe=$(readlink -f "$exe")
# shellcheck source=scripts/mpi-env.sh
source scripts/mpi-env.sh
np=${NP:-$(nproc)}
mpiexec=${MPIEXEC:-mpirun}

if ((quick)); then out=out/paper-quick; else out=out/paper; fi
mkdir -p "$out/racket-energy"
: >"$out/runtimes.txt"
sweep_extra=()
((restart)) && sweep_extra+=(-sweep_restart)

now() { date +%s.%N; }
# timed NAME START: one line in runtimes.txt and on screen
timed() { local dt; dt=$(awk -v a="$2" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'); printf '%-28s %6s s\n' "$1" "$dt" | tee -a "$out/runtimes.txt"; }

# sweep NAME OPTS_FILE [options...]: one -task sweep on all ranks, log in $out/NAME.log
sweep() {
  local name=$1 file=$2 t0; shift 2
  t0=$(now)
  if ! "$mpiexec" -n "$np" "$exe" -options_file "$file" "$@" -sweep_progress_interval 10 "${sweep_extra[@]}" \
      -output "$out/$name.h5" >"$out/$name.log" 2>&1; then
    echo "run_paper.sh: $name failed; see $out/$name.log:" >&2; tail -5 "$out/$name.log" >&2; exit 1
  fi
  timed "$name (sweep, $np ranks)" "$t0"
}

# impacts LABEL < lines "NAME OPTS_FILE [options...]": single runs, $np at a time, logs next to the files
impacts() {
  local label=$1 t0 status=0
  t0=$(now)
  # shellcheck disable=SC2016
  xargs -P "$np" -L 1 bash -c 'name=$1 file=$2; shift 2; "$0" -options_file "$file" "$@" -output "$OUT/$name.h5" >"$OUT/$name.log" 2>&1 || { echo "failed: $name (see $OUT/$name.log)" >&2; exit 255; }' "$exe" \
    || status=$?
  ((status == 0)) || { echo "run_paper.sh: $label failed" >&2; exit 1; }
  timed "$label" "$t0"
}
export OUT=$out

t_all=$(now)
echo "beamimpact: $exe    output: $out/    ranks: $np$( ((quick)) && echo '    (quick)')"

# modes: the table of periods, 6 mm beams of four lengths and the 10 mm beam, clamped-free and free-free
for a in 6 10; do
  if [[ $a == 6 ]]; then lengths="0.3 0.6 1.1 1.8"; else lengths="1.1"; fi
  for L in $lengths; do
    for s in clamped free; do
      echo "modes-${a}mm-$L-$s options/scenes/modes.opts -beam_thickness 0.0$(printf '%02d' "$a") -beam_length $L -beam_left $s"
    done
  done
done | impacts "modes (10 beams)"

# waves: the dispersed pulse (N = 181), and the same on the base grid N = 41 for the discrete group velocity
printf '%s\n' "waves options/scenes/waves.opts" "waves-n41 options/scenes/waves.opts -beam_nodes 41" | impacts "waves (N = 181 and 41)"

# ACOR sweeps: 1 cm apart, or 5 cm with --quick
if ((quick)); then step=0.05; else step=0.01; fi
pts() { awk -v a="$1" -v b="$2" -v s="$step" 'BEGIN { printf "%s:%s:%d", a, b, int((b - a) / s + 0.5) + 1 }'; }
for L in 0.3 0.6 1.1; do
  case $L in 0.3) f=0.2 ;; 0.6) f=0.6 ;; *) f=0 ;; esac
  sweep "acor-6mm-$L-free" options/scenes/acor-6mm.opts -beam_length $L -sweep_x "$(pts 0 $L)" -rigid_loss_fraction $f
  sweep "acor-6mm-$L-clamped" options/scenes/acor-6mm.opts -beam_length $L -beam_left clamped -sweep_x "$(pts 0.01 $L)"
done
sweep acor-6mm-1.1-clamped-hysteresis options/scenes/acor-6mm-hysteresis.opts -sweep_x "$(pts 0.01 1.1)"
sweep acor-10mm-1.1-free options/scenes/acor-10mm.opts -sweep_x "$(pts 0 1.1)"

# snapshots of the 1.1 m beam, and the energy partition against time
printf '%s\n' "snapshots-0.55 options/scenes/snapshots.opts -impact_x 0.55" \
  "snapshots-0.90 options/scenes/snapshots.opts -impact_x 0.9" \
  "snapshots-1.03 options/scenes/snapshots.opts -impact_x 1.03" | impacts "snapshots (3 impacts)"
printf '%s\n' "energy-0.55 options/scenes/energy.opts -impact_x 0.55" \
  "energy-0.90 options/scenes/energy.opts -impact_x 0.9" | impacts "energy (2 impacts)"

# the racket: ACOR for the three handle supports, snapshots, energy against impact point
sweep racket-acor-free options/scenes/racket-acor.opts -sweep_x "$(pts 0 0.6)"
sweep racket-acor-pinned options/scenes/racket-acor.opts -beam_right pinned -sweep_x "$(pts 0 0.6)"
sweep racket-acor-clamped options/scenes/racket-acor.opts -beam_clamp 0.62,0.72 -sweep_x "$(pts 0 0.6)"
printf '%s\n' "racket-snapshots-pinned options/scenes/racket-snapshots.opts" \
  "racket-snapshots-clamped options/scenes/racket-snapshots.opts -beam_right free -beam_clamp 0.62,0.72 -impact_x 0.31" |
  impacts "racket snapshots (2 impacts)"
# one -task impact per point: -task sweep does not take -monitor_segment (see racket-energy.opts)
if ((quick)); then estep=5; else estep=2; fi
rm -f "$out"/racket-energy/x*.h5
for ((cm = 0; cm <= 60; cm += estep)); do
  x=$(awk -v c=$cm 'BEGIN { printf "%.2f", c / 100 }')
  echo "racket-energy/x$x options/scenes/racket-energy.opts -impact_x $x"
done | impacts "racket energy ($(( 60 / estep + 1 )) impacts)"

timed "all scenes" "$t_all"

# figures and the comparison numbers
t0=$(now)
scripts/paper_figures.py "$out"
timed "figures" "$t0"
echo "figures: $out/*.png    numbers: $out/summary.txt    runtimes: $out/runtimes.txt"
