#!/usr/bin/env bash
# Sweep store, launcher, output and logging defects of the newcomer issue, through the real
# executable; one part per ctest test (the last argument):
#   lock       a refused resume (other options) and a sweep refused after it took the lock (its
#              -output is not an HDF5 file) leave no FILE.h5.parts/lock behind, a second resume
#              then works; a lock held by a live sweep is still respected, a stale one is taken;
#   launcher   kill -9 of mpirun during a 2-rank sweep: within 0.5 s none of its ranks is left
#              and the journal stops growing; the same command then resumes to a complete file;
#   integers   counts are HDF5 integer attributes (beam_nodes, ranks, impact_max_contacts,
#              modes_count, sweep point counts, ...), -task impact's integer /results columns
#              are integer datasets (a sweep's stay float: NaN rows), and impact_x,
#              impact_window, impact_max_time, dt_nominal are the values used (the formulas of
#              docs/model.md section 7 from the file's own attributes), not -1;
#   stages     -log_view names and times the stages "modal reference" (-reference modal) and
#              "output" (a sweep's rewrites of its file);
#   beyond     the sweep summary counts the points whose compression exceeds -ball_radius;
#   cutoff     -task convergence reports a run cut off in contact as failed, never a number.
#
#   tests/sweep_io.sh path/to/beamimpact scratch_dir mpiexec part
set -uo pipefail
exe=${1:?usage: sweep_io.sh beamimpact scratch_dir mpiexec part}
dir=${2:?usage: sweep_io.sh beamimpact scratch_dir mpiexec part}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
part=${4:?usage: sweep_io.sh beamimpact scratch_dir mpiexec part}
exe=$(readlink -f "$exe")
source "$(dirname "$0")/lib.sh" # MPI env, fail/pass, $python
cd "$(dirname "$0")/.." || exit 2
dir="$dir/$part"
rm -rf "$dir" && mkdir -p "$dir"

# A quick scene: the 6 mm aluminium beam, free-free, N = 21, struck by the linear superball.
scene=(-options_file options/base/aluminium-6mm.opts -options_file options/base/superball-linear.opts -beam_length 1.1 -beam_left free -beam_right free -beam_nodes 21)

need_python() { [[ -n "$python" ]] || { echo "SKIP: no Python with h5py"; exit 77; }; }

case $part in
lock)
  f=$dir/lock.h5
  opts=("${scene[@]}" -task sweep -sweep "impact_x=0.1:1.0:4" -sweep_quiet -impact_window 0)
  "$exe" "${opts[@]}" -output "$f" >"$dir/first.log" 2>&1 || { fail "first sweep failed"; cat "$dir/first.log"; }
  [[ ! -e $f.parts ]] && pass "a finished sweep leaves no $f.parts" || fail "a finished sweep left $(ls "$f.parts")"
  # a resume with other options is refused, and leaves no lock
  if "$exe" "${opts[@]}" -ball_speed 2 -output "$f" >"$dir/refused.log" 2>&1; then fail "a resume with another -ball_speed was accepted"
  elif grep -q "different parameters" "$dir/refused.log"; then pass "a resume with another -ball_speed is refused"
  else fail "refused resume: unclear message"; cat "$dir/refused.log"; fi
  [[ ! -e $f.parts/lock ]] && pass "the refused resume left no $f.parts/lock" || fail "the refused resume left $f.parts/lock"
  [[ ! -e $f.parts ]] && pass "... nor an empty $f.parts" || fail "the refused resume left $f.parts: $(ls -A "$f.parts")"
  "$exe" "${opts[@]}" -output "$f" >"$dir/second.log" 2>&1 && [[ ! -e $f.parts ]] \
    && pass "a second resume (the same options) then works" || { fail "second resume"; cat "$dir/second.log"; }
  # bad input found after the lock was taken: -output names a file that is not HDF5
  echo "not a results file" >"$dir/text.h5"
  if "$exe" "${opts[@]}" -output "$dir/text.h5" >"$dir/text.log" 2>&1; then fail "a sweep onto a text file was accepted"
  else grep -q "is not an HDF5 file" "$dir/text.log" && pass "a sweep onto a text file is refused" || { fail "sweep onto a text file: unclear message"; cat "$dir/text.log"; }; fi
  [[ ! -e $dir/text.h5.parts ]] && pass "... and leaves no text.h5.parts/lock" || fail "the refused sweep left text.h5.parts/$(ls -A "$dir/text.h5.parts")"
  # the same with a directory of that name
  mkdir -p "$dir/isdir.h5/x"
  if "$exe" "${opts[@]}" -output "$dir/isdir.h5" >"$dir/isdir.log" 2>&1; then fail "a sweep onto a directory succeeded"; else pass "a sweep onto a directory fails: $(grep -m1 error "$dir/isdir.log")"; fi
  [[ ! -e $dir/isdir.h5.parts/lock ]] && pass "... and leaves no lock" || fail "the failed sweep left isdir.h5.parts/lock"
  # a live sweep's lock is respected (held here by flock, as a running sweep holds it)
  mkdir -p "$f.parts"
  if command -v flock >/dev/null; then
    flock -x "$f.parts/lock" sleep 120 & # held until killed below, however slow the machine
    holder=$!
    for ((i = 0; i < 200; ++i)); do flock -n "$f.parts/lock" true || break; sleep 0.05; done # until it holds the lock
    if "$exe" "${opts[@]}" -output "$f" >"$dir/held.log" 2>&1; then fail "a sweep ran while another held the lock"
    else grep -q "being written by another sweep that is still running" "$dir/held.log" && pass "a held lock is respected" || { fail "held lock: unclear message"; cat "$dir/held.log"; }; fi
    [[ -e $f.parts/lock ]] && pass "... and the holder's lock file stays" || fail "the refused run removed the lock another sweep holds"
    kill $(descendants $holder) $holder 2>/dev/null; wait $holder 2>/dev/null
  fi
  # a stale lock (its holder killed: the file is there, nobody holds it) is taken
  touch "$f.parts/lock"
  "$exe" "${opts[@]}" -output "$f" >"$dir/stale.log" 2>&1 && [[ ! -e $f.parts ]] && pass "a stale lock is taken and removed at the end" || { fail "stale lock"; cat "$dir/stale.log"; }
  ;;

