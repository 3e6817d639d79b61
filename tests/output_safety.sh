#!/usr/bin/env bash
# Nothing lost, nothing silently wrong around -output and the input files:
#   1. -output naming an input of the run (the options file, a file it includes, -beam_profile,
#      -beam_properties, -ball_cor_table) is refused by every task (impact, modes, convergence,
#      sweep), the input unchanged; so is a file of another program (a text file, another
#      program's HDF5), -output_overwrite or not; a file a running sweep holds (its lock) is not
#      replaced by another task, even with -output_overwrite.
#   2. Every results file records its input files by contents (input_sha256_<option> = the
#      SHA-256 of the bytes, input_files with the paths): an edited -ball_cor_table or
#      -beam_properties refuses a sweep's resume naming the option and the file; the same
#      contents at another path resume.
#   3. -sweep_retry_failed may change the options the failed rows name as their cause (raising
#      -impact_max_contacts after status-5 rows): the failed points are computed again and the
#      change is recorded (sweep_retry_changed); another change is still refused.
#   4. A per-point note (a pivot moved onto a node) is said once per sweep, not once per point.
#   5. scripts/plot_bat.py --sweep refuses a sweep of another beam; plot_sweep.py of a swinging
#      bat draws the batted-ball speed without the Eq. (11) curve, and refuses its acor.
#   6. -output writes only to a regular file or a new name, for every task: a character device
#      (a /dev/null twin made with mknod here, never the real one), a FIFO, a socket, a directory,
#      a symbolic link to any of them or to nothing, and any name inside a sweep's FILE.h5.parts
#      (its lock too, also through a link) are refused, left as they were, the message naming
#      what it is (and -output none where that is what was meant); a link to a results file is
#      followed (the file replaced, the link kept, a note); an empty file (directly or through a
#      link) is refused, left as the same empty file; a directory merely named *.parts is written
#      into; a sweep's file replaced by a FIFO while the sweep runs is not written over.
#
#   tests/output_safety.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: output_safety.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: output_safety.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
exe=$(readlink -f "$exe")
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
source "$src/tests/lib.sh" # MPI env, fail/pass, $python
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1

small=(-beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt 2e-6)
printf -- '-beam_nodes 21\n-options_file inner.opts\n' >outer.opts
printf -- '-ball_speed 2\n' >inner.opts
cp "$src/options/bats/r161.profile" bat.profile
cp "$src/options/bats/racket-frame.properties" frame.properties
cp "$src/options/balls/baseball-cor.txt" cor.txt

# refused WHAT EXPECTED-TEXT FILE CMD...: the command fails with the text and FILE is unchanged
refused() {
  local what=$1 text=$2 file=$3
  shift 3
  local before
  before=$(sha256sum "$file" | cut -c1-64)
  out=$("$@" 2>&1)
  local rc=$?
  if ((rc != 0)) && grep -q -- "$text" <<<"$out" && [[ $(sha256sum "$file" | cut -c1-64) == "$before" ]]; then pass "$what"
  else fail "$what: exit $rc, $file $( [[ $(sha256sum "$file" | cut -c1-64) == "$before" ]] && echo unchanged || echo CHANGED): $out"; fi
}

# --- 1. -output onto an input or a foreign file ------------------------------------------------
for task in impact modes convergence sweep; do
  extra=()
  [[ $task == sweep ]] && extra=(-sweep "impact_x=0.3;0.6")
  refused "-task $task -output onto its options file" "is an input of this run (-options_file outer.opts)" outer.opts \
    "$exe" -task $task -options_file outer.opts "${extra[@]}" -output outer.opts
  refused "-task $task -output onto an included options file" "is an input of this run (-options_file inner.opts)" inner.opts \
    "$exe" -task $task -options_file outer.opts "${extra[@]}" -output inner.opts -output_overwrite
  refused "-task $task -output onto its -beam_profile" "is an input of this run (-beam_profile bat.profile)" bat.profile \
    "$exe" -task $task -beam_profile bat.profile "${extra[@]}" -output bat.profile
  refused "-task $task -output onto its -beam_properties" "is an input of this run (-beam_properties frame.properties)" frame.properties \
    "$exe" -task $task -beam_properties frame.properties "${extra[@]}" -output frame.properties
  refused "-task $task -output onto its -ball_cor_table" "is an input of this run (-ball_cor_table cor.txt)" cor.txt \
    "$exe" -task $task -ball_law hysteresis -ball_cor_table cor.txt "${extra[@]}" -output cor.txt
