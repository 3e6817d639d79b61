#!/usr/bin/env bash
# The fast part of the stability study (issue 5, docs/stability.md) through the real executable:
#   * no diagnostic fires on the default scene (options/impact.opts, energy monitor on), and the
#     explicit stability limit is printed before the run (with rk4.opts: the scene is modal); the summary counts rejected steps and
#     failed solves;
#   * every diagnostic fires where it must: a held impact point, a fixed explicit step above
#     dt_max, an RK type unstable on the imaginary axis, a step or a tolerance that cannot
#     resolve the contact (warnings), the energy monitor (adaptive explicit at a loose
#     tolerance; ARKIMEX with a very stiff ball), a failed Newton solve as a sentence (and the
#     round-off stall of alpha2 on a fine grid), a missed maximum compression after a hysteretic
#     reload, too many contacts (physical, or from an unstable run); never a NaN in a message;
#   * the heavy ball on the rigid beam gives the negative ACOR of Eq. (11); the double- and
#     triple-impact cases count their contacts; fixed RK4 just below dt_max is right;
#   * a slice of scripts/stability_matrix.py (when Debian's python with h5py is there).
#
#   tests/stability_subset.sh path/to/beamimpact scratch_dir
set -uo pipefail

exe=${1:?usage: stability_subset.sh beamimpact scratch_dir}
dir=${2:?usage: stability_subset.sh beamimpact scratch_dir}
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe=$(readlink -f "$exe")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" || exit 1
dir=$(readlink -f "$dir")
cd "$src" || exit 1 # options files name their bases relative to the repository root
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" # MPI env, fail/pass, $python


# The paper's beam and superball, explicitly (independent of the options files).
BEAM="-beam_length 1.1 -beam_youngs_modulus 7e10 -beam_density 2700 -beam_thickness 0.006 -beam_width 0.032 -beam_nodes 41"
BALL="-ball_mass 0.042 -ball_speed 1 -ball_law linear -ball_k 2e4"

out="" rc=0
# run ARGS...: runs one impact, keeps stdout+stderr in $out and the status in $rc.
run() {
  out=$(timeout 120 "$exe" -task impact "$@" 2>&1)
  rc=$?
}
# field NAME: a number from the summary line ("acor 0.59 ... contacts 1").
field() { sed -n "s/.*  $1 \([^ ]*\).*/\1/p" <<<"$out" | tail -1; }
no_nan() { if grep -qiw -e nan -e inf <<<"$out"; then fail "$1: output mentions NaN/Inf: $out"; fi; }
# expect_error NAME REGEX ARGS...: nonzero exit with a message matching REGEX, no NaN.
expect_error() {
  local name=$1 re=$2
  shift 2
  run "$@" -output none
  no_nan "$name"
  if [[ $rc -eq 0 ]]; then fail "$name: accepted (must stop with /$re/): $out"
  elif [[ $rc -ge 124 ]]; then fail "$name: timed out or crashed (status $rc): $out"
  elif grep -Eq "beamimpact: error: .*$re" <<<"$out"; then pass "$name: stops with /$re/"
  else fail "$name: message does not match /$re/: $out"; fi
}
# close A B TOL: |A - B| <= TOL
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

# --- the default scene: nothing fires ------------------------------------------------------
run -options_file options/impact.opts -impact_energy_check -output none
no_nan "default scene"
if [[ $rc -ne 0 ]]; then fail "default scene: exit $rc: $out"
elif grep -q "WARNING" <<<"$out"; then fail "default scene: a warning fired: $out"
else pass "default scene: no warning, no error with the energy monitor on"; fi
# the default scene is -ts_type modal (no stability limit); with the former default, rk4, the
# explicit limit is printed before the run
run -options_file options/impact.opts -options_file options/integrators/rk4.opts -impact_energy_check -output none
lim=$(grep -n "explicit stability limit dt_max" <<<"$out" | cut -d: -f1)
sum=$(grep -n "  acor " <<<"$out" | cut -d: -f1)
if [[ -n "$lim" && -n "$sum" && $lim -lt $sum ]]; then pass "default scene with rk4: dt_max printed before the run"; else fail "default scene with rk4: no dt_max line before the summary: $out"; fi
if grep -Eq "  rejected [0-9]+  failed [0-9]+ " <<<"$out"; then pass "summary counts rejected steps and failed solves"; else fail "summary without rejected/failed counts: $out"; fi
acor_default=$(field acor)
run $BEAM $BALL -impact_x 0.55 -reference modal -output none
if close "$acor_default" "$(field acor)" 1e-3; then pass "default scene: ACOR $acor_default matches the modal reference $(field acor)"; else fail "default scene: ACOR $acor_default vs modal $(field acor)"; fi

