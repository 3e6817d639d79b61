#!/usr/bin/env bash
# -task sweep (two axes: impact point x ball speed) survives kill -9 and resumes without
# losing or recomputing rows:
#   1. an uninterrupted 2-rank sweep is the reference;
#   2. the same sweep is started in the background and, once its progress shows
#      some but not all points done, mpiexec and its rank processes are killed
#      with SIGKILL (by process id); the output file, if any, must still be a
#      readable HDF5 file;
#   3. rerunning the same command resumes: it reports A points already done
#      (at least as many as were reported done before the kill: nothing lost),
#      computes exactly the other N - A (nothing recomputed) and leaves a file
#      identical to the reference (datasets but wall_time within 1e-12, every
#      attribute but the command line 'options');
#   4. a third run finds everything done; so do runs that change nothing: the axis's values
#      written differently (ball_speed=1.0;2.0 for 1;2), an option given at its default
#      (-impact_offset 0), an option the run does not read (-ts_theta_theta under rk); a changed
#      parameter (-beam_nodes, an axis's value) is refused with a message naming it;
#      -sweep_restart starts over;
#   5. steps 1-3 again for a sweep with a text (categorical) axis, ts_type=rk;cn by
#      impact point: killed, resumed, identical to its uninterrupted run;
#   6. and for a sampled sweep (a grid axis times a Latin hypercube of impact points): its
#      points and /statistics identical to the uninterrupted run's.
#
#   tests/sweep_resume.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: sweep_resume.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: sweep_resume.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
exe=$(readlink -f "$exe")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && cd "$dir" || exit 1
rm -rf resume_*
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" # MPI env, fail/pass, $python


# Slow enough cases (~0.2 s each on one core, the window after separation stepped too: seconds
# for the sweep, however idle the machine) that the kill lands mid-sweep.
N=24
base=(-task sweep -beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2e-6 -impact_after time
      -rigid_loss_fraction 0.2 -sweep_progress_interval 0.02 -sweep_write_interval 0.1)
opts=("${base[@]}" -sweep "impact_x=0.05:1.05:$((N / 2)),ball_speed=1;2")

same_file() {
  if [[ -n "$python" ]]; then
    "$python" - "$1" "$2" <<'PY'
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = []
def walk(g, h, path):
    if set(g.keys()) != set(h.keys()): bad.append("%s: members differ" % path)
    for k in g:
        if k not in h: continue
        p = path.rstrip("/") + "/" + k
        if isinstance(g[k], h5py.Group): walk(g[k], h[k], p)
        elif p != "/results/wall_time":
            x, y = g[k][()], h[k][()]
            if x.dtype.kind in "OSU":
                if not np.array_equal(x, y): bad.append("%s differs" % p)
            elif x.shape != y.shape or (x.size and not np.all((np.abs(x - y) <= 1e-12 * np.maximum(1, np.abs(x))) | (np.isnan(x) & np.isnan(y)))):
                bad.append("%s differs" % p)
walk(a, b, "/")
for k in set(a.attrs) | set(b.attrs):
    if k not in ("options", "date", "host", "ranks") and (k not in a.attrs or k not in b.attrs or a.attrs[k] != b.attrs[k]): bad.append("attribute %s differs" % k)
for m in bad: print("   ", m)
sys.exit(1 if bad else 0)
PY
  else
    local g n # h5dump -m %.17g prints every dataset exactly: compare the text
    for g in results sweep; do
      for n in $(h5dump -H -g "/$g" "$1" | sed -nE 's/^ *DATASET "([^"]+)".*/\1/p'); do
        [[ $g/$n == results/wall_time ]] && continue
        cmp -s <(h5dump -m %.17g -d "/$g/$n" "$1" | tail -n +3) <(h5dump -m %.17g -d "/$g/$n" "$2" | tail -n +3) || { echo "    /$g/$n differs"; return 1; }
      done
    done
  fi
}
readable() { if [[ -n "$python" ]]; then "$python" -c "import h5py,sys; f=h5py.File(sys.argv[1],'r'); f['results/acor'][()]" "$1"; else h5dump -d /results/acor "$1" >/dev/null; fi; }