done
echo "my notes" >notes.txt
if [[ -n "$python" ]]; then "$python" -c "import h5py; f = h5py.File('other.h5', 'w'); f['data'] = [1.0, 2.0]; f.attrs['task'] = 'impact'"
else cp notes.txt other.h5; fi
for task in impact modes convergence sweep; do
  extra=()
  [[ $task == sweep ]] && extra=(-sweep "impact_x=0.3;0.6")
  refused "-task $task -output onto a text file" "not an HDF5 file" notes.txt "$exe" -task $task "${small[@]}" "${extra[@]}" -output notes.txt
  refused "-task $task -output onto another program's HDF5, -output_overwrite too" "not a results file of beamimpact" other.h5 \
    "$exe" -task $task "${small[@]}" "${extra[@]}" -output other.h5 -output_overwrite
done
# an empty file (another program's lock or marker, like a sweep's own FILE.h5.parts/lock): refused
# by every task, -output_overwrite or not, directly or through a link, the file left empty (the
# same inode); impact replaced it, sweep refused it as "not an HDF5 file"
: >empty.h5
ln -s empty.h5 link_to_empty
inode=$(stat -c %i empty.h5)
for task in impact modes sweep; do
  extra=()
  [[ $task == sweep ]] && extra=(-sweep "impact_x=0.3;0.6")
  for target in empty.h5 link_to_empty; do
    refused "-task $task -output $target (an empty file): refused" "it exists and is empty, not a results file of beamimpact .*or -output none to write nothing" empty.h5 \
      "$exe" -task $task "${small[@]}" "${extra[@]}" -output $target -output_overwrite
  done
done
[[ ! -s empty.h5 && $(stat -c %i empty.h5) == "$inode" && -L link_to_empty ]] && pass "the empty file is the same empty file after the refusals" || fail "empty.h5 was replaced: $(ls -li empty.h5)"
# a directory whose name merely ends in .parts (no sweep's lock in it, no FILE beside it) is anyone's
mkdir -p mine.parts
"$exe" -task modes -beam_nodes 21 -output mine.parts/modes.h5 >mine_parts.log 2>&1 && [[ -s mine.parts/modes.h5 ]] \
  && pass "-output into a directory named mine.parts that is no sweep's: written" || fail "-output mine.parts/modes.h5: $(cat mine_parts.log)"

# a running sweep's file: no other task replaces it, -output_overwrite or not
"$exe" -task sweep "${small[@]}" -impact_after time -sweep "impact_x=0.05:1.05:40" -sweep_quiet -output locked.h5 >locked_sweep.log 2>&1 &
sweep_pid=$!
for ((i = 0; i < 300; ++i)); do [[ -e locked.h5 && -e locked.h5.parts/lock ]] && break; sleep 0.05; done
if kill -0 $sweep_pid 2>/dev/null; then
  refused "-output_overwrite does not replace a file a running sweep holds" "is being written by another sweep that is still running" locked.h5 \
    "$exe" -task modes -beam_nodes 21 -output locked.h5 -output_overwrite
else fail "the sweep ended before the lock could be tried"; fi
# ... nor a name inside its journal directory: the lock itself, a link to it, a new name there
if kill -0 $sweep_pid 2>/dev/null; then
  ln -sf locked.h5.parts/lock link_to_lock
  for target in locked.h5.parts/lock link_to_lock locked.h5.parts/new.h5; do
    out=$("$exe" -task modes -beam_nodes 21 -output $target -output_overwrite 2>&1)
    if (($? != 0)) && grep -q "it is inside .*locked.h5.parts, the journal directory of a sweep writing .*locked.h5" <<<"$out" && [[ -f locked.h5.parts/lock && ! -s locked.h5.parts/lock ]] &&
      [[ ! -e locked.h5.parts/new.h5 ]]; then pass "-output $target (inside the running sweep's .parts) is refused, the lock left as it was"
    else fail "-output $target: $out"; fi
  done
fi
kill $sweep_pid 2>/dev/null; wait $sweep_pid 2>/dev/null