# --- refusals before the run -----------------------------------------------------------------
expect_error "impact on the pinned end" "that point is held fixed" $BEAM $BALL -beam_right pinned -impact_x 1.1
expect_error "impact inside -beam_clamp" "that point is held fixed" $BEAM $BALL -beam_clamp 0.9,1.1 -impact_x 1.0
expect_error "fixed RK4 step above dt_max" "above the stability limit dt_max = [0-9.e+-]+ s of -ts_type rk -ts_rk_type 4" \
  $BEAM $BALL -beam_nodes 201 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2.5e-6
expect_error "RK type unstable on the imaginary axis" "unstable for an undamped oscillation" $BEAM $BALL -ts_type rk -ts_rk_type 2a -ts_adapt_type none

# Fixed RK4 just below the limit runs and is right (N = 201: dt_max = 2.425e-6 s).
run $BEAM $BALL -beam_nodes 201 -impact_window 3e-3 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2.37e-6 -impact_energy_check -output none
a=$(field acor)
run $BEAM $BALL -beam_nodes 201 -impact_window 3e-3 -reference modal -output none
if [[ -n "$a" ]] && close "$a" "$(field acor)" 1e-3; then pass "fixed RK4 at 0.98 dt_max: ACOR $a matches the modal reference"; else fail "fixed RK4 at 0.98 dt_max: ACOR '$a' vs $(field acor)"; fi

# --- warnings: the step or the tolerance cannot resolve the contact ---------------------------
run $BEAM $BALL -ts_type cn -ts_dt 1e-4 -output none
if [[ $rc -eq 0 ]] && grep -Eq "WARNING: fixed step -ts_dt 0.0001 s resolves the contact time scale .* with only [0-9]+ steps" <<<"$out"; then pass "warning: under 100 steps per contact"; else fail "no under-resolution warning for -ts_dt 1e-4: $out"; fi
run $BEAM $BALL -ts_type cn -ts_dt 1e-3 -output none
if grep -q "WARNING: fixed step -ts_dt 0.001 s is more than 1/8 of the contact time" <<<"$out"; then pass "warning: step above T_c/8"; else fail "no T_c/8 warning for -ts_dt 1e-3: $out"; fi
run $BEAM $BALL -ts_type bdf -ts_bdf_order 2 -output none
if grep -q "WARNING: adaptive step with -ts_rtol 0.0001 -ts_atol 0.0001 cannot resolve the contact" <<<"$out"; then pass "warning: PETSc's default tolerances"; else fail "no tolerance warning for adaptive bdf at default tolerances: $out"; fi
run $BEAM $BALL -options_file options/integrators/rk5dp.opts -output none
if [[ $rc -eq 0 ]] && ! grep -q WARNING <<<"$out"; then pass "no warning for rk 5dp at the advertised tolerances"; else fail "rk5dp.opts: $out"; fi

# --- the energy monitor during the run --------------------------------------------------------
expect_error "energy monitor: adaptive RK 5dp at -ts_rtol 1e-2" \
  "energy grew by [0-9.e+-]+ of the incident kinetic energy at t = .*-ts_type rk -ts_rk_type 5dp.*likely cause: the error controller let the step reach the explicit stability limit" \
  $BEAM $BALL -impact_x 0.9 -ts_type rk -ts_rk_type 5dp -ts_rtol 1e-2 -impact_energy_check
expect_error "energy monitor: adaptive ARKIMEX, ball k = 1e8" "energy grew by .*-ts_type arkimex.*treats the contact force explicitly" \
  $BEAM -ball_mass 0.042 -ball_speed 1 -ball_law linear -ball_k 1e8 -impact_x 0.9 -ts_type arkimex -impact_energy_check
run $BEAM $BALL -impact_x 0.9 -ts_type cn -ts_dt 1.14e-5 -impact_energy_check -impact_window 0.2 -output none
if [[ $rc -eq 0 ]]; then pass "energy monitor silent for cn over 0.2 s"; else fail "energy monitor fired for cn: $out"; fi

# --- after the run: failures as sentences -------------------------------------------------------
expect_error "failed Newton solve" "the nonlinear \(Newton\) solve failed \(SNES DIVERGED_[A-Z_]+ after [0-9]+ iterations, residual norm" \
  $BEAM $BALL -ts_type cn -ts_dt 1e-5 -ksp_type richardson -ksp_max_it 1 -pc_type jacobi -snes_max_it 3