# kill_resume TAG OPTIONS...: steps 1-3 for the sweep of OPTIONS (files resume_TAGref.h5, resume_TAGk.h5)
kill_resume() {
  local tag=$1 launcher seen ranks i p alive already todo computed
  shift
  # 1. reference
  "$mpiexec" -n 2 "$exe" "$@" -sweep_quiet -output resume_${tag}ref.h5 >resume_${tag}ref.log 2>&1 || { fail "reference sweep failed"; cat resume_${tag}ref.log; exit 1; }

  # 2. start, wait for some progress, kill -9
  setsid "$mpiexec" -n 2 "$exe" "$@" -output resume_${tag}k.h5 >resume_${tag}killed.log 2>&1 &
  launcher=$!
  seen=$(sweep_progress resume_${tag}killed.log "$launcher")
  # The launcher and everything below it: kill -9 by pid.
  ranks=$(descendants "$launcher" | tr '\n' ' ')
  kill -9 "$launcher" $ranks 2>/dev/null
  wait "$launcher" 2>/dev/null
  for ((i = 0; i < 100; ++i)); do
    alive=0
    for p in $ranks; do kill -0 "$p" 2>/dev/null && alive=1; done
    ((alive)) || break
    sleep 0.05
  done
  if grep -q "^sweep: computed" resume_${tag}killed.log; then fail "the sweep finished before it could be killed (make the cases slower)"; fi
  if ((seen < 4)); then fail "no progress seen before the kill"; cat resume_${tag}killed.log; fi
  echo "      killed after progress reported $seen/$N points done (ranks: $ranks)"
  if [[ -e resume_${tag}k.h5 ]]; then
    readable resume_${tag}k.h5 && pass "after kill -9 the output is a readable HDF5 file" || fail "after kill -9 the output is not readable"
  fi
  [[ -d resume_${tag}k.h5.parts ]] && pass "journal directory left for the resume" || fail "no journal directory after the kill"

  # 3. the same command again: resume
  "$mpiexec" -n 2 "$exe" "$@" -output resume_${tag}k.h5 >resume_${tag}resumed.log 2>&1 || { fail "resume failed"; cat resume_${tag}resumed.log; }
  already=$(sed -nE 's/^sweep: resuming .*: ([0-9]+) of [0-9]+ points already done, ([0-9]+) to compute/\1/p' resume_${tag}resumed.log)
  todo=$(sed -nE 's/^sweep: resuming .*: ([0-9]+) of [0-9]+ points already done, ([0-9]+) to compute/\2/p' resume_${tag}resumed.log)
  computed=$(sed -nE 's/^sweep: computed ([0-9]+) points? .*/\1/p' resume_${tag}resumed.log)
  echo "      resumed: ${already:-?} already done, ${todo:-?} to compute, ${computed:-?} computed"
  if [[ -z "$already" || -z "$computed" ]]; then
    fail "resume did not report what it skipped and computed"; cat resume_${tag}resumed.log
  else
    ((already >= seen)) && pass "nothing lost: $already on disk >= $seen reported done before the kill" || fail "lost rows: $already on disk < $seen reported done"
    ((already < N)) && pass "the killed run was partial ($already/$N)" || fail "the killed run had finished all points"
    ((computed == N - already && todo == N - already)) && pass "nothing recomputed: computed $computed = $N - $already" || fail "computed $computed, expected $((N - already))"
  fi
  [[ -d resume_${tag}k.h5.parts ]] && fail "journal directory not removed after completion"
  same_file resume_${tag}ref.h5 resume_${tag}k.h5 && pass "resumed file identical to the uninterrupted one" || fail "resumed file differs from the uninterrupted one"
}

kill_resume "" "${opts[@]}"

# 4. done, changed parameters, restart
"$mpiexec" -n 2 "$exe" "${opts[@]}" -output resume_k.h5 >resume_again.log 2>&1 && grep -q "all $N points were already done" resume_again.log \
  && pass "third run: nothing to compute" || { fail "third run"; cat resume_again.log; }
if "$exe" "${base[@]}" -sweep "impact_x=0.05:1.05:$((N / 2)),ball_speed=1;2.5" -output resume_k.h5 >resume_changed.log 2>&1; then
  fail "a changed axis value was accepted for resume"
elif grep -q "sweep axis ball_speed: '1;2' in the file, '1;2.5' now" resume_changed.log; then
  pass "a changed axis value refused: $(grep -m1 "sweep axis" resume_changed.log | sed 's/^ *//')"
else
  fail "changed axis value: unclear message"; cat resume_changed.log
fi
if "$exe" "${opts[@]}" -beam_nodes 23 -output resume_k.h5 >resume_changed.log 2>&1; then
  fail "a changed parameter was accepted for resume"
elif grep -q "different parameters" resume_changed.log && grep -q "option -beam_nodes: '21' in the file, '23' now" resume_changed.log && grep -q -- "-sweep_restart" resume_changed.log; then
  pass "changed -beam_nodes refused: $(grep -m1 "beam_nodes" resume_changed.log | sed 's/^ *//')"
