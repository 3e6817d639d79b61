#!/usr/bin/env bash
# After separation, exact free vibration (-impact_after modal, the default) against time
# integration (-impact_after time), through the real executable (issue 12): the same contact
# counts, and the same final ACOR to the integrator's accuracy, on
#   * the 1.1 m paper sweeps (options/scenes/acor-6mm.opts), free-free and clamped at x = 0,
#     in short form (points near the ends, where the beam can catch the ball again);
#   * the 30 cm beam clamped at x = 0, struck at 29 cm: the second contact is found;
#   * the racket scenes: free, pinned handle, clamped 62-72 cm (sweeps), snapshots, energy
#     (segment peak);
#   * the profile bat R161 with the baseball at 40 m/s at 0.7 m, Euler-Bernoulli and Timoshenko;
#   * a damped beam (Rayleigh), and 2 ranks; the printed fallback where modal is not possible.
# The ACOR is the ball's speed after its last contact: when there is only one, it is the same
# number on both paths (the free flight does not change it); after a re-contact the two differ
# by the integrator's error over the free flight (set per case below).
#
#   tests/after_modal.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: after_modal.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: after_modal.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
exe=$(readlink -f "$exe")
mkdir -p "$dir" && dir=$(readlink -f "$dir")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[[ -n $python ]] || { echo "FAIL: no python3 with h5py and numpy"; exit 1; }
rm -f "$dir"/*.h5 "$dir"/*.log

# same NAME TOL NP OPTIONS...: runs time and modal, compares contacts (equal) and ACOR (within TOL).
same() {
  local name=$1 tol=$2 np=$3; shift 3
  local a ok=1
  for a in time modal; do
    local cmd=("$exe" "$@" -impact_after "$a" -output "$dir/$name-$a.h5")
    [[ $np -gt 1 ]] && cmd=("$mpiexec" -n "$np" "${cmd[@]}")
    if ! "${cmd[@]}" >"$dir/$name-$a.log" 2>&1; then
      fail "$name ($a): ${cmd[*]}"; tail -3 "$dir/$name-$a.log" | sed 's/^/      /'; ok=0
    fi
  done
  [[ $ok == 1 ]] || return
  local msg
  if msg=$("$python" - "$dir/$name-time.h5" "$dir/$name-modal.h5" "$tol" <<'PY'
import sys, h5py, numpy as np
a, b = (h5py.File(f, "r") for f in sys.argv[1:3]); tol = float(sys.argv[3])
ra, rb = a["results"], b["results"]
ca, cb = np.asarray(ra["contacts"]), np.asarray(rb["contacts"])
da = np.max(np.abs(np.asarray(ra["acor"]) - np.asarray(rb["acor"])))
wa, wb = np.sum(ra["wall_time"]), np.sum(rb["wall_time"])
txt = f"contacts {','.join(str(int(c)) for c in cb)}; max |acor diff| {da:.2e} (tol {tol:g}); wall {wa:.3g} s -> {wb:.3g} s"
if not np.array_equal(ca, cb): print("contacts differ: time " + ",".join(str(int(c)) for c in ca) + " modal " + txt); sys.exit(1)
if not da <= tol: print(txt); sys.exit(1)
print(txt)
PY
  ); then pass "$name: $msg"; else fail "$name: $msg"; fi
}

S6=options/scenes/acor-6mm.opts
same free-1.1 1e-9 1 -options_file $S6 -sweep_x 0.02,0.1,0.55,1.0,1.06,1.09 -sweep_quiet
same clamped-1.1 1e-6 1 -options_file $S6 -beam_left clamped -sweep_x 0.1,0.55,1.0,1.06,1.09 -sweep_quiet
same clamped-1.1-np2 1e-6 2 -options_file $S6 -beam_left clamped -sweep_x 1.06,1.09 -sweep_quiet
same double-0.3 1e-5 1 -options_file options/base/aluminium-6mm.opts -options_file options/base/superball-linear.opts \
  -beam_length 0.3 -beam_left clamped -impact_x 0.29 -ts_type cn -ts_dt 5e-6
same racket-free 1e-6 1 -options_file options/scenes/racket-acor.opts -sweep_x 0.02,0.2,0.3,0.5 -sweep_quiet
same racket-pinned 1e-6 1 -options_file options/scenes/racket-acor.opts -beam_right pinned -sweep_x 0.02,0.3 -sweep_quiet
same racket-clamped 1e-6 1 -options_file options/scenes/racket-acor.opts -beam_clamp 0.62,0.72 -sweep_x 0.02,0.3 -sweep_quiet
same racket-snapshots 1e-6 1 -options_file options/scenes/racket-snapshots.opts
same racket-energy 1e-6 1 -options_file options/scenes/racket-energy.opts
same r161-eb 1e-6 1 -options_file options/bats/r161.opts -options_file options/balls/baseball.opts -impact_x 0.7 -ball_speed 40 -task impact
same r161-timoshenko 1e-6 1 -options_file options/bats/r161.opts -options_file options/balls/baseball.opts -impact_x 0.7 -ball_speed 40 -task impact -beam_theory timoshenko
same damped-0.3 1e-5 1 -options_file options/base/aluminium-6mm.opts -options_file options/base/superball-linear.opts \
  -beam_length 0.3 -beam_left clamped -impact_x 0.29 -ts_type cn -ts_dt 5e-6 -beam_damping_mass 2 -beam_damping_stiffness 1e-6

# The outputs keep their shape: the snapshots of the pinned racket agree to the integrator's accuracy.
if msg=$("$python" - "$dir/racket-snapshots-time.h5" "$dir/racket-snapshots-modal.h5" <<'PY'
import sys, h5py, numpy as np
a, b = (np.asarray(h5py.File(f, "r")["snapshots/y"]) for f in sys.argv[1:3])
if a.shape != b.shape: print(f"shapes {a.shape} {b.shape}"); sys.exit(1)
d = np.max(np.abs(a - b)) / np.max(np.abs(a))
print(f"shape {a.shape}, max difference {d:.2e} of the largest deflection"); sys.exit(0 if d < 1e-4 else 1)
PY
); then pass "racket-snapshots: $msg"; else fail "racket-snapshots: $msg"; fi

# With -impact_after modal the free flight is not stepped: far fewer steps than time.
st=$("$python" -c "import h5py,sys; print(int(sum(h5py.File(sys.argv[1])['results']['steps'])), int(sum(h5py.File(sys.argv[2])['results']['steps'])))" "$dir/clamped-1.1-time.h5" "$dir/clamped-1.1-modal.h5")
read -r s_time s_modal <<<"$st"
if [[ $s_modal -lt $((s_time / 5)) ]]; then pass "clamped sweep: $s_modal steps with modal against $s_time with time"
else fail "clamped sweep: $s_modal steps with modal against $s_time with time (expected < 1/5)"; fi

# Where the beam does not allow it (beyond the dense decomposition's size) the default falls
# back to time integration and says why (given explicitly: an error, tests/cli_bad_input.cmake).
out=$("$exe" -grip 0.1,0.2 -grip_stiffness 1e4 -grip_damping 10 -ts_type cn -ts_dt 1e-5 -impact_max_time 2e-5 -output none 2>&1)
if grep -q "note: the free vibration after separation is integrated in time (-impact_after time): the beam is held by the hands" <<<"$out"; then
  pass "fallback to time integration is printed with its reason"
else fail "fallback to time integration: no reason printed: $out"; fi
# No size limit (issue 21): beyond 3000 free dofs the modes are truncated, not refused.
out=$("$exe" -beam_nodes 3100 -ts_type cn -ts_dt 1e-5 -impact_max_time 2e-5 -output none 2>&1)
if grep -q "integrated in time" <<<"$out"; then fail "N = 3100 fell back to time integration: $out"
else pass "no fallback at N = 3100"; fi

[[ $fails -eq 0 ]] && echo "all after-separation checks passed" || echo "$fails check(s) failed"
exit $((fails > 0))
