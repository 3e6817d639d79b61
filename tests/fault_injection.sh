#!/usr/bin/env bash
# Faults while results are written: nothing lost, nothing half-written, no crash.
#   1. A full disk during an impact, a modes run and a sweep: a 400 kB tmpfs made here (root, as
#      in CI), else an LD_PRELOAD (tests/enospc_preload.c) that makes writes under a directory
#      fail with ENOSPC (an impact with snapshots: also once its XDMF description is written and
#      the file is not). Each run ends with an error naming -output and "disk full", exit status
#      1 (no signal: no crash at PetscFinalize), no "wrote", no temporary file left, and the
#      file of an earlier run at that path unchanged. The sweep, given room again, resumes and
#      its file equals an uninterrupted run's. A sweep on 2 ranks whose first write fails says
#      that no point had been computed, names no FILE.h5.parts (the failed run removes it) and
#      ends every rank with that one message (it ended in MPI_ABORT and ORTE_ERROR_LOG); one
#      whose rewrite fails later stops every rank with one message saying truly where the rows
#      are (how many the journals keep, how many are in none: a resume finds exactly F's and the
#      journals' rows done).
#   2. kill -9 at random moments of a sweep that rewrites its file after every point, 20
#      times (every fifth under mpiexec on 2 ranks): after each kill the file is absent or a
#      complete HDF5 file (its rows and sweep_cases_done agree); the last resume completes it,
#      every row bit-identical to an uninterrupted run's.
#   3. An error under mpirun on 2 ranks (bad input on every rank; a failed write on rank 0
#      only): one "beamimpact: error:" line, exit status 1, no MPI_Abort/ORTE noise.
#
#   tests/fault_injection.sh path/to/beamimpact scratch_dir [mpiexec] [enospc_preload.so]
set -uo pipefail

