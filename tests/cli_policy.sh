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
#   * every results file records its provenance: task, git, date, host, ranks, library versions.
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
for opt in -task -beam_profile -beam_theory -ball_cor_table -bat_speed -impact_after -monitor_velocity_at -modes_count -sweep -sweep_retry_failed -convergence_configs -leapfrog_dt -ts_type -ts_rk_type -output_overwrite; do
  grep -q -- "$opt\b" <<<"$out" || fail "-help does not list $opt"
done
grep -q -- "-ts_type <now rk" <<<"$out" && pass "-help lists every task's options, PETSc's TS from the program's default rk" || fail "-help shows a TS default other than rk"

# a scene with a later -ts_type
out=$("$exe" -options_file options/impact.opts -ts_type cn -output none 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "note: 1 PETSc solver option(s) set but not used by this integrator: -ts_rk_type 4" <<<"$out"; then
  pass "options/impact.opts -ts_type cn runs, the leftover -ts_rk_type is a note"
else fail "options/impact.opts -ts_type cn: exit $rc: $out"; fi
out=$("$exe" -options_file options/impact.opts -beam_thicknes 0.01 -output none 2>&1); rc=$?
if [[ $rc -ne 0 ]] && grep -q "option(s) set but not used by this task and integrator: -beam_thicknes 0.01" <<<"$out"; then pass "a misspelt program option is still an error"; else fail "-beam_thicknes: exit $rc: $out"; fi

# PETSc's own habits: monitors and viewers work, options the driver cannot honour are refused
out=$("$exe" -options_file options/impact.opts -impact_window 0 -ts_monitor -ts_view -output none 2>&1); rc=$?
[[ $rc -eq 0 ]] && grep -q "^1 TS dt" <<<"$out" && grep -q "TS Object" <<<"$out" && pass "-ts_monitor and -ts_view print" || fail "-ts_monitor/-ts_view: exit $rc"
for o in "-ts_max_steps 100" "-ts_max_time 1e-3"; do
  out=$("$exe" -options_file options/impact.opts $o -output none 2>&1); rc=$?
  [[ $rc -ne 0 ]] && grep -q -- "${o%% *} is not used here: .* use -impact_max_time" <<<"$out" && pass "$o refused, naming what to use" || fail "$o: exit $rc: $out"
done

# -output
out=$("$exe" -output "" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "-output needs a file name" <<<"$out" && pass "-output '' refused" || fail "-output '': exit $rc: $out"
out=$("$exe" -output "$dir/no/such/dir/x.h5" -impact_x 0.5 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "the directory $dir/no/such/dir does not exist or is not writable" <<<"$out" && ! grep -q "^x " <<<"$out" && pass "-output into a missing directory refused before any work" || fail "missing directory: exit $rc: $out"
"$exe" -task sweep -sweep_x 0.5,0.6 -sweep_quiet -output "$dir/sweep.h5" >/dev/null 2>&1 || fail "the sweep for the overwrite test did not run"
out=$("$exe" -output "$dir/sweep.h5" 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "holds the results of -task sweep: -task impact will not replace them" <<<"$out" && pass "-task impact does not overwrite a sweep's file" || fail "overwrite: exit $rc: $out"
"$exe" -output "$dir/sweep.h5" -output_overwrite >/dev/null 2>&1 && pass "-output_overwrite lets it" || fail "-output_overwrite refused"
"$exe" -output "$dir/sweep.h5" >/dev/null 2>&1 && pass "an impact file is replaced by the next impact (same task)" || fail "same-task overwrite refused"

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

echo "cli_policy: $fails failure(s)"
[[ $fails -eq 0 ]]