# alpha2 on N = 201: either right, or the Newton round-off diagnosis (a known limitation).
run $BEAM $BALL -beam_nodes 201 -impact_window 3e-3 -ts_type alpha2 -ts_alpha_radius 0.8 -ts_dt 1.1e-5 -output none
no_nan "alpha2 N = 201"
if [[ $rc -eq 0 ]] && close "$(field acor)" "$a" 1e-3; then pass "alpha2 on N = 201 is right"
elif [[ $rc -eq 1 ]] && grep -q "the Newton iteration stalled at a residual norm of .* round-off level .* set -snes_atol" <<<"$out"; then pass "alpha2 on N = 201: Newton round-off diagnosis"
else fail "alpha2 on N = 201: neither right nor diagnosed: $out"; fi
# The hysteretic baseball at 40 m/s reloads during unloading; at this step the maximum compression
# right after the reload is missed (a known defect): either right, or refused with that diagnosis.
# Right is -0.219907 since the reload climbs the unloading curve (issue 23; cn at half this step and
# rk4 at 1e-7 s agree to 6 digits); -0.214664 was the old rule's, which jumped to the loading branch.
run -beam_length 1.1 -beam_nodes 41 -ball_law hysteresis -ball_mass 0.145 -ball_speed 40 -ball_k1 1.5e6 -ball_n 7 -impact_x 0.9 \
    -impact_window 1e-3 -ts_type cn -ts_dt 2.45437e-7 -output none
no_nan "reload"
if [[ $rc -eq 0 ]] && close "$(field acor)" -0.219907 1e-3; then pass "hysteretic reload: ACOR $(field acor) is right"
elif [[ $rc -eq 1 ]] && grep -q "while the hysteretic law was still in its loading branch: the maximum-compression event was missed after the reload" <<<"$out"; then
  pass "hysteretic reload: the missed maximum compression is refused, not reported as a number"
else fail "hysteretic reload: neither right nor diagnosed: $out"; fi
expect_error "too many contacts (the double impact with -impact_max_contacts 1)" "more than -impact_max_contacts 1 separate contacts" \
  $BEAM $BALL -beam_length 0.3 -beam_left clamped -impact_x 0.29 -ts_type cn -ts_dt 1e-5 -impact_max_contacts 1
expect_error "chatter from an unstable integration is not called physical" "more than -impact_max_contacts 50 separate contacts .*energy has grown .*not a physical chatter" \
  $BEAM $BALL -impact_x 0.9 -ts_type rk -ts_rk_type 5dp -ts_rtol 1e-1 -ts_atol 1e-1 -impact_after time

# --- physics: rigid limit, heavy ball, double and triple impacts ------------------------------------
for ts in "-ts_type cn -ts_dt 1.14e-5" "-ts_type rk -ts_rk_type 4 -ts_adapt_type none"; do
  run $BEAM -beam_youngs_modulus 7e14 -ball_mass 5 -ball_speed 1 -ball_law linear -ball_k 2e4 -impact_x 0.9 $ts -impact_energy_check -output none
  a=$(field acor)
  # Eq. (11), f = 0: M = 0.570 kg, I = M L^2/12, b = 0.35 m.
  e=$(awk 'BEGIN { M = 1.1*2700*0.006*0.032; b = 0.35; Me = M/(1 + 12*b*b/(1.1*1.1)); R = 5/Me; printf "%.8f", (1-R)/(1+R) }')
  if [[ $rc -eq 0 ]] && awk -v a="$a" 'BEGIN { exit !(a < 0) }' && close "$a" "$e" 1e-3; then pass "heavy ball, rigid beam ($ts): ACOR $a, Eq. (11) $e"
  else fail "heavy ball, rigid beam ($ts): ACOR '$a' vs Eq. (11) $e: $out"; fi
done
run $BEAM $BALL -beam_length 0.3 -beam_left clamped -impact_x 0.29 -ts_type cn -ts_dt 1e-5 -impact_energy_check -output none
if [[ $rc -eq 0 && "$(field contacts)" == 2 ]]; then pass "double impact: 2 contacts"; else fail "double impact: contacts '$(field contacts)': $out"; fi
run $BEAM $BALL -beam_length 0.3 -beam_left clamped -ball_mass 0.1 -impact_x 0.295 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -impact_energy_check -output none
if [[ $rc -eq 0 && "$(field contacts)" == 3 ]]; then pass "triple impact: 3 contacts"; else fail "triple impact: contacts '$(field contacts)': $out"; fi

# --- a slice of the study script -------------------------------------------------------------------
if [[ -n "$python" ]]; then
  log=$("$python" "$src/scripts/stability_matrix.py" --exe "$exe" --jobs 2 --quiet --cases default,heavy-rigid,pinned-point,dt-above \
        --integrators rk4,cn,rosw --h5 "$dir/slice.h5" --md "$dir/slice.md" --workdir "$dir/slice" 2>&1)
  rc=$?
  if [[ $rc -eq 0 ]] && grep -q "12 cells: 8 correct, 4 clear error, 0 wrong, 0 unverified" <<<"$log" && grep -q "| \`dt-above\`" "$dir/slice.md"; then
    pass "stability_matrix.py slice: $(tail -1 <<<"$log" | cut -c1-80)"
  else fail "stability_matrix.py slice: $log"; fi
else
  echo "skip: stability_matrix.py slice (no python with numpy and h5py)"
fi

if [[ $fails -gt 0 ]]; then echo "$fails check(s) failed"; exit 1; fi
echo "all stability checks passed"
