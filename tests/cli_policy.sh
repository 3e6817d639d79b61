#!/usr/bin/env bash
# What a newcomer or a PETSc user runs into first, through the real executable:
#   * -help lists the options of every task (sweep, convergence, swinging bat, PETSc's TS) and
#     exits 0 without running or writing anything;
#   * a scene composes with a later -ts_type: the scene's leftover -ts_rk_type is a one-line
#     note, not an error (an unknown option of the program's own stays an error);
#   * -output: an empty name, a missing directory, and a file another task wrote are refused
#     before any work (the last unless -output_overwrite);
#   * -ts_monitor and -ts_view work (the driver steps the TS itself); -ts_max_steps and
#     -ts_max_time, which it cannot honour, are refused naming -impact_max_time;
#   * a missing -options_file (also one included by another file) is one plain line, no
#     PETSc traceback, no MPI abort;
#   * every results file records its provenance: task, git, date, host, ranks, library versions,
#     and every option read, as used, with its unit (/options_used).
#   * -log_view lists the program's stages (set-up, contact, free flight, output);
#   * a sweep whose runs -impact_max_time cuts off in contact gives failed rows (status 7);
#   * a sweep's h^2 note is a whole point's, not its 1 ns set-up probe's;
#   * a run expected to take long prints its cost first (-impact_cost_warn), progress lines
#     (-impact_progress), -ts_type modal's modes too, and a sweep of more than 1e6 points
#     announces its set-up cost; a sweep whose remaining points are expected to take longer
#     than -impact_cost_warn says so once;
#   * -modal_tolerance under a stepped integrator acts (the free flight's modes): no note;
#     -modal_modes is noted unused exactly where no consumer of the modes runs (a table of cases);
#   * the barrel wall: a displacement beyond a quarter of its radius flagged, a thick wall noted.
#   * the oblique impact's tangential options on a head-on hit, or without friction, and the
#     error tolerances under a fixed step are notes, the numbers unchanged (issue 34).
#
#   tests/cli_policy.sh path/to/beamimpact scratch_dir
set -uo pipefail
exe=${1:?usage: cli_policy.sh beamimpact scratch_dir}
dir=${2:?usage: cli_policy.sh beamimpact scratch_dir}
source "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.." || exit 2
rm -rf "$dir" && mkdir -p "$dir"

# -help
out=$(cd "$dir" && "$exe" -help 2>&1); rc=$?
if [[ $rc -eq 0 && ! -e $dir/impact.h5 ]]; then pass "-help exits 0 and writes nothing"; else fail "-help: exit $rc, files: $(ls "$dir")"; fi
for opt in -task -beam_profile -beam_theory -ball_cor_table -bat_speed -impact_after -monitor_velocity_at -modes_count -sweep -sweep_retry_failed -convergence_configs -leapfrog_dt -ts_type -ts_rk_type -ts_modal_order -output_overwrite -allow_unused_options -error_traceback; do
  grep -q -- "$opt\b" <<<"$out" || fail "-help does not list $opt"
done
bad=$(grep -E "^  -(beam|ball|bat|impact|monitor|snapshot|modes|sweep|convergence|leapfrog|grip|reference|task|output)[a-z_]* <" <<<"$out" | grep -E "<[^>]*e[+-][0-9]{3}|nan|inf" | grep -v "beam_length <inf\|1e+30")
[[ -z $bad ]] && pass "-help shows no uninitialised or absurd defaults for the program's options" || fail "-help defaults: $bad"
grep -q -- "-ts_type <now rk" <<<"$out" && pass "-help lists every task's options, PETSc's TS from the program's default rk" || fail "-help shows a TS default other than rk"

