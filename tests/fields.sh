#!/usr/bin/env bash
# The fields for ParaView and xarray (issue 35) through the real executable:
#   * the XDMF description written beside each impact file with snapshots (out.xmf for out.h5):
#     the beam's snapshots (options/scenes/snapshots.opts), the racket's string bed
#     (racket-strings.opts) and the barrel wall's harmonics (the aluminium bat with -beam_shell);
#     parsed with xml.etree, every DataItem names a dataset of the .h5 beside it (by relative
#     name) with the declared dimensions and type, every grid's time is /snapshots/time's and its
#     part of the dataset it reads is that snapshot's row (tests/fields_check.py xdmf);
#   * the wall's W_n under the ball (a point load at a node) against the run's own measure
#     wall_deflection_peak, taken over every step by another path (run/measures.cpp);
#   * every group of an impact, a sweep, a flight, a modes, a string bed's modes and a convergence
#     file opened by xarray with h5netcdf without phony dimensions, units on every numeric
#     variable, and the coordinates' values (the snapshot times asked for, the nodes, the sweep's
#     cases, the flight's sampling) from the inputs (fields_check.py xarray);
#   * the .xmf made safe as the .h5 is: a file of another program there refuses the run before
#     any work (and a directory), one of ours is replaced, or removed when the file it described
#     is replaced by one without snapshots; -output none writes neither; a run without snapshots
#     leaves another program's .xmf alone.
#
#   tests/fields.sh path/to/beamimpact scratch_dir
# Needs a Python with h5py, numpy, xarray and h5netcdf (Debian: python3-h5py python3-xarray
# python3-h5netcdf); without them the Python checks are skipped and the test exits 77 (a skip
# CTest counts: SKIP_RETURN_CODE) after the shell checks, never a silent pass.
set -uo pipefail