launcher)
  need_python
  f=$dir/killed.h5
  N=80 # 0.06 to 0.3 s a point on one core: seconds on two ranks, however idle the machine
  opts=(-task sweep -beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2.5e-7 -rigid_loss_fraction 0.2
        -sweep "impact_x=0.05:1.05:$((N / 2)),ball_speed=1;2" -sweep_progress_interval 0.02 -sweep_write_interval 0.1)
  setsid "$mpiexec" -n 2 "$exe" "${opts[@]}" -output "$f" >"$dir/killed.log" 2>&1 &
  launcher=$!
  seen=$(sweep_progress "$dir/killed.log" "$launcher")
  ranks=$(for p in $(descendants "$launcher"); do [[ $(ps -o comm= -p "$p") == *beamimpact* ]] && echo "$p"; done | tr '\n' ' ')
  [[ -n $ranks ]] || fail "no rank process found under the launcher"
  journal_bytes() { cat "$f.parts"/run*-rank*.bin 2>/dev/null | wc -c; }
  kill -9 "$launcher" # the launcher only: its ranks must follow it
  wait "$launcher" 2>/dev/null
  # Poll for 0.5 s: a killed rank may stay a zombie until its new parent reaps it, so only
  # those not dead (state other than Z, X) count; the state of any left is printed.
  running() { local p st out=""; for p in $ranks; do st=$(awk '{ print $3 }' "/proc/$p/stat" 2>/dev/null); [[ -n $st && $st != Z && $st != X ]] && out+=" $p($st)"; done; echo "$out"; }
  for ((i = 0; i < 10; ++i)); do
    alive=$(running)
    [[ -z $alive ]] && break
    sleep 0.05
  done
  alive=$(running)
  b1=$(journal_bytes)
  sleep 1
  b2=$(journal_bytes)
  echo "      killed mpirun after $seen/$N points; ranks $ranks; running after 0.5 s:${alive:- none}; journal $b1 then $b2 bytes 1 s later"
  grep -q "^sweep: computed" "$dir/killed.log" && fail "the sweep finished before it could be killed"
  [[ -z $alive ]] && pass "no rank of the killed mpirun is left after 0.5 s" || fail "ranks$alive still running 0.5 s after mpirun was killed"
  [[ $b1 == "$b2" ]] && pass "the journal stopped growing ($b1 bytes)" || fail "the journal grew from $b1 to $b2 bytes after the kill"
  for p in $alive; do kill -9 "${p%%(*}" 2>/dev/null; done # leave nothing behind (checked just now: still ours)
  sleep 0.2
  "$mpiexec" -n 2 "$exe" "${opts[@]}" -output "$f" >"$dir/resumed.log" 2>&1 || { fail "resume failed"; cat "$dir/resumed.log"; }
  already=$(sed -nE 's/^sweep: resuming .*: ([0-9]+) of [0-9]+ points already done.*/\1/p' "$dir/resumed.log")
  computed=$(sed -nE 's/^sweep: computed ([0-9]+) points? .*/\1/p' "$dir/resumed.log")
  if [[ -n $already && -n $computed ]] && ((already >= seen && already + computed == N)); then pass "resumed: $already already done (>= $seen seen), $computed computed"
  else fail "resume: already '${already}', computed '${computed}', seen $seen"; cat "$dir/resumed.log"; fi
  "$python" - "$f" "$N" <<'PY' && pass "the resumed file is complete: $N rows in case order, all status 0" || fail "the resumed file is incomplete"