else
  fail "changed parameter: unclear message"; cat resume_changed.log
fi
same_file resume_ref.h5 resume_k.h5 || fail "the refused runs modified the file"
# the same sweep written otherwise, or with options that change nothing: resumed, nothing computed
# (each change alone: the file's plan is ball_speed=1;2, no -impact_offset, no -ts_theta_theta)
for extra in "same values written 1.0;2.0|ball_speed=1.0;2.0|" "-impact_offset 0 (its default)|ball_speed=1;2|-impact_offset 0" \
             "-ts_theta_theta 0.6 (unused under rk)|ball_speed=1;2|-ts_theta_theta 0.6"; do
  IFS='|' read -r what speeds args <<<"$extra"
  # shellcheck disable=SC2086
  "$exe" "${base[@]}" -sweep "impact_x=0.05:1.05:$((N / 2)),$speeds" $args -output resume_k.h5 >resume_same.log 2>&1 && grep -q "all $N points were already done" resume_same.log \
    && pass "resume accepts $what: nothing to compute" || { fail "resume with $what refused"; cat resume_same.log; }
done
# ... but a real change beside them is still refused, with its difference alone
if "$exe" "${base[@]}" -sweep "impact_x=0.05:1.05:$((N / 2)),ball_speed=1.0;2.0" -impact_offset 0 -ts_theta_theta 0.6 -beam_nodes 23 -output resume_k.h5 >resume_changed.log 2>&1; then
  fail "a changed -beam_nodes beside the harmless changes was accepted"
elif diffs=$(sed -n '/cannot be resumed:/,/^Rerun/p' resume_changed.log) && grep -q "option -beam_nodes: '21' in the file, '23' now" <<<"$diffs" &&
  ! grep -qE "impact_offset|ts_theta_theta|sweep axis|sweep:|option -sweep|ball_speed" <<<"$diffs"; then
  pass "-beam_nodes 23 beside the harmless changes: refused, the difference list -beam_nodes alone"
else fail "-beam_nodes beside harmless changes: unclear"; cat resume_changed.log; fi
"$exe" "${base[@]}" -beam_nodes 23 -sweep_x 0.3,0.6 -sweep_restart -sweep_quiet -output resume_k.h5 >resume_restart.log 2>&1 && readable resume_k.h5 \
  && pass "-sweep_restart starts a new file" || { fail "-sweep_restart"; cat resume_restart.log; }

# 5. a text axis (the integrator) by impact point: the same kill, resume and identity
N=12
kill_resume text_ "${base[@]}" -sweep "ts_type=rk;cn,impact_x=0.05:1.05:$((N / 2))"
# a text axis changes what is read (the integrator): an option the first point did not read still counts
if "$exe" "${base[@]}" -sweep "ts_type=rk;cn,impact_x=0.05:1.05:$((N / 2))" -ts_theta_theta 0.6 -output resume_text_k.h5 >resume_text_theta.log 2>&1; then
  fail "a text (ts_type) sweep resumed with -ts_theta_theta added"
elif grep -q "option -ts_theta_theta: not set in the file, '0.6' now" resume_text_theta.log; then pass "a ts_type sweep: -ts_theta_theta added is refused, named"
else fail "ts_type sweep with -ts_theta_theta: unclear"; cat resume_text_theta.log; fi
if [[ -n "$python" ]]; then
  "$python" -c "import h5py, sys; r = h5py.File(sys.argv[1], 'r')['results']; assert [v.decode() for v in r['ts_type'][()]] == ['rk'] * 6 + ['cn'] * 6 and list(r['ts_type'].attrs['values']) == ['rk', 'cn']" resume_text_k.h5 \
    && pass "text axis resumed: /results/ts_type rk (6 points) then cn (6) in case order, values attribute" || fail "text axis column of the resumed file"
fi

# 6. a sampled sweep (docs/uncertainty.md): a grid axis times a sample drawn from the seed, killed,
# resumed: the same points and statistics bit for bit (a sample is a function of seed and index).
N=24
kill_resume uq_ "${base[@]}" -sweep "ball_speed=1;2,impact_x=uniform:0.05:1.05" -sweep_samples 12 -sweep_sampling lhs -sweep_seed 3
if [[ -n "$python" ]]; then
  "$python" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'r'); assert f['statistics/acor/mean'].shape == (2,) and list(f['statistics/ball_speed'][()]) == [1, 2]" resume_uq_k.h5 \
    && pass "sampled sweep resumed: /statistics per ball_speed" || fail "the resumed sampled sweep's /statistics"
fi

if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
echo "all checks passed"