exe=${1:?usage: fields.sh beamimpact scratch_dir}
dir=${2:?usage: fields.sh beamimpact scratch_dir}
exe=$(readlink -f "$exe")
[[ -x $exe ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && dir=$(readlink -f "$dir")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
rm -rf "${dir:?}"/*
source tests/lib.sh # MPI env, fail/pass, $python
root=$(pwd)

check=""
if [[ -n $python ]] && "$python" -c "import xarray, h5netcdf" 2>/dev/null; then check="$python tests/fields_check.py"
else echo "SKIP: the Python checks need h5py, numpy, xarray and h5netcdf (Debian: apt-get install python3-xarray python3-h5netcdf)"; fi
# py WORDS...: a fields_check.py check, run with the others at the end (one Python: xarray's import is slow)
checks=()
py() { checks+=("$*"); }

# run NAME [options...]: beamimpact into $dir/NAME.h5 (log $dir/NAME.log)
run() {
  local name=$1 rc
  shift
  "$exe" "$@" -output "$dir/$name.h5" >"$dir/$name.log" 2>&1
  rc=$?
  if [[ $rc -eq 0 && -f $dir/$name.h5 ]]; then pass "$name runs"; return 0; fi
  fail "$name: beamimpact $* (exit $rc)"
  tail -5 "$dir/$name.log" | sed 's/^/      /'
  return 1
}
t0=$SECONDS

# --- the XDMF of the beam, the bed and the wall ---------------------------------------------------
times=0.001,0.003,0.005
run beam -options_file options/scenes/snapshots.opts -beam_nodes 41 -snapshot_times $times -monitor_ball -monitor_velocity_at 0.2,0.5 &&
  py xdmf "$dir/beam.xmf" "$dir/beam.h5" beam
run bed -options_file options/scenes/racket-strings.opts -snapshot_times 0,0.0015,0.003 &&
  py xdmf "$dir/bed.xmf" "$dir/bed.h5" beam bed
wall_times=$(seq -f '%.5f' 0 0.00002 0.0008 | paste -sd,) # through the contact (0.8 ms)
if run wall -options_file options/bats/aluminium-bat.opts -options_file options/balls/baseball.opts -options_file options/integrators/rk4.opts \
  -beam_shell -shell_contact_radius 0 -beam_nodes 41 -impact_after time -ball_speed 40 -impact_x 0.63 -impact_window 1e-5 -snapshot_times "$wall_times"; then
  py xdmf "$dir/wall.xmf" "$dir/wall.h5" beam wall
  py wall "$dir/wall.h5" 0.63
fi

# --- xarray: every group of every kind of file ----------------------------------------------------------
[[ -f $dir/beam.h5 ]] && py xarray "$dir/beam.h5" impact $times 0.2,0.5
run sweep -task sweep -beam_nodes 21 -sweep "impact_x=0.3:0.9:4,ball_speed=1;2" -sweep_quiet && py xarray "$dir/sweep.h5" sweep 0.3,0.3,0.5,0.5,0.7,0.7,0.9,0.9
run flight -task flight && py xarray "$dir/flight.h5" flight
run modes -task modes -options_file options/bats/r161.opts -beam_nodes 41 && py xarray "$dir/modes.h5" modes
run racket_modes -task modes -options_file options/base/racket-strung.opts && py xarray "$dir/racket_modes.h5" modes
run strings -options_file options/scenes/strings-modes.opts && py xarray "$dir/strings.h5" other
run convergence -task convergence -beam_nodes 21 -convergence_configs options/convergence/rk4.opts -convergence_repeats 1 -convergence_spatial_nodes 11,21,41 &&
  py xarray "$dir/convergence.h5" other
for f in sweep flight modes strings convergence; do
  [[ -e $dir/$f.xmf ]] && fail "$f.xmf written for a file without snapshots"
done

# --- the .xmf made safe as the .h5 ------------------------------------------------------------------
plain=(-options_file "$root/options/impact.opts" -beam_nodes 21)
snap=("${plain[@]}" -snapshot_times 0.001)
cd "$dir" || exit 1
printf 'notes of mine\n' >own.xmf
out=$("$exe" "${snap[@]}" -output own.h5 2>&1)
rc=$?
[[ $rc -ne 0 && ! -e own.h5 && $(cat own.xmf) == "notes of mine" ]] && grep -q "would replace own.xmf, which exists and is not an XDMF file of beamimpact" <<<"$out" &&
  ! grep -q "acor" <<<"$out" && pass "another program's own.xmf: the run refused before any work, nothing written: $(grep -m1 error <<<"$out" | cut -c1-150)" ||
  fail "another program's .xmf: exit $rc, own.h5 $([[ -e own.h5 ]] && echo written || echo absent): $out"
out=$("$exe" "${plain[@]}" -output own.h5 2>&1)
[[ $? -eq 0 && -e own.h5 && $(cat own.xmf) == "notes of mine" ]] && pass "a run without snapshots leaves another program's own.xmf alone" ||
  fail "run without snapshots beside another program's .xmf: $out"
mkdir -p dir.xmf
out=$("$exe" "${snap[@]}" -output dir.h5 2>&1)
[[ $? -ne 0 && ! -e dir.h5 ]] && grep -q "dir.xmf, which is a directory" <<<"$out" && pass "a directory at dir.xmf: refused" || fail "a directory at the .xmf: $out"
for k in 1 2; do # ours is replaced by the next run's
  "$exe" "${snap[@]}" -snapshot_times 0.00$k -output ours.h5 >/dev/null 2>&1 || fail "snapshots run $k into ours.h5"
done
grep -q 'Time Value="0.002"' ours.xmf && ! grep -q 'Time Value="0.001"' ours.xmf && pass "ours.xmf replaced by the next run's" || fail "ours.xmf not replaced: $(grep Time ours.xmf)"
"$exe" "${plain[@]}" -output ours.h5 >/dev/null 2>&1 || fail "run without snapshots into ours.h5"
[[ ! -e ours.xmf ]] && pass "ours.xmf removed with the file it described (the new ours.h5 has no snapshots)" || fail "a stale ours.xmf is left"
mkdir -p none && cd none && "$exe" "${snap[@]}" -output none >/dev/null 2>&1 && [[ -z $(ls) ]] && pass "-output none: neither .h5 nor .xmf" ||
  fail "-output none wrote: $(ls)"
cd "$dir" && [[ -z $(ls | grep '\.tmp$') ]] && pass "no temporary file left" || fail "temporary files left: $(ls | grep '\.tmp$')"
cd "$root" || exit 1
if [[ -n $check ]]; then $check "${checks[@]}" || fail "tests/fields_check.py (the FAIL lines above)"; fi

echo "fields.sh: $((SECONDS - t0)) s"
if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
[[ -n $check ]] || exit 77
echo "all checks passed"