import sys, h5py, numpy as np
f, n = h5py.File(sys.argv[1], "r"), int(sys.argv[2])
r = f["results"]
ok = int(f.attrs["sweep_complete"]) == 1 and int(f.attrs["sweep_cases_done"]) == n
ok = ok and np.array_equal(r["case_index"][()], np.arange(n)) and np.all(r["status"][()] == 0) and np.all(np.isfinite(r["acor"][()]))
sys.exit(0 if ok else 1)
PY
  [[ ! -e $f.parts ]] || fail "journal directory left after the resume"
  if ((fails)); then
    echo "--- killed.log"; tail -n 15 "$dir/killed.log"; echo "--- resumed.log"; tail -n 15 "$dir/resumed.log"
  fi
  ;;

integers)
  need_python
  out=$("$exe" "${scene[@]}" -task impact -impact_x 0.9 -output "$dir/impact.h5" 2>&1) || { fail "impact run: $out"; }
  summary=$(grep -m1 "^x " <<<"$out")
  "$exe" "${scene[@]}" -task impact -impact_window 0 -impact_max_time 0.05 -impact_max_contacts 7 -impact_after time -output "$dir/given.h5" >/dev/null 2>&1 || fail "impact run with given times"
  "$exe" "${scene[@]:0:2}" "${scene[@]:4}" -task modes -modes_count 5 -output "$dir/modes.h5" >/dev/null 2>&1 || fail "modes run"
  "$mpiexec" -n 2 "$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.2:1.0:3,ball_speed=1;2" -sweep_quiet -output "$dir/sweep.h5" >/dev/null 2>&1 || fail "sweep run"
  "$python" - "$dir" "$summary" <<'PY'
import sys, math, re, h5py, numpy as np
d, summary = sys.argv[1], sys.argv[2]
bad, good = [], []
def check(what, ok):
    (good if ok else bad).append(what)
def attr(f, name):
    a = f.attrs.get(name)
    if a is None: bad.append("%s: no attribute %s" % (f.filename.split("/")[-1], name))
    return float("nan") if a is None else a
def integer_attr(f, name, value=None):
    a = f.attrs.get(name)
    ok = a is not None and np.asarray(a).dtype.kind in "iu" and (value is None or int(a) == value)
    check("%s: attribute %s = %r (%s)%s" % (f.filename.split("/")[-1], name, a, None if a is None else np.asarray(a).dtype, "" if value is None else ", expected the integer %d" % value), ok)
def close(what, a, b, rtol=1e-12):
    check("%s = %.12g (expected %.12g)" % (what, a, b), abs(a - b) <= rtol * abs(b))
# -task impact, derived defaults
f = h5py.File(d + "/impact.h5", "r")
A = f.attrs
for name, v in (("beam_nodes", 21), ("ranks", 1), ("impact_max_contacts", 50), ("impact_window_default", 1), ("impact_max_time_default", 1)):
    integer_attr(f, name, v)