exe=${1:?usage: fault_injection.sh beamimpact scratch_dir [mpiexec] [enospc_preload.so]}
dir=${2:?usage: fault_injection.sh beamimpact scratch_dir [mpiexec] [enospc_preload.so]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
preload=${4:-}
exe=$(readlink -f "$exe")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
[[ -z "$preload" ]] || preload=$(readlink -f "$preload")
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" # MPI env, fail/pass, $python
full=$dir/full
mountpoint -q "$full" 2>/dev/null && umount "$full"
rm -rf "$dir" && mkdir -p "$full" && cd "$dir" || exit 1

# --- 1. a full disk --------------------------------------------------------------------------
mode=""
if [[ $(id -u) == 0 ]] && mount -t tmpfs -o size=400k tmpfs "$full" 2>/dev/null; then
  mode=tmpfs
  lib_exit_trap 'cd /; umount "$full" 2>/dev/null'
  echo "      disk full: a 400 kB tmpfs at $full"
elif [[ -n "$preload" && -f "$preload" ]]; then
  mode=preload
  echo "      disk full: no tmpfs can be mounted here (not root?): writes under $full fail with ENOSPC by LD_PRELOAD=$preload"
else
  skip "disk full: neither a tmpfs can be mounted (not root) nor an LD_PRELOAD library was given"
fi

# room KB: about KB kilobytes free in $full from now on
room() {
  if [[ $mode == tmpfs ]]; then
    rm -f "$full/filler"
    dd if=/dev/zero of="$full/filler" bs=1k count=400 2>/dev/null
    truncate -s "-$1K" "$full/filler"
  else
    export ENOSPC_BYTES=$(($1 * 1024))
  fi
}
# full_run LOG ARGS...: the executable (or "$mpiexec -n 2" when ARGS start with -np2) on the full disk
full_run() {
  local log=$1 launch=("$exe")
  shift
  if [[ $1 == -np2 ]]; then launch=("$mpiexec" -n 2 "$exe"); shift; fi
  if [[ $mode == preload ]]; then env LD_PRELOAD="$preload" ENOSPC_DIR="$full" ENOSPC_BYTES="$ENOSPC_BYTES" "${launch[@]}" "$@" >"$log" 2>&1
  else "${launch[@]}" "$@" >"$log" 2>&1; fi
}
# refused_cleanly WHAT LOG RC FILE: the run failed as a full disk should make it fail
refused_cleanly() {
  local what=$1 log=$2 rc=$3 file=$4 ok=1
  ((rc != 0)) || { fail "$what: exit 0 on a full disk"; ok=0; }
  ((rc < 128)) || { fail "$what: killed by a signal (exit $rc)"; ok=0; }
  grep -qiE "segmentation|signal|SIGSEGV|core dumped" "$log" && { fail "$what: a crash"; ok=0; }
  grep -q "^wrote " "$log" && { fail "$what: says 'wrote' though the write failed"; ok=0; }
  grep -q "disk full" "$log" && grep -q -- "$file" "$log" || { fail "$what: the error does not name $file and a full disk"; ok=0; }
  ls "$full" | grep -q '\.tmp$' && { fail "$what: a temporary file is left: $(ls "$full" | grep '\.tmp$')"; ok=0; }
  ((ok)) && pass "$what: refused cleanly ($(grep -m1 'error' "$log" | cut -c1-150))"
  ((ok)) || grep -v '^ ' "$log" | tail -15
}

small=(-beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2e-6)
if [[ -n $mode ]]; then
  # impact: an earlier file at the path stays as it was; a large series makes the file too big
  "$exe" "${small[@]}" -output impact_old.h5 >impact_old.log 2>&1 || { fail "impact reference run"; cat impact_old.log; }
  room 180 && rm -f "$full/filler" && cp impact_old.h5 "$full/impact.h5"
  room 6
  full_run impact_full.log "${small[@]}" -monitor_energy -monitor_ball -snapshot_times 1e-5,2e-5,3e-5,4e-5,5e-5,6e-5,7e-5,8e-5 -output "$full/impact.h5"
  refused_cleanly "impact on a full disk" impact_full.log $? "$full/impact.h5"
  cmp -s impact_old.h5 "$full/impact.h5" && pass "impact: the earlier file is unchanged" || fail "impact: the earlier file was changed"
  [[ -e "$full/impact.xmf" ]] && fail "impact: its snapshots' description impact.xmf was left" || pass "impact: no impact.xmf left"
  rm -f "$full/impact.h5"
  # the snapshots' description (7 kB, written first) fits, the file does not: neither is installed,
  # the description there before is unchanged
  printf '<?xml version="1.0" ?>\n<!-- Written by beamimpact: an earlier description -->\n' >"$full/impact.xmf"
  cp "$full/impact.xmf" impact_old.xmf
  room 12
  full_run impact_xmf.log "${small[@]}" -monitor_energy -monitor_ball -snapshot_times 1e-5,2e-5,3e-5,4e-5,5e-5,6e-5,7e-5,8e-5 -output "$full/impact.h5"
  refused_cleanly "impact on a full disk after its description" impact_xmf.log $? "$full/impact.h5"
  cmp -s impact_old.xmf "$full/impact.xmf" && [[ ! -e "$full/impact.h5" ]] && pass "impact: the earlier impact.xmf unchanged, no impact.h5" ||
    fail "impact: impact.xmf changed or impact.h5 written: $(ls "$full")"
  rm -f "$full/impact.xmf"
  # modes: no file before: none after
  room 4
  full_run modes_full.log -task modes -beam_nodes 401 -modes_count 30 -output "$full/modes.h5"
  refused_cleanly "modes on a full disk" modes_full.log $? "$full/modes.h5"
  [[ -e "$full/modes.h5" ]] && fail "modes: a file was left" || pass "modes: no file left"
  # the same write failure on rank 0 of 2: every rank ends, one message
  room 4
  full_run modes_np2.log -np2 -task modes -beam_nodes 401 -modes_count 30 -output "$full/modes.h5"
  rc=$?
  refused_cleanly "modes on a full disk, 2 ranks" modes_np2.log $rc "$full/modes.h5"
  grep -qE "MPI_ABORT|unpack would read|Data unpack" modes_np2.log && fail "2 ranks: MPI_Abort noise: $(cat modes_np2.log)"
  # sweep: fails on the full disk, resumes once there is room, equals an uninterrupted run
  sweep=(-task sweep "${small[@]}" -impact_after time -rigid_loss_fraction 0.2 -sweep "impact_x=0.1:1:10" -sweep_quiet)
  "$exe" "${sweep[@]}" -output sweep_ref.h5 >sweep_ref.log 2>&1 || { fail "reference sweep"; cat sweep_ref.log; }
  room 12
  full_run sweep_full.log "${sweep[@]}" -sweep_write_interval 0 -output "$full/sweep.h5"
  rc=$?
  ((rc != 0 && rc < 128)) && grep -q "disk full" sweep_full.log && ! ls "$full" | grep -q '\.tmp$' && pass "sweep on a full disk: an error, no crash, no .tmp ($(grep -m1 error sweep_full.log | cut -c1-120))" ||
    { fail "sweep on a full disk: exit $rc"; cat sweep_full.log; ls -la "$full"; }
  # the first write fails on 2 ranks: one message, every rank ends, nothing named that is not there
  room 4
  full_run sweep_first.log -np2 "${sweep[@]}" -output "$full/first.h5"
  rc=$?
  if ((rc == 1)) && grep -q "beamimpact: error: -output $full/first.h5: writing it failed (disk full: .*); nothing was written at $full/first.h5; no point had been computed" sweep_first.log &&
    ! grep -qE "MPI_ABORT|ORTE_ERROR_LOG|\.parts" sweep_first.log && [[ ! -e $full/first.h5.parts && ! -e $full/first.h5 ]] && [[ $(grep -c "beamimpact: error" sweep_first.log) == 1 ]]; then
    pass "a sweep's first write on a full disk, 2 ranks: one message, no point lost, no MPI_ABORT"
  else fail "a sweep's first write on a full disk, 2 ranks: exit $rc: $(cat sweep_first.log)"; ls -la "$full"; fi
  # a later rewrite fails on 2 ranks: no further point handed out, every rank ends, one message,
  # and what it says is where the rows are is true: F's rows and the journals' (K kept) are what a
  # resume finds done, the L it says are in neither are computed again (the journals fail on this
  # disk too: it said "the journals in F.parts keep the rows" of journals that held none)
  # room for the first write (the file without its rows: nearly the whole file, whose 10 rows are
  # a few kB) and not for a rewrite's temporary file beside it (a second whole file): 1.5 times the
  # reference file, which keeps half a file of margin on both sides whatever columns the table
  # grows (a fixed 80 kB, then the file less 4 kB, each failed once columns were added)
  room $(($(stat -c %s sweep_ref.h5) * 3 / 2 / 1024))
  full_run sweep_later.log -np2 "${sweep[@]}" -sweep_write_interval 0 -output "$full/later.h5"
  rc=$?
  msg=$(grep "beamimpact: error: -output $full/later.h5: writing it failed (disk full: " sweep_later.log)
  kept=$(sed -nE 's/.* ([0-9]+) row\(s\) not in it are kept by the journal\(s\) in .*later.h5.parts for a resume.*/\1/p' <<<"$msg")
  lost=$(sed -nE 's/.* ([0-9]+) row\(s\) computed are neither in it nor in a journal .*/\1/p' <<<"$msg")
  in_file=0
  [[ -e $full/later.h5 && -n $python ]] && in_file=$("$python" -c "import h5py, sys; print(len(h5py.File(sys.argv[1], 'r')['results/case_index']))" "$full/later.h5")
  if ((rc == 1)) && [[ -n $msg && -n $kept$lost ]] && ! grep -qE "MPI_ABORT|ORTE_ERROR_LOG" sweep_later.log && [[ $(grep -c "beamimpact: error" sweep_later.log) == 1 ]]; then
    pass "a sweep's later rewrite on a full disk, 2 ranks: one message (F holds $in_file rows, ${kept:-0} in journals, ${lost:-0} lost), no MPI_ABORT"
  else fail "a sweep's later rewrite on a full disk, 2 ranks: exit $rc: $(cat sweep_later.log)"; ls -la "$full"; fi
  rm -f "$full/filler"
  "$exe" "${sweep[@]}" -sweep_quiet false -output "$full/later.h5" >sweep_later_resumed.log 2>&1
  done_before=$(sed -nE 's/^sweep: computed ([0-9]+) points .*, ([0-9]+) already done$/\2/p' sweep_later_resumed.log)
  # (a point a rank was finishing when the write failed is journaled after the message's count:
  # the resume finds at least the rows the message names, never fewer)
  if [[ -n $done_before ]] && ((done_before >= in_file + ${kept:-0} && done_before <= 10 && in_file + ${kept:-0} + ${lost:-0} <= 10)); then
    pass "... and it was true: the resume found $done_before rows done (F's $in_file + the journals' ${kept:-0}, at least), computed the rest"
  else fail "the message's account: F $in_file + kept ${kept:-0} (lost ${lost:-0}), the resume found '$done_before' done: $msg / $(grep -E 'computed|error' sweep_later_resumed.log)"; fi
  rm -rf "$full/later.h5" "$full/later.h5.parts"
  # given room (the file and its journals moved to a larger disk: the sweep's file alone is
  # near the tmpfs's size), the same command resumes and completes it
  rm -f "$full/filler"
  mv "$full/sweep.h5.parts" sweep_full.h5.parts 2>/dev/null
  [[ -e "$full/sweep.h5" ]] && mv "$full/sweep.h5" sweep_full.h5
  "$exe" "${sweep[@]}" -output sweep_full.h5 >sweep_resumed.log 2>&1 && pass "the sweep resumes once there is room ($(grep -m1 -o 'resuming.*' sweep_resumed.log || echo 'nothing was kept'))" ||
    { fail "sweep resume after the full disk"; tail -5 sweep_resumed.log; }
fi

# same_rows A B: every /results and /sweep dataset of A equals B's bit for bit (wall_time apart)
same_rows() {
  [[ -n "$python" ]] || { h5diff -d 0 --exclude-path /results/wall_time "$1" "$2" >/dev/null; return; }
  "$python" - "$1" "$2" <<'PY'
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = [f"{g}/{k}" for g in ("results", "sweep") for k in set(a[g]) | set(b[g])
       if k != "wall_time" and (k not in a[g] or k not in b[g] or a[g][k].shape != b[g][k].shape
                                or not np.array_equal(a[g][k][()], b[g][k][()], equal_nan=a[g][k].dtype.kind == "f"))]
print(" ".join(bad)); sys.exit(1 if bad else 0)
PY
}
[[ -n $mode && -f sweep_full.h5 ]] && { same_rows sweep_ref.h5 sweep_full.h5 && pass "resumed after the full disk: identical to the uninterrupted sweep" || fail "resumed after the full disk: rows differ"; }
if [[ $mode == tmpfs ]]; then cd "$dir" && umount "$full"; lib_exit_trap :; fi

# --- 2. kill -9 at random moments of the writes ----------------------------------------------
complete_or_absent() {
  [[ -e "$1" ]] || return 0
  [[ -n "$python" ]] || { h5dump -A "$1" >/dev/null 2>&1; return; }
  "$python" - "$1" <<'PY'
import sys, h5py
f = h5py.File(sys.argv[1], "r")
n = {len(f["results"][k]) for k in f["results"]}
assert len(n) == 1 and n.pop() == int(f.attrs["sweep_cases_done"]), "rows and sweep_cases_done disagree"
PY
}
kill_sweep=(-task sweep "${small[@]}" -impact_after time -rigid_loss_fraction 0.2 -sweep "impact_x=0.05:1.05:16,ball_speed=1;2" -sweep_write_interval 0 -sweep_quiet)
"$exe" "${kill_sweep[@]}" -output kill_ref.h5 >kill_ref.log 2>&1 || { fail "reference sweep for the kills"; cat kill_ref.log; }
bad=0 partial=0
for ((k = 1; k <= 20; ++k)); do
  if ((k % 5 == 0)); then setsid "$mpiexec" -n 2 "$exe" "${kill_sweep[@]}" -output kill.h5 >kill_$k.log 2>&1 &
  else setsid "$exe" "${kill_sweep[@]}" -output kill.h5 >kill_$k.log 2>&1 & fi
  launcher=$!
  sleep "$(awk -v s=$RANDOM 'BEGIN { srand(s); printf "%.3f", 0.15 + 1.2 * rand() }')"
  ranks=$(descendants "$launcher" | tr '\n' ' ')
  kill -9 "$launcher" $ranks 2>/dev/null
  wait "$launcher" 2>/dev/null
  sleep 0.1
  complete_or_absent kill.h5 || { bad=$((bad + 1)); echo "      kill $k: kill.h5 is neither complete nor absent"; }
  [[ -e kill.h5 ]] && ((partial += 1))
done
((bad == 0)) && pass "20 kills -9 during the sweep's rewrites: the file was complete or absent after each ($partial times present)" || fail "$bad of 20 kills left a file that is not complete"
"$exe" "${kill_sweep[@]}" -output kill.h5 >kill_final.log 2>&1 || { fail "the resume after the kills failed"; cat kill_final.log; }
same_rows kill_ref.h5 kill.h5 && pass "resumed after 20 kills: every row bit-identical to the uninterrupted sweep" || fail "resumed after the kills: rows differ"
ls | grep -q '^kill.h5.tmp$' && fail "kill.h5.tmp left after the completed resume"
[[ -d kill.h5.parts ]] && fail "kill.h5.parts left after the completed resume"

# --- 3. an error under mpirun: one line, exit 1 ----------------------------------------------
# Every rank fails alike (bad input): they agree, end through SlepcFinalize, no MPI_Abort.
# Open MPI's own exit-status notice is left out with OMPI_MCA_orte_execute_quiet=1 (mpirun -q):
# then stderr is the one line.
"$mpiexec" -n 2 "$exe" -beam_length -1 -output none >np2_error.log 2>&1
rc=$?
lines=$(grep -c "beamimpact: error" np2_error.log)
if ((rc == 1 && lines == 1)) && ! grep -qE "MPI_ABORT|Data unpack|unpack would read" np2_error.log; then pass "an error on 2 ranks: one error line, exit 1, no MPI_Abort"
else fail "an error on 2 ranks: exit $rc, $lines error lines:"; cat np2_error.log; fi
OMPI_MCA_orte_execute_quiet=1 "$mpiexec" -n 2 "$exe" -beam_length -1 -output none >np2_quiet.log 2>&1
rc=$?
if ((rc == 1)) && [[ $(wc -l <np2_quiet.log) == 1 ]] && grep -q "^beamimpact: error: -beam_length -1 is not allowed" np2_quiet.log; then pass "... with mpirun -q: that one line is all"
else fail "an error on 2 ranks with mpirun -q: exit $rc:"; cat np2_quiet.log; fi

echo "fault_injection: $fails failure(s)"
exit $((fails > 0))