# --- 6. -output only to a regular file or a new name --------------------------------------------
# kind_left NAME TEST: NAME still passes `test TEST` (-c a character device, -p a FIFO, ...)
mkfifo fifo.h5
mkdir adir
ln -s fifo.h5 link_to_fifo
ln -s adir link_to_dir
ln -s nowhere.h5 link_to_nothing
if [[ $(id -u) == 0 ]] && mknod null_twin c 1 3 2>/dev/null; then ln -s null_twin link_to_device; else echo "      (not root: no device node; the character device cases are skipped)"; fi
if [[ -n "$python" ]]; then "$python" -c "import socket; socket.socket(socket.AF_UNIX).bind('sock.h5')"; fi
flight=(-flight_series_dt 0.1)
# every kind for impact and sweep (their files are written by two writers); the device and the
# FIFO for the other tasks (the check before any work is one, RunTask's)
for task in impact sweep modes convergence flight; do
  extra=()
  [[ $task == sweep ]] && extra=(-sweep "impact_x=0.3;0.6")
  [[ $task == flight ]] && extra=("${flight[@]}")
  for case in "null_twin|-c|a character device, not a file.*Use -output none to write nothing" "fifo.h5|-p|a FIFO (named pipe), not a file.*Use -output none to write nothing" \
              "sock.h5|-S|a socket, not a file" "adir|-d|it is a directory; give a file name" "link_to_device|-L|a symbolic link to .*null_twin, a character device" \
              "link_to_fifo|-L|a symbolic link to .*fifo.h5, a FIFO" "link_to_dir|-L|a symbolic link to .*adir, a directory" "link_to_nothing|-L|a symbolic link to nothing"; do
    IFS='|' read -r target kind text <<<"$case"
    [[ -e $target || -L $target ]] || continue
    [[ $task == impact || $task == sweep || $target == null_twin || $target == fifo.h5 ]] || continue
    out=$(timeout 30 "$exe" -task $task "${extra[@]}" -output $target -output_overwrite 2>&1)
    rc=$?
    if ((rc == 1)) && grep -q -- "-output $target is not allowed: .*$text" <<<"$out" && test $kind $target && [[ ! -e null_twin || -c null_twin ]] && [[ -p fifo.h5 ]]; then
      pass "-task $task -output $target: refused, left as it was ($(grep -o 'it is [^;]*' <<<"$out" | head -1 | sed "s|$PWD/||" | cut -c1-70))"
    else fail "-task $task -output $target: exit $rc, $(ls -ld $target): $out"; fi
  done
done
ls | grep -q '\.tmp$' && fail "a temporary file was left: $(ls | grep '\.tmp$')"
# a link to a results file of this program: followed, the file replaced, the link kept
"$exe" -task modes -beam_nodes 21 -output modes_target.h5 >/dev/null 2>&1
ln -s modes_target.h5 link_to_results
before=$(sha256sum modes_target.h5 | cut -c1-64)
out=$("$exe" -task modes -beam_nodes 23 -output link_to_results 2>&1)
if (($? == 0)) && [[ -L link_to_results && $(readlink link_to_results) == modes_target.h5 ]] && [[ $(sha256sum modes_target.h5 | cut -c1-64) != "$before" ]] &&
  grep -q "note: -output link_to_results is a symbolic link: the results go to the file it names, .*modes_target.h5 (the link stays)" <<<"$out"; then
  pass "-output a link to a results file: the file replaced through it, the link kept, a note"
else fail "-output link_to_results: $(ls -l link_to_results): $out"; fi
# the check at the rename: a sweep's file replaced by a FIFO while the sweep runs is not replaced
"$exe" -task sweep "${small[@]}" -impact_after time -sweep "impact_x=0.05:1.05:40" -sweep_write_interval 0 -sweep_quiet -output swapped.h5 >swapped.log 2>&1 &
sweep_pid=$!
for ((i = 0; i < 300; ++i)); do [[ -s swapped.h5 ]] && break; sleep 0.05; done
rm -f swapped.h5 && mkfifo swapped.h5
wait $sweep_pid
rc=$?
if ((rc == 1)) && [[ -p swapped.h5 ]] && grep -q "it is now a FIFO (named pipe), not a regular file, and is not replaced); swapped.h5 is left as it is (a FIFO" swapped.log &&
  ! grep -q "there is room" swapped.log; then
  pass "a sweep's file replaced by a FIFO while it runs: the FIFO is left, the sweep stops saying why"