w1 = 4.73004 ** 2 * math.sqrt(A["beam_EI"] / (A["beam_mu"] * A["beam_length"] ** 4))  # free-free, docs/model.md section 7
window = 2 * 2 * math.pi / w1
Tc = math.pi * math.sqrt(A["ball_mass"] / A["ball_k"])  # the linear ball's wall contact time
close("impact.h5 impact_window (2 fundamental periods)", float(attr(f, "impact_window")), window, 1e-5)
close("impact.h5 impact_max_time (4 windows + 100 T_c)", float(attr(f, "impact_max_time")), 4 * window + 100 * Tc, 1e-5)
close("impact.h5 impact_x", float(attr(f, "impact_x")), 0.9)
check("impact.h5 impact_after = %r (modal: the default, resolved)" % attr(f, "impact_after"), str(attr(f, "impact_after")) in ("modal", "b'modal'"))
close("impact.h5 dt_nominal (as /results/dt_nominal)", float(attr(f, "dt_nominal")), float(f["results/dt_nominal"][0]))
check("impact.h5 impact_window, impact_max_time > 0 (not -1)", attr(f, "impact_window") > 0 and attr(f, "impact_max_time") > 0)
r = f["results"]
for name in ("contacts", "ended_in_contact", "compression_beyond_radius", "steps", "rejected_steps", "event_steps", "failed_solves", "function_evals", "jacobian_evals", "jacobian_assemblies", "nonlinear_its", "linear_its"):
    check("impact.h5 /results/%s is an integer dataset (%s)" % (name, r[name].dtype), r[name].dtype.kind == "i")
for name in ("acor", "x", "wall_time", "dt_nominal"):
    check("impact.h5 /results/%s stays float (%s)" % (name, r[name].dtype), r[name].dtype.kind == "f")
m = re.search(r"contacts (\d+)  steps (\d+)  rejected (\d+)  failed (\d+)  fevals (\d+)", summary)
check("summary line parsed: %s" % summary, m is not None)
if m:
    c, s, rej, fl, fe = (int(v) for v in m.groups())
    check("contacts %d = /results/contacts %d" % (c, r["contacts"][0]), c == r["contacts"][0])
    check("steps %d = /results/steps + event_steps %d" % (s, r["steps"][0] + r["event_steps"][0]), s == r["steps"][0] + r["event_steps"][0])
    check("rejected, failed, fevals = /results", (rej, fl, fe) == (r["rejected_steps"][0], r["failed_solves"][0], r["function_evals"][0]))
# given times are stored as given
g = h5py.File(d + "/given.h5", "r")
close("given.h5 impact_window", float(attr(g, "impact_window")) + 1, 1.0)
close("given.h5 impact_max_time", float(attr(g, "impact_max_time")), 0.05)
integer_attr(g, "impact_max_contacts", 7)
check("given.h5 impact_after = %r (-impact_after time)" % attr(g, "impact_after"), str(attr(g, "impact_after")) in ("time", "b'time'"))
integer_attr(g, "impact_window_default", 0)
integer_attr(g, "impact_max_time_default", 0)
# -task modes
mf = h5py.File(d + "/modes.h5", "r")
integer_attr(mf, "modes_count", 5)
integer_attr(mf, "modes_rigid_count", 2)
integer_attr(mf, "beam_nodes", 21)
check("modes.h5: modes_count = len(/modes/frequency)", attr(mf, "modes_count") == len(mf["modes/frequency"]))
# -task sweep on 2 ranks
s = h5py.File(d + "/sweep.h5", "r")
for name, v in (("beam_nodes", 21), ("ranks", 2), ("sweep_count_impact_x", 3), ("sweep_count_ball_speed", 2), ("sweep_cases_total", 6), ("sweep_cases_done", 6), ("sweep_complete", 1), ("sweep_ranks_per_case", 1), ("impact_max_contacts", 50)):
    integer_attr(s, name, v)
check("sweep.h5 impact_window > 0 (the value used)", attr(s, "impact_window") > 0)
check("sweep.h5 /results/steps stays float (NaN in failed rows; docs/model.md section 9)", s["results/steps"].dtype.kind == "f")
for m in good: print("ok:  ", m)
for m in bad: print("FAIL:", m)
sys.exit(1 if bad else 0)
PY
  [[ $? -eq 0 ]] && pass "integer attributes and columns, values used" || fail "integer attributes and columns, values used"
  # the scripts still read the files with integer attributes and columns
  if "$python" -c "import matplotlib" 2>/dev/null; then
    for args in "$dir/sweep.h5 -o $dir/sweep.png" "$dir/impact.h5 contacts -o $dir/impact.png"; do
      # shellcheck disable=SC2086
      "$python" scripts/plot_sweep.py $args >"$dir/plot.log" 2>&1 && pass "scripts/plot_sweep.py $(basename "${args%% *}")" || { fail "plot_sweep.py $args"; cat "$dir/plot.log"; }
    done
    "$python" scripts/plot_bat.py "$dir/modes.h5" -o "$dir/modes.png" >"$dir/plot.log" 2>&1 && pass "scripts/plot_bat.py modes.h5" || { fail "plot_bat.py"; cat "$dir/plot.log"; }
  fi
  ;;