# a scene with a later -ts_type (the default scene is -ts_type modal: rk4's file adds a
# -ts_rk_type that cn leaves over)
out=$("$exe" -options_file options/impact.opts -ts_type cn -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "^ts cn " <<<"$out" && ! grep -q "note: .*not used" <<<"$out"; then
  pass "options/impact.opts -ts_type cn runs cn, nothing left over"
else fail "options/impact.opts -ts_type cn: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -options_file options/integrators/rk4.opts -ts_type cn -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "note: 1 PETSc solver option(s) set but not used by this integrator: -ts_rk_type 4" <<<"$out"; then
  pass "options/impact.opts with rk4.opts and -ts_type cn runs, the leftover -ts_rk_type is a note"
else fail "options/impact.opts rk4.opts -ts_type cn: exit $rc: $out"; fi
# a solver's viewers are read at each solve, after the set-up's check: they act under an
# implicit integrator (no note) and are leftovers under an explicit one
out=$("$exe" -options_file options/impact.opts -ts_type cn -ksp_converged_reason -snes_converged_reason -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "Linear solve converged" <<<"$out" && grep -q "Nonlinear solve converged" <<<"$out" && ! grep -q "note: .*not used" <<<"$out"; then
  pass "-ksp_converged_reason and -snes_converged_reason under cn act and are not called unused"
else fail "cn -ksp_converged_reason: exit $rc: $(grep -v 'solve converged' <<<"$out")"; fi
out=$("$exe" -options_file options/impact.opts -ts_type rk -ts_rk_type 4 -ksp_converged_reason -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "note: 1 PETSc solver option(s) set but not used by this integrator: -ksp_converged_reason" <<<"$out"; then
  pass "-ksp_converged_reason under rk4 (no linear solve) is a leftover note"
else fail "rk4 -ksp_converged_reason: exit $rc: $out"; fi
# the program's own LU reads -pc_factor_mat_solver_type at its first solve, after the set-up's
# check: under cn it acts, and is not called unused
out=$("$exe" -options_file options/impact.opts -ts_type cn -pc_factor_mat_solver_type superlu -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "^ts cn " <<<"$out" && ! grep -q "note: .*not used" <<<"$out"; then
  pass "-pc_factor_mat_solver_type under cn acts and is not called unused"
else fail "cn -pc_factor_mat_solver_type: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -beam_thicknes 0.01 -output none 2>&1); rc=$?
if [[ $rc -ne 0 ]] && grep -q "option(s) unknown (set but read by no task): -beam_thicknes 0.01 (did you mean -beam_thickness?)" <<<"$out" && ! grep -q "^x " <<<"$out"; then
  pass "a misspelt program option is an error before the run, suggesting the closest known option"
else fail "-beam_thicknes: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -ball_spede 2 -impactx 0.3 -no_such_thing 1 -output none 2>&1); rc=$?
if [[ $rc -ne 0 ]] && grep -q -- "-ball_spede 2 (did you mean -ball_speed?)" <<<"$out" && grep -q -- "-impactx 0.3 (did you mean -impact_x?)" <<<"$out" &&
   grep -q -- "-no_such_thing 1\( -\|$\)" <<<"$out" && ! grep -q "no_such_thing 1 (did you mean" <<<"$out"; then
  pass "each unknown option gets its own suggestion, none when nothing is close"
else fail "unknown options: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -sweep_x 0:1:3 -modes_count 3 -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "note: 2 option(s) set but not used by this task: -modes_count 3 -sweep_x 0:1:3" <<<"$out" && grep -q "^x " <<<"$out"; then
  pass "known options another task reads are a one-line note under -task impact"
else fail "known unused options: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -beam_thicknes 0.01 -allow_unused_options -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "WARNING: 1 option(s) unknown.*-beam_thicknes 0.01 (did you mean -beam_thickness?)" <<<"$out" && pass "-allow_unused_options makes it a warning" || fail "-allow_unused_options: exit $rc: $out"

# options files: includes and file paths inside a file are relative to that file, so a scene
# runs from any directory (r161-modes.opts includes ../bats/r161.opts, which names r161.profile)
src=$(pwd)
out=$(cd "$dir" && "$exe" -options_file "$src/options/scenes/r161-modes.opts" -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "profile section $src/options/bats/r161.profile" <<<"$out" && grep -q "^ *r2 *0.0000 .*(rigid)" <<<"$out" && grep -q "^ *1 *174\.[0-9]* " <<<"$out"; then
  pass "a scene runs from another directory: its includes and profile are found next to the files"
else fail "scene from another directory: exit $rc: $out"; fi
out=$(cd "$dir" && PETSC_OPTIONS="-options_file $src/options/scenes/r161-modes.opts" "$exe" -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "profile section $src/options/bats/r161.profile" <<<"$out" && pass "an -options_file in PETSC_OPTIONS resolves its paths alike" || fail "PETSC_OPTIONS -options_file: exit $rc: $out"
out=$("$exe" -options_file options/impact.opts -options_left -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "There are no unused options" <<<"$out" && pass "-options_left (read at finalize) is not reported as unused" || fail "-options_left: exit $rc: $out"
mkdir -p "$dir/inc/sub"
printf -- "-options_file sub/ball.opts # an include next to this file\n-beam_nodes 21\n" >"$dir/inc/scene.opts"
printf -- "-ball_law hysteresis\n-ball_m 1.5\n-ball_contact_time 1e-3\n-ball_test_speed 3\n-ball_cor_table ../cor.txt\n" >"$dir/inc/sub/ball.opts"
printf -- "0.5 0.8\n5 0.7\n" >"$dir/inc/cor.txt"
out=$("$exe" -options_file "$dir/inc/scene.opts" -ball_cor 0.7 -output none 2>&1); rc=$?
grep -q -- "-ball_cor_table" <<<"$out" && ! grep -q "cannot open\|cannot read" <<<"$out" && pass "a path option two files down resolves next to its file" || fail "nested path option: exit $rc: $out"

# PETSc's own habits: monitors and viewers work, options the driver cannot honour are refused
out=$("$exe" -options_file options/impact.opts -impact_window 0 -ts_monitor -ts_view -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "^1 TS dt" <<<"$out" && grep -q "TS Object" <<<"$out" && pass "-ts_monitor and -ts_view print" || fail "-ts_monitor/-ts_view: exit $rc"
for o in "-ts_max_steps 100" "-ts_max_time 1e-3"; do
  out=$("$exe" -options_file options/impact.opts $o -output none 2>&1); rc=$?
  [[ $rc -ne 0 ]] && grep -q -- "${o%% *} is not used here: .* use -impact_max_time" <<<"$out" && pass "$o refused, naming what to use" || fail "$o: exit $rc: $out"
done

# snapshots: times after the run's end are named in a note; /events holds NaN where a quantity
# does not apply (the approach speed except at contact starts, e and n for the linear law)
out=$("$exe" -options_file options/impact.opts -snapshot_times 0.002,0.001,5,7 -output "$dir/snap.h5" 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "^note: 2 of the -snapshot_times (5.000000, 7.000000) are after the run's end at t = [0-9.e-]* s and were not recorded" <<<"$out" \
  && pass "-snapshot_times after the run's end: a note names them" || fail "late snapshot times: exit $rc: $out"
if [[ -n $python ]]; then
  ev=$("$python" -c "
import h5py, numpy as np, sys
f = h5py.File(sys.argv[1]); e = f['events']; k = e['kind'][()]
ok = e['kind'].dtype.kind == 'i' and np.all(np.isnan(e['approach_speed'][()][k != 0])) and np.all(e['approach_speed'][()][k == 0] == 1.0) \
     and np.all(np.isnan(e['cor'][()])) and np.all(np.isnan(e['n'][()])) and list(f['snapshots/time'][()]) == [0.001, 0.002]
print('ok' if ok else 'bad: kind %s speed %s cor %s n %s t %s' % (k, e['approach_speed'][()], e['cor'][()], e['n'][()], f['snapshots/time'][()]))" "$dir/snap.h5")
  [[ $ev == ok ]] && pass "/events: integer kinds, NaN where a quantity does not apply; snapshots sorted" || fail "/events of a linear-spring impact: $ev"
fi

# -output
out=$("$exe" -output "" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "-output needs a file name" <<<"$out" && pass "-output '' refused" || fail "-output '': exit $rc: $out"
out=$("$exe" -output "$dir/no/such/dir/x.h5" -impact_x 0.5 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "the directory $dir/no/such/dir does not exist or is not writable" <<<"$out" && ! grep -q "^x " <<<"$out" && pass "-output into a missing directory refused before any work" || fail "missing directory: exit $rc: $out"
mkdir -p "$dir/adir"
for task in impact sweep; do
  out=$("$exe" -task $task -sweep_x 0.5 -output "$dir/adir" 2>&1); rc=$?
  [[ $rc -ne 0 ]] && grep -q -- "-output $dir/adir is not allowed: it is a directory; give a file name" <<<"$out" && ! grep -q "^x \|HDF5-DIAG\|MPI_ABORT" <<<"$out" && ! ls "$dir"/adir.* >/dev/null 2>&1 \
    && pass "-task $task -output DIRECTORY refused before any work, nothing left" || fail "-task $task -output a directory: exit $rc: $out"
done
"$exe" -task sweep -sweep_x 0.5,0.6 -sweep_quiet -output "$dir/sweep.h5" >/dev/null 2>&1 || fail "the sweep for the overwrite test did not run"
out=$("$exe" -output "$dir/sweep.h5" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "holds the results of -task sweep: -task impact will not replace them" <<<"$out" && pass "-task impact does not overwrite a sweep's file" || fail "overwrite: exit $rc: $out"
"$exe" -output "$dir/sweep.h5" -output_overwrite >/dev/null 2>&1 && pass "-output_overwrite lets it" || fail "-output_overwrite refused"
"$exe" -output "$dir/sweep.h5" >/dev/null 2>&1 && pass "an impact file is replaced by the next impact (same task)" || fail "same-task overwrite refused"

# -log_view shows the program's stages (set-up, contact, free flight, output)
out=$("$exe" -options_file options/impact.opts -log_view -output "$dir/logview.h5" 2>&1); rc=$?
miss=""
for st in "beamimpact: set-up" "beamimpact: contact" "beamimpact: free flight" "beamimpact: output"; do
  grep -qE "^ *[0-9]+: +$st:? " <<<"$out" || miss+=" '$st'"
done
[[ $rc -eq 0 && -z $miss ]] && pass "-log_view lists the stages set-up, contact, free flight, output" || fail "-log_view: exit $rc, stages missing:$miss"

# cost: an estimate before a long run, progress lines during it, a huge sweep's set-up announced
# (4001 nodes: the free flight is modal at any size since issue 21, so only the contact is stepped)
out=$(output_until "^cost:" 60 "$exe" -beam_nodes 4001 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 5e-9 -output none)
grep -q "^cost: at least 8.79e+05 steps (0.00439 s stepped / dt 5e-09 s, -ts_dt) on 4001 nodes: expected [0-9.e+]* s of wall time .*to shorten it: a larger -ts_dt, fewer -beam_nodes.*an implicit -ts_type" <<<"$out" \
  && pass "a long run (4001 nodes, rk4 at 5e-9 s) prints its cost first" || fail "no cost estimate before a long run: $out"
out=$("$exe" -output none 2>&1)
! grep -q "^cost:\|^progress:" <<<"$out" && pass "the default run prints no cost or progress line" || fail "the default run: $out"
out=$(output_until "^cost: -ts_type rk's step" 60 "$exe" -beam_nodes 641 -output none)
grep -q "^cost: -ts_type rk's step is bound by h^2: the stability limit dt_max = [0-9.e-]* s at N = 641 .*-ts_type modal takes this run in ~[0-9.e-]* s at the same accuracy ([0-9]*x faster)" <<<"$out" \
  && pass "rk4's h^2-bound step on 641 nodes is said at set-up, with -ts_type modal's time" || fail "no h^2 note at N = 641: $out"
# a sweep's set-up probe steps 1 ns: the h^2 note quotes a whole point's stepping (it quoted the
# probe's: "at least 2.83e-09 s"), at least the contact time over the stability limit's steps
# and within a factor 100 of what a point measures
out=$("$exe" -options_file options/scenes/acor-6mm.opts -sweep_x 0.3,0.5 -ts_type rk -ts_rk_type 4 -beam_nodes 201 -output "$dir/probe_cost.h5" 2>&1)
at_least=$(sed -nE "s/^cost: -ts_type rk's step is bound by h\^2: .*: at least ([0-9.e+-]+) s of stepping a point; -ts_type modal takes each point in .*/\1/p" <<<"$out")
per=$(sed -nE 's/^sweep: per point: compute ([0-9.e+-]+) ms.*/\1/p' <<<"$out")
if [[ -n $at_least && -n $per ]] && awk -v a="$at_least" -v p="$per" 'BEGIN { exit !(a > 1e-4 && a < 100 * p / 1e3 && p / 1e3 < 100 * a) }'; then
  pass "a sweep's h^2 note quotes a point's stepping: at least $at_least s, a point measured $per ms"
else fail "sweep cost note: at least '$at_least' s, per point '$per' ms: $(grep -E '^cost|per point' <<<"$out")"; fi
out=$("$exe" -impact_cost_warn 1e-9 -impact_progress 1e-9 -output none 2>&1)
grep -q "^cost: at least [0-9.e+]* steps .* the explicit stability limit) on 41 nodes" <<<"$out" && grep -q "^progress: t = [0-9.e-]* s simulated (the run stops by [0-9.e-]* s), [0-9]* steps" <<<"$out" \
  && pass "-impact_cost_warn and -impact_progress set when the cost and progress lines appear" || fail "cost/progress lines: $out"
# -ts_type modal's own modes: -impact_cost_warn and -impact_progress reach its set-up (the cost
# line and progress lines, as the free flight's under cn); progress comes within a restart too
# (per application of the operator), and the converged count never passes the modes wanted
# (Krylov-Schur converges more of its basis: "146 of 108" before)
out=$("$exe" -ts_type modal -beam_nodes 641 -impact_x 0.9 -modal_tolerance 1e-6 -impact_cost_warn 1e-9 -impact_progress 1e-9 -output none 2>&1)
want=$(sed -nE "s/^cost: the beam's modes: a partial eigen-solve of ([0-9]+) modes of 641 free dofs \(SLEPc\).*/\1/p" <<<"$out")
lines=$(grep -E "^beamimpact: the beam's modes: [0-9]+ of ${want:-none} converged after [0-9]+ restarts? \([0-9]+ operator applications?\)" <<<"$out")
over=$(awk -v w="${want:-0}" '$5 > w' <<<"$lines")
if [[ -n $want ]] && grep -q "after 0 restarts" <<<"$lines" && grep -q "^beamimpact: the beam's modes: $want of $want converged" <<<"$lines" && [[ -z $over ]]; then
  pass "-ts_type modal: its modes' cost line and progress (within a restart too, at most $want of $want converged)"
else fail "-ts_type modal's modes: cost/progress: want '$want', over '$over': $(head -c 3000 <<<"$out")"; fi
# -modal_tolerance acts under a stepped integrator (its free flight's modes): no note; a note
# where it does not (-impact_after time)
out=$("$exe" -ts_type cn -beam_nodes 641 -impact_x 0.9 -modal_tolerance 1e-6 -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && ! grep -q "note: .*-modal_tolerance" <<<"$out" && grep -q "modes 100/641 cut-off" <<<"$out"; then
  pass "-ts_type cn -modal_tolerance 1e-6: the free flight keeps 100 of 641 modes, no 'not used' note"
else fail "cn -modal_tolerance: exit $rc: $out"; fi
out=$("$exe" -ts_type cn -beam_nodes 641 -impact_x 0.9 -modal_tolerance 1e-6 -impact_after time -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "note: 1 option(s) set but not used by this task: -modal_tolerance 1e-6" <<<"$out" \
  && pass "-modal_tolerance with -impact_after time (no modes): a note" || fail "cn -impact_after time -modal_tolerance: exit $rc: $out"
# Where the modal engine's options (-modal_modes, -modal_tolerance, -modal_weight) act, and so are
# not noted unused: a consumer of the modes in the run (-ts_type modal, the free flight after the
# separation with -impact_after modal and a window to follow, an oblique hit's second plane, the
# exact -reference modal, a sweep's points). Elsewhere a one-line note. The truncation is read once,
# at the run's set-up (run/impact_problem.cpp): this pins the set of options marked used there.
base=(-options_file options/impact.opts -beam_nodes 41 -output none)
modal_guard() { # expect(noted|quiet) description args...
  local expect=$1 what=$2; shift 2
  local out rc; out=$("$exe" "${base[@]}" "$@" 2>&1); rc=$?
  local noted=quiet; grep -q "note: .*not used.*-modal_modes 8" <<<"$out" && noted=noted
  if [[ $rc -eq ${guard_rc:-0} && $noted == "$expect" ]]; then pass "-modal_modes 8, $what: $expect"
  else fail "-modal_modes 8, $what: exit $rc, expected $expect, got $noted: $out"; fi
}
modal_guard noted "rk head-on, -impact_after time" -ts_type rk -impact_after time -modal_modes 8
modal_guard quiet "rk head-on, -impact_after modal" -ts_type rk -impact_after modal -modal_modes 8
# (the cost note of rk's h^2 step bound reads them after the check; cut off in contact, an error, to be quick)
guard_rc=1 modal_guard noted "rk head-on, -impact_after time, its h^2 cost note" -ts_type rk -impact_after time \
  -beam_nodes 401 -impact_max_time 1e-5 -modal_modes 8
modal_guard noted "rk head-on, -impact_after modal, -impact_window 0" -ts_type rk -impact_window 0 -modal_modes 8
modal_guard quiet "-ts_type modal, -impact_after time" -ts_type modal -impact_after time -modal_modes 8
modal_guard quiet "-ts_type modal, -impact_window 0" -ts_type modal -impact_window 0 -modal_modes 8
base=(-options_file options/scenes/oblique.opts -beam_nodes 41 -flight 0 -output none)
modal_guard quiet "rk oblique, -impact_after time" -ts_type rk -impact_after time -modal_modes 8
modal_guard quiet "rk face-on with spin and friction (-impact_offset 0: still oblique), -impact_after time" -impact_offset 0 \
  -ts_type rk -impact_after time -modal_modes 8
base=(-options_file options/impact.opts -beam_nodes 41 -output none)
# the exact reference reads its truncation before its check of unused options (was after: a
# wrong note for the -modal_modes its 8 modes came from)
modal_guard quiet "-reference modal (modes 8/41)" -reference modal -modal_modes 8
# a sweep checks after its probe point: what the probe's set-up and cost notes read counts (the
# cost note of rk's h^2 step bound estimates -ts_type modal's modes with them: -beam_nodes 401,
# its points cut off in contact by -impact_max_time, status 7, so exit 2, to be quick)
base=(-options_file options/impact.opts -beam_nodes 41 -task sweep -sweep_x 0.5:0.6:2)
sweep_out() { rm -f "$dir/modal_guard.h5"; echo -output "$dir/modal_guard.h5"; }
modal_guard noted "sweep, rk, -impact_after time" $(sweep_out) -ts_type rk -impact_after time -modal_modes 8
modal_guard quiet "sweep, rk, -impact_after modal" $(sweep_out) -ts_type rk -modal_modes 8
modal_guard quiet "sweep, -ts_type modal, -impact_after time" $(sweep_out) -ts_type modal -impact_after time -modal_modes 8
guard_rc=2 modal_guard quiet "sweep, rk, -impact_after time, its h^2 cost note" $(sweep_out) -ts_type rk -impact_after time \
  -beam_nodes 401 -impact_max_time 1e-5 -modal_modes 8
# with -impact_window 0 no point has a free flight: noted, as -task impact notes it (was quiet:
# the probe read the truncation for a free flight that never comes)
modal_guard noted "sweep, rk, -impact_after modal, -impact_window 0" $(sweep_out) -ts_type rk -impact_window 0 -modal_modes 8
out=$(output_until "^sweep: 1000001 points planned" 60 "$exe" -task sweep -sweep_x 0:1.1:1000001 -output "$dir/huge.h5")
grep -q "^sweep: 1000001 points planned: checking every point's options takes about [0-9.e+]* s" <<<"$out" && pass "a sweep of 1e6 points announces its set-up cost" || fail "huge sweep: $out"
rm -rf "$dir/huge.h5" "$dir/huge.h5.parts"
out=$("$exe" -task sweep -sweep_x 0:1.1:1e12 -output "$dir/huge.h5" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "-sweep_x 0:1.1:1e12 is not allowed: count 1e12 of start:stop:count is too large: an axis has at most 1e+08 points" <<<"$out" && pass "-sweep_x 0:1.1:1e12: too many points, said so (not 'a whole number')" || fail "-sweep_x 1e12: exit $rc: $out"
out=$("$exe" -task sweep -sweep_x 0:1.1:2.5 -output "$dir/huge.h5" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "count of start:stop:count must be a whole number >= 1, not '2.5'" <<<"$out" && pass "-sweep_x 0:1.1:2.5 refused: not a whole number" || fail "-sweep_x 2.5: exit $rc: $out"
rm -rf "$dir/huge.h5" "$dir/huge.h5.parts"
out=$("$exe" -task sweep -sweep_x 0:1.1:300 -sweep_progress_interval 0.05 -impact_cost_warn 0.01 -output "$dir/costly.h5" 2>&1)
grep -q "^cost: 300 points to compute at [0-9.e-]* s a point (measured over the first [0-9]*): expected .* more; to shorten it: fewer points" <<<"$out" && [[ $(grep -c "^cost:" <<<"$out") == 1 ]] \
  && pass "a sweep expected to take longer than -impact_cost_warn says so once, measured over its first points" || fail "sweep cost line: $out"
out=$("$exe" -task sweep -sweep_x 0:1.1:300 -sweep_progress_interval 0.05 -sweep_restart -output "$dir/costly.h5" 2>&1)
! grep -q "^cost:" <<<"$out" && pass "a short sweep prints no cost line" || fail "short sweep: $out"
rm -rf "$dir/costly.h5" "$dir/costly.h5.parts"

# a compression beyond the ball's radius is flagged (the presets give the radius)
out=$("$exe" -options_file options/base/superball-linear.opts -ball_speed 1e6 -output "$dir/absurd.h5" 2>&1); rc=$?
flag=$(h5dump -d /results/compression_beyond_radius "$dir/absurd.h5" 2>/dev/null | sed -nE 's/^ *\(0\): *([0-9.]+).*/\1/p')
if [[ $rc -eq 0 ]] && grep -q "^warning: the maximum compression 124[01] m is beyond the ball's radius (-ball_radius 0.018 m" <<<"$out" && [[ $flag == 1* ]]; then
  pass "-ball_speed 1e6: the 1240 m compression is flagged (summary and compression_beyond_radius)"
else fail "-ball_speed 1e6: exit $rc, flag '$flag': $out"; fi
out=$("$exe" -options_file options/base/superball-linear.opts -output none 2>&1)
! grep -q "beyond the ball's radius" <<<"$out" && pass "no flag at 1 m/s" || fail "flag at 1 m/s: $out"

# the barrel wall (issue 34): a displacement under the ball beyond a quarter of the wall's radius is
# flagged like the ball's compression (a hoop of 10 Hz on the aluminium bat lets the baseball push
# its wall in by far more than the 32 mm radius), a wall of 1000 Hz is not; the thin-shell model on
# the corked R161's 19 mm wall is noted (t/R above 0.1), on the aluminium bat's 2.5 mm it is not
out=$("$exe" -options_file options/bats/aluminium-bat.opts -options_file options/balls/baseball.opts -beam_nodes 41 -impact_x 0.66 -barrel_hoop_frequency 10 -barrel_hoop_mass 0.27 -ts_type modal -output "$dir/wall.h5" 2>&1); rc=$?
flag=$(h5dump -d /results/wall_deflection_large "$dir/wall.h5" 2>/dev/null | sed -nE 's/^ *\(0\): *([0-9.]+).*/\1/p')
if [[ $rc -eq 0 ]] && grep -q "^warning: the barrel wall's largest displacement under the ball, [0-9.]* m, is [0-9.]* times its midsurface radius (R = 0.0321 m at x = 0.66 m), beyond 0.25 of it: physically absurd, the wall's model is linear .* check -barrel_hoop_frequency and -barrel_hoop_mass" <<<"$out" && [[ $flag == 1* ]]; then
  pass "a 10 Hz hoop: the wall's displacement beyond a quarter of its radius is flagged (summary and wall_deflection_large)"
else fail "hoop 10 Hz: exit $rc, flag '$flag': $out"; fi
out=$("$exe" -options_file options/bats/aluminium-bat.opts -options_file options/balls/baseball.opts -beam_nodes 41 -impact_x 0.66 -barrel_hoop_frequency 1000 -barrel_hoop_mass 0.27 -ts_type modal -output none 2>&1)
! grep -q "barrel wall's largest displacement" <<<"$out" && pass "no flag for a 1000 Hz hoop" || fail "flag at 1000 Hz: $out"
out=$("$exe" -task modes -options_file options/bats/r161-corked.opts -beam_shell -beam_nodes 41 -modes_count 2 -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "^note: -beam_shell on a thick wall: the barrel's wall is t = 0.01945 m on a midsurface radius R = 0.02243 m (t/R = 0.87, above 0.1): the thin-shell model" <<<"$out"; then
  pass "-beam_shell on the corked R161's 19 mm wall: noted (t/R 0.87 > 0.1)"
else fail "corked R161 -beam_shell: exit $rc: $out"; fi
out=$("$exe" -task modes -options_file options/bats/aluminium-bat.opts -beam_shell -beam_nodes 41 -modes_count 2 -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && ! grep -q "thick wall" <<<"$out" && pass "-beam_shell on the aluminium bat's 2.5 mm wall: no note (t/R 0.078)" || fail "aluminium -beam_shell: exit $rc: $out"

# a contact cut short by -impact_max_time: an error for one impact (tests/cli_bad_input.cmake),
# a failed row (status 7) in a sweep, never a number
out=$("$exe" -task sweep -sweep_x 0.5,0.6 -impact_max_time 1e-3 -output "$dir/cut.h5" 2>&1); rc=$?
if [[ $rc -eq 2 ]] && grep -q "sweep: 2 of 2 points failed: 2 with status 7 (cut off in contact by -impact_max_time)" <<<"$out" && grep -q "status 7 .*: the run was cut off in contact: -impact_max_time 0.001 s ended it" <<<"$out"; then
  pass "a sweep cut off in contact: failed rows with status 7 and the reason"
else fail "sweep with -impact_max_time 1e-3: exit $rc: $out"; fi

# missing options files
for f in "$dir/nosuch.opts" "$dir/includes.opts"; do
  printf -- "-options_file %s/also-missing.opts\n" "$dir" >"$dir/includes.opts"
  out=$("$exe" -options_file "$f" 2>&1); rc=$?
  if [[ $rc -eq 1 ]] && grep -q "beamimpact: error: -options_file .*: cannot open the file" <<<"$out" && ! grep -q "PETSC ERROR\|MPI_ABORT" <<<"$out"; then pass "missing -options_file ($(basename "$f")): one plain line"
  else fail "missing -options_file $f: exit $rc: $out"; fi
done

# provenance
f="$dir/sweep.h5"
for a in task git date host ranks slepc_version hdf5_version petsc_version program; do
  h5dump -a "/$a" "$f" >/dev/null 2>&1 || fail "the results file has no provenance attribute $a"
done
pass "provenance: $(h5dump -a /task -a /git -a /date "$f" 2>/dev/null | sed -nE 's/^ *\(0\): *//p' | paste -sd' ')"

# the run record: every option read, as used, with its unit (/options_used and its unit and
# given subgroups; io/run_record.hpp): the hands, the swing, the damping and the pivot among them
if [[ -n $python ]]; then
  "$exe" -grip 0.05,0.2 -grip_stiffness 1e5 -bat_speed 20 -beam_damping_mass 2 -output "$dir/record.h5" >/dev/null 2>&1 || fail "the run for the record did not run"
  "$exe" -beam_pivot 0.3 -impact_x 0.9 -output "$dir/record-pivot.h5" >/dev/null 2>&1 || fail "the pivoted run for the record did not run"
  rec=$("$python" - "$dir/record.h5" "$dir/record-pivot.h5" <<'PY'
import sys, h5py, numpy as np
s = lambda v: v.decode() if isinstance(v, bytes) else str(v)
bad = []
with h5py.File(sys.argv[1], "r") as f:
    o, u, g = f["options_used"].attrs, f["options_used/unit"].attrs, f["options_used/given"].attrs
    want = {"grip": ([0.05, 0.2], "m", 1), "grip_stiffness": (1e5, "N/m^2", 1), "grip_damping": (0, "N s/m^2", 0), "grip_mass": (0, "kg", 0),
            "bat_speed": (20, "m/s", 1), "bat_angular_velocity": (0, "rad/s", 0), "beam_damping_mass": (2, "1/s", 1), "beam_damping_stiffness": (0, "s", 0),
            "impact_x": (0.55, "m", 0), "beam_nodes": (41, "1", 0)}
    for k, (v, unit, given) in want.items():
        if k not in o or not np.allclose(o[k], v) or s(u.get(k, "")) != unit or g[k] != given:
            bad.append("%s = %r %r given %r" % (k, o.get(k), u.get(k), g.get(k)))
    if s(o.get("beam_left")) != "free" or "beam_left" in u: bad.append("beam_left %r" % o.get("beam_left"))
    if not np.isclose(f.attrs["beam_mass"], 0.57024): bad.append("the derived beam_mass is gone")
with h5py.File(sys.argv[2], "r") as f:
    o, u = f["options_used"].attrs, f["options_used/unit"].attrs
    if not np.isclose(o["beam_pivot"], 0.3) or s(u["beam_pivot"]) != "m": bad.append("beam_pivot %r %r" % (o.get("beam_pivot"), u.get("beam_pivot")))
print("ok" if not bad else "bad: " + "; ".join(bad))
PY
)
  [[ $rec == ok ]] && pass "the run record carries every option read, with units: grip, swing, damping, pivot" || fail "run record: $rec"
fi

# Options without effect (issue 34): a head-on hit (no -impact_offset, no -ball_spin, -flight or
# not) slides nothing along the tangent, so friction, the tangential compliance, the ball's
# inertia and the bat's second plane change nothing: each a note, the numbers bit-identical to a
# run without them; the compliance, the inertia and the plane without friction likewise; the
# error tolerances under a fixed step (-ts_type modal).
bat=(-options_file options/bats/r161.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -ts_type modal -impact_x 0.7 -output none)
numbers() { grep -E "^(x |flight:|oblique:)" <<<"$1" | sed -E 's/  wall [0-9.e+-]+ s//'; }
# notes OUTPUT ITEM...: the note line holds every ITEM
notes() {
  local line item
  line=$(grep "^note: option(s) with no effect in this run:" <<<"$1") || return 1
  shift
  for item in "$@"; do grep -qF -- "$item" <<<"$line" || return 1; done
}
head_on="(it acts only with -impact_offset not 0 or -ball_spin not 0 or -impact_angle not 0 or -bat_speed_face not 0)"
plain=$("$exe" "${bat[@]}" -flight 2>&1)
out=$("$exe" "${bat[@]}" -flight -ball_friction 0.9 -ball_tangential_cor 0.3 -ball_inertia_factor 0.6 -impact_tangential_plane rigid 2>&1); rc=$?
if [[ $rc -eq 0 ]] && notes "$out" "-ball_friction 0.9 $head_on" "-ball_inertia_factor 0.6 $head_on" "-ball_tangential_cor 0.3 $head_on" "-impact_tangential_plane rigid $head_on" &&
   [[ -n $(numbers "$out") && $(numbers "$out") == $(numbers "$plain") ]]; then
  pass "a head-on hit with -flight: the four tangential options are notes, the numbers those of a run without them"
else fail "head-on tangential options: exit $rc: $out"; fi
no_friction="(it acts only with -ball_friction not 0; -ball_friction is 0)"
plain=$("$exe" "${bat[@]}" -impact_offset 0.01 -ball_friction 0 2>&1)
out=$("$exe" "${bat[@]}" -impact_offset 0.01 -ball_friction 0 -ball_tangential_cor 0.3 -impact_tangential_plane rigid 2>&1); rc=$?
if [[ $rc -eq 0 ]] && notes "$out" "-ball_tangential_cor 0.3 $no_friction" "-impact_tangential_plane rigid $no_friction" "-ball_inertia_factor 0.4 $no_friction" &&
   [[ -n $(numbers "$out") && $(numbers "$out") == $(numbers "$plain") ]]; then
  pass "-ball_friction 0: -ball_tangential_cor, -impact_tangential_plane and the inertia are notes, the numbers unchanged"
else fail "-ball_friction 0 with -ball_tangential_cor: exit $rc: $out"; fi
out=$("$exe" "${bat[@]}" -impact_offset 0.01 -ball_friction 0.5 -ball_tangential_cor 0.3 2>&1); rc=$?
[[ $rc -eq 0 ]] && ! grep -q "no effect" <<<"$out" && pass "an oblique hit with friction: no note" || fail "oblique hit with friction: exit $rc: $out"
fixed="(the step is fixed, -ts_type modal with -ts_adapt_type none: -ts_dt sets it)"
plain=$("$exe" "${bat[@]}" 2>&1)
out=$("$exe" "${bat[@]}" -ts_rtol 1e-3 -ts_atol 1e-2 2>&1); rc=$?
if [[ $rc -eq 0 ]] && notes "$out" "-ts_atol 1e-2 $fixed" "-ts_rtol 1e-3 $fixed" && [[ $(numbers "$out") == $(numbers "$plain") ]]; then
  pass "-ts_rtol and -ts_atol under the fixed-step -ts_type modal: notes, the numbers unchanged"
else fail "-ts_type modal -ts_rtol: exit $rc: $out"; fi
out=$("$exe" -ts_type rk -ts_rk_type 5dp -ts_rtol 1e-6 -ts_atol 1e-6 -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && ! grep -q "no effect" <<<"$out" && pass "an adaptive -ts_type rk: -ts_rtol and -ts_atol act, no note" || fail "rk 5dp -ts_rtol: exit $rc: $out"
# a sweep whose axis varies what an option needs: the option acts at some points, no note
out=$("$exe" -task sweep -sweep "beam_theory=euler;timoshenko" -beam_shear_modulus 1e9 -output "$dir/theories.h5" 2>&1); rc=$?
[[ $rc -eq 0 ]] && ! grep -q "no effect" <<<"$out" && pass "-sweep beam_theory=euler;timoshenko with -beam_shear_modulus: no 'no effect' note" \
  || fail "sweep over beam_theory with -beam_shear_modulus: exit $rc: $out"

echo "cli_policy: $fails failure(s)"
[[ $fails -eq 0 ]]