else fail "swapped for a FIFO: exit $rc, $(ls -ld swapped.h5): $(cat swapped.log)"; fi
rm -rf swapped.h5 swapped.h5.parts swapped.h5.tmp

# --- 2. input files by contents ----------------------------------------------------------------
"$exe" "${small[@]}" -ball_law hysteresis -ball_cor_table cor.txt -output hashed.h5 >hashed.log 2>&1 || { fail "impact with a COR table"; cat hashed.log; }
if [[ -n "$python" ]]; then
  want=$(sha256sum cor.txt | cut -c1-64)
  got=$("$python" -c "import h5py,sys; f=h5py.File('hashed.h5','r'); a=f.attrs['input_sha256_ball_cor_table']; print(a.decode() if isinstance(a, bytes) else a)")
  [[ "$got" == "$want" ]] && pass "the impact file records the COR table's SHA-256" || fail "input_sha256_ball_cor_table '$got', sha256sum $want"
fi
# a sweep over the ball's speed: the edited row (45 m/s) changes the points at 40 m/s, not the
# wall values the record keeps at the nominal speed (what a build without the hashes compared)
sweep_cor=(-task sweep "${small[@]}" -impact_after time -ball_law hysteresis -sweep "impact_x=0.3;0.9,ball_speed=1;40")
"$exe" "${sweep_cor[@]}" -ball_cor_table cor.txt -output cor_sweep.h5 >cor1.log 2>&1 || { fail "sweep with a COR table"; cat cor1.log; }
cp cor.txt cor_copy.txt
"$exe" "${sweep_cor[@]}" -ball_cor_table cor_copy.txt -output cor_sweep.h5 >cor2.log 2>&1 && grep -q "already done" cor2.log \
  && pass "the same COR table at another path: the sweep resumes" || { fail "the same table at another path was refused"; cat cor2.log; }
sed 's/^  45.0    0.500/  45.0    0.400/' cor_copy.txt >cor.txt # one row's COR changed
cmp -s cor.txt cor_copy.txt && fail "the COR table was not edited"
refused "an edited -ball_cor_table refuses the resume, naming it" "input file -ball_cor_table cor.txt: its contents changed" cor_sweep.h5 "$exe" "${sweep_cor[@]}" -ball_cor_table cor.txt -output cor_sweep.h5
# kappa G A of one row doubled (Timoshenko): no recorded scalar changes with it
sweep_props=(-task sweep -beam_properties frame.properties -beam_theory timoshenko -beam_nodes 41 -ts_type cn -ts_dt 1e-5 -impact_after time -sweep "impact_x=0.45;0.55" -sweep_quiet)
"$exe" "${sweep_props[@]}" -output props_sweep.h5 >props1.log 2>&1 || { fail "sweep with -beam_properties"; cat props1.log; }
cp frame.properties frame_copy.properties
awk '!done && $1 ~ /^[0-9]/ && NF >= 4 { $4 = $4 * 2; done = 1 } 1' frame_copy.properties >frame.properties
refused "an edited -beam_properties (kappa G A) refuses the resume, naming it" "input file -beam_properties frame.properties: its contents changed" props_sweep.h5 "$exe" "${sweep_props[@]}" -output props_sweep.h5

# --- 3. -sweep_retry_failed may change what the failures name ---------------------------------
double=(-task sweep -beam_length 0.3 -beam_left clamped -beam_youngs_modulus 7e10 -beam_density 2700 -beam_thickness 0.006 -beam_width 0.032 -beam_nodes 41
        -ball_mass 0.042 -ball_speed 1 -ball_law linear -ball_k 2e4 -ts_type cn -ts_dt 1e-5 -impact_after time -sweep "impact_x=0.2;0.25;0.29" -sweep_quiet)
"$exe" "${double[@]}" -impact_max_contacts 1 -output retry.h5 >retry1.log 2>&1
rc=$?
grep -q "status 5" retry1.log && ((rc == 2)) && pass "double impacts with -impact_max_contacts 1: status-5 rows (exit 2)" || { fail "no status-5 rows (exit $rc)"; cat retry1.log; }
refused "-sweep_retry_failed with another option changed is refused" "different parameters" retry.h5 "$exe" "${double[@]}" -impact_max_contacts 5 -ball_speed 2 -sweep_retry_failed -output retry.h5
"$exe" "${double[@]}" -impact_max_contacts 5 -sweep_retry_failed -output retry.h5 >retry2.log 2>&1
rc=$?
if ((rc == 0)) && [[ -n "$python" ]]; then
  "$python" - <<'PY' && pass "-sweep_retry_failed after raising -impact_max_contacts: every point ok, the change recorded" || fail "retry: rows or record wrong"
