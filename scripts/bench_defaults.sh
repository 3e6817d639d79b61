#!/usr/bin/env bash
# Which integrator is fastest at the default accuracy, by grid size (issue 21; a benchmark, not
# a test). The default scene (options/base/default-scene.opts: the paper's 1.1 m free-free beam,
# the linear superball at 1 m/s; its integrator -ts_type modal since 2026-11, rk4 at its default
# step before) struck at x = BENCH_X (0.3 m) on
# N = BENCH_NODES nodes (41 161 641 2561). The accuracy asked is the ACOR error of the former default
# integrator on the default grid: |acor - exact| of rk4 at N = 41, the exact value from
# -reference modal (the beam's modes, no time step) on the same grid. For each N:
#   rk4     at its default step (min(T_r/200, 0.9 dt_max), dt_max ~ h^2: no larger step is allowed),
#   cn, alpha2, modal (its default order 4; the dense engine of main at the time of writing)
#           at T_r/200 halved until the error is within the target (BENCH_HALVINGS at most, 12),
# and prints each one's step, error and cost: the -log_view stages set-up (layout, TS, modal
# decomposition of -ts_type modal) and stepping (contact and free flight), in seconds on one
# rank. The free flight after the separation is in closed form for all of them (-impact_after
# modal, the default), so the stepping is the contact's.
#
#   scripts/bench_defaults.sh [path/to/beamimpact] [beamimpact options ...]
# BENCH_REFERENCE: another executable for the -reference modal runs (default: the same).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
source "$here/find-exe.sh"
arg=""
if [[ $# -gt 0 && -x "$1" && ! -d "$1" ]]; then arg=$1; shift; fi
exe=$(find_beamimpact bench_defaults.sh "$arg") || exit 2
source "$here/mpi-env.sh"
ref_exe=$(readlink -f "${BENCH_REFERENCE:-$exe}") # the executable of -reference modal
py=/usr/bin/python3
x=${BENCH_X:-0.3}
halvings=${BENCH_HALVINGS:-12}
work="$(mktemp -d "${TMPDIR:-/tmp}/bench_defaults.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# run N NAME OPTIONS...: one impact; prints "acor setup stepping dt"
run() {
  local n=$1 name=$2 exe=$exe
  shift 2
  [[ $name == ref* ]] && exe=$ref_exe
  local f="$work/$name.h5" lv="$work/$name.lv" log="$work/$name.log"
  if ! (cd "$root/options" && "$exe" -options_file base/default-scene.opts -impact_x "$x" -beam_nodes "$n" -impact_cost_warn 0 "$@" -output "$f" -output_overwrite -log_view ":$lv" >"$log" 2>&1); then
    echo "bench_defaults.sh: $name failed:" >&2
    cat "$log" >&2
    exit 1
  fi
  local acor dt
  acor=$("$py" - "$f" <<'EOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    print(repr(float(f["results/acor"][0])))
EOF
)
  dt=$("$py" - "$f" <<'EOF'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    g = f["results"]
    print(repr(float(g["dt_nominal"][0])) if "dt_nominal" in g else "nan")
EOF
)
  awk -v a="$acor" -v d="$dt" '
    /beamimpact: set-up:/ { sub(/.*set-up: */, ""); su = $1 }
    /beamimpact: contact:/ { sub(/.*contact: */, ""); co = $1 }
    /beamimpact: free flight:/ { sub(/.*free flight: */, ""); ff = $1 }
    /beamimpact: modal reference:/ { sub(/.*modal reference: */, ""); mr = $1 }
    END { printf "%s %.4g %.4g %s\n", a, su + mr, co + ff, d }' "$lv"
}

echo "executable: $exe (reference: $ref_exe)"
echo "machine:    $(nproc) cores, $(uname -n); load average: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "scene:      options/base/default-scene.opts -impact_x $x $*"
target=""
printf "%6s  %-7s %11s  %10s  %10s  %10s  %10s\n" N ts "dt (s)" "|ACOR err|" "set-up s" "stepping s" "total s"
for n in ${BENCH_NODES:-41 161 641 2561}; do
  read -r exact _ _ _ <<<"$(run "$n" "ref$n" -reference modal "$@")"
  read -r a su st dt <<<"$(run "$n" "rk4_$n" -options_file integrators/rk4.opts "$@")"
  err=$(awk -v a="$a" -v e="$exact" 'BEGIN {d = a - e; printf "%.3g", d < 0 ? -d : d}')
  [[ -z $target ]] && target=$err
  printf "%6d  %-7s %11.4g  %10s  %10s  %10s  %10.4g\n" "$n" rk4 "$dt" "$err" "$su" "$st" "$(awk -v a="$su" -v b="$st" 'BEGIN {print a + b}')"
  for ts in cn alpha2 modal; do
    opts=(-ts_type "$ts")
    read -r a su st dt0 <<<"$(run "$n" "${ts}_$n" "${opts[@]}" "$@")" # its default step: T_r/200
    for ((k = 0; ; ++k)); do
      dt=$(awk -v d="$dt0" -v k="$k" 'BEGIN {printf "%.6g", d / 2 ^ k}')
      ((k > 0)) && read -r a su st dt <<<"$(run "$n" "${ts}_$n" "${opts[@]}" -ts_dt "$dt" "$@")"
      err=$(awk -v a="$a" -v e="$exact" 'BEGIN {d = a - e; printf "%.3g", d < 0 ? -d : d}')
      ok=$(awk -v e="$err" -v t="$target" 'BEGIN {print (e <= t) ? 1 : 0}')
      if ((ok)) || ((k >= halvings)); then
        printf "%6d  %-7s %11.4g  %10s  %10s  %10s  %10.4g%s\n" "$n" "$ts" "$dt" "$err" "$su" "$st" "$(awk -v a="$su" -v b="$st" 'BEGIN {print a + b}')" "$( ((ok)) || echo "  (target not reached)")"
        break
      fi
    done
  done
done
echo "(target: |ACOR error| <= $target, rk4's at N = the first grid; set-up includes -ts_type modal's decomposition)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