stages)
  # the time of a stage in the -log_view summary ("  4: beamimpact: output: 1.2e-03 ..."), or "" when absent
  stage_time() { sed -nE "s/^ *[0-9]+: +$1: +([0-9.e+-]+) .*/\1/p" <<<"$2" | head -1; }
  out=$("$exe" "${scene[@]}" -task impact -reference modal -log_view -output "$dir/modal.h5" 2>&1); rc=$?
  t=$(stage_time "beamimpact: modal reference" "$out")
  [[ $rc -eq 0 && -n $t ]] && awk -v t="$t" 'BEGIN { exit !(t > 0) }' && pass "-reference modal: -log_view times the stage 'modal reference' ($t s)" || { fail "-reference modal -log_view: exit $rc, stage time '$t'"; grep -E "^ *[0-9]+: " <<<"$out"; }
  out=$("$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.2:1.0:3" -sweep_quiet -log_view -output "$dir/sweep.h5" 2>&1); rc=$?
  t=$(stage_time "beamimpact: output" "$out")
  [[ $rc -eq 0 && -n $t ]] && awk -v t="$t" 'BEGIN { exit !(t > 0) }' && pass "sweep: -log_view times its file's rewrites in the stage 'output' ($t s)" || { fail "sweep -log_view: exit $rc, output stage time '$t'"; grep -E "^ *[0-9]+: " <<<"$out"; }
  ;;

beyond)
  # 1 m/s: 3.6 mm compression; 1e4 m/s: about 12 m, far beyond the superball's 18 mm radius
  out=$("$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.3;0.6,ball_speed=1;1e4" -impact_window 0 -sweep_quiet -output "$dir/beyond.h5" 2>&1); rc=$?
  n=$(sed -nE 's/^sweep: ([0-9]+) of 4 points compressed the ball beyond its radius.*/\1/p' <<<"$out")
  if [[ -n $python ]]; then
    flagged=$("$python" -c "import h5py,sys; r=h5py.File(sys.argv[1])['results']; print(int(((r['compression_beyond_radius'][()] == 1) & (r['status'][()] == 0)).sum()))" "$dir/beyond.h5")
  else flagged=2; fi
  [[ $rc -eq 0 && $n == 2 && $flagged == 2 ]] && pass "the summary counts the 2 points beyond -ball_radius: $(grep "beyond its radius" <<<"$out")" || fail "beyond radius: exit $rc, summary count '$n', file $flagged: $out"
  grep -q "beyond its radius" <<<"$out" && grep -q "physically absurd" <<<"$out" || fail "the summary does not say what these points are"
  out=$("$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.3;0.6" -impact_window 0 -sweep_quiet -output "$dir/fine.h5" 2>&1)
  ! grep -q "beyond its radius" <<<"$out" && pass "no such line at 1 m/s" || fail "line at 1 m/s: $out"
  ;;

cutoff)
  # -impact_max_time 2e-4 s cuts every run off in the first contact (about 0.4 ms long)
  conv=(-task convergence -impact_window 0 -impact_max_time 2e-4 -convergence_reference run -convergence_reference_config options/convergence/rk4.opts
        -convergence_configs options/convergence/rk4.opts -convergence_repeats 1)
  out=$("$exe" "${scene[@]}" "${conv[@]}" -output "$dir/conv.h5" 2>&1); rc=$?
  if [[ $rc -ne 0 ]] && grep -q "cut off\|still in contact\|still touching" <<<"$out" && ! grep -q "ended in contact" <<<"$out" && ! grep -Eq "acor_err [0-9]" <<<"$out"; then
    pass "a convergence reference cut off in contact is an error: $(grep -m1 error <<<"$out" | cut -c1-200)"
  else fail "convergence reference cut off in contact: exit $rc: $out"; fi
  # the exact modal reference cut off the same way stops the study too (as before), no number
  out=$("$exe" "${scene[@]}" -task convergence -impact_window 0 -impact_max_time 2e-4 -convergence_configs options/convergence/rk4.opts -convergence_repeats 1 -output "$dir/conv2.h5" 2>&1); rc=$?
  [[ $rc -ne 0 ]] && ! grep -Eq "acor_err [0-9]|ended in contact" <<<"$out" && pass "the modal reference cut off in contact is an error too" || fail "modal reference cut off: exit $rc: $out"
  ;;
*) echo "unknown part $part"; exit 2 ;;
esac

if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
echo "all checks passed"