import h5py
f = h5py.File("retry.h5", "r")
st = f["results/status"][()]
ch = f.attrs["sweep_retry_changed"]
ch = ch.decode() if isinstance(ch, bytes) else ch
print("      status", list(st), "| sweep_retry_changed:", ch)
assert (st == 0).all() and "-impact_max_contacts 1 -> 5" in ch
PY
else fail "retry after raising -impact_max_contacts: exit $rc"; cat retry2.log; fi

# --- 4. notes once per sweep --------------------------------------------------------------------
"$exe" -task sweep "${small[@]}" -beam_pivot 0.5 -impact_after time -sweep "impact_x=0.6:1.0:21" -output pivot.h5 >pivot.log 2>&1 || { fail "pivot sweep"; cat pivot.log; }
n=$(grep -c "beam_pivot 0.5 is placed on the nearest node" pivot.log)
((n == 1)) && pass "the pivot note is said once in a 21-point sweep" || { fail "the pivot note is said $n times"; grep note pivot.log | head -5; }

# --- 5. plot scripts check what they are given -------------------------------------------------
if [[ -n "$python" ]]; then
  bat=(-options_file "$src/options/bats/r161.opts" -beam_nodes 41)
  "$exe" -task modes "${bat[@]}" -output bat_modes.h5 >/dev/null 2>&1 || fail "modes of the bat"
  "$exe" -task sweep "${small[@]}" -impact_after time -sweep "impact_x=0.6:1.0:3" -sweep_quiet -output beam_sweep.h5 >/dev/null 2>&1 || fail "sweep of a uniform beam"
  swing=("${bat[@]}" -options_file "$src/options/balls/baseball.opts" -options_file "$src/options/integrators/rk4.opts" -bat_speed 24 -bat_angular_velocity 51 -ball_speed 40 -impact_after time)
  "$exe" -task sweep "${swing[@]}" -sweep "impact_x=0.6:0.8:3" -sweep_quiet -output swing_sweep.h5 >swing.log 2>&1 || { fail "sweep of the swinging bat"; tail -3 swing.log; }
  out=$("$python" "$src/scripts/plot_bat.py" bat_modes.h5 --sweep beam_sweep.h5 -o other.png 2>&1)
  (($? != 0)) && grep -q "is a sweep of another beam than bat_modes.h5" <<<"$out" && [[ ! -e other.png ]] && pass "plot_bat.py --sweep refuses a sweep of another beam" ||
    fail "plot_bat.py --sweep of another beam: $out"
  out=$("$python" "$src/scripts/plot_bat.py" bat_modes.h5 --sweep swing_sweep.h5 -o same.png 2>&1)
  (($? == 0)) && [[ -s same.png ]] && grep -q "sweet spot" <<<"$out" && pass "plot_bat.py --sweep of the same bat draws its sweet spots" || fail "plot_bat.py --sweep of the same bat: $out"
  out=$("$python" "$src/scripts/plot_sweep.py" swing_sweep.h5 -o swing.png 2>&1)
  (($? == 0)) && grep -q "drawing bbs" <<<"$out" && grep -q "Eq. (11) curve: not an ACOR plot" <<<"$out" && [[ -s swing.png ]] &&
    pass "plot_sweep.py of a swinging sweep draws the batted-ball speed, no Eq. (11) curve" || fail "plot_sweep.py of a swinging sweep: $out"
  out=$("$python" "$src/scripts/plot_sweep.py" swing_sweep.h5 acor -o swing_acor.png 2>&1)
  (($? != 0)) && grep -q "not the ACOR of a bat at rest" <<<"$out" && pass "plot_sweep.py refuses the acor of a swinging bat" || fail "plot_sweep.py acor of a swinging bat: $out"
else
  skip "plot scripts: no Python with h5py"
fi

echo "output_safety: $fails failure(s)"
exit $((fails > 0))
