#!/usr/bin/env bash
# Issue 22's silently-wrong and refused inputs, through the real executable: each case failed
# (or was silent) before and passes now.
#   * options that have no effect in the run are a note, once (also in a sweep); a sweep axis
#     over such an option is refused before any point runs; a racket's (issue 34): the bed's and
#     the head's options without a bed, the frame's own in a held frame, -strings_nodes on a
#     beam frame; -flight after a tennis ball's hit notes the baseball's aerodynamics;
#   * section files: rows that do not start at x = 0 are shifted with a note; a file far outside
#     any bat (a profile in centimetres) is a warning naming the file, the values and the units;
#     a NUL byte in an options file, a profile or a COR table is refused naming file and line;
#     a UTF-8 byte order mark at the start and CR-only (classic Mac) or CR LF line ends are read:
#     the same numbers as the plain file (it was "'<BOM>-impact_x' is not an option", "the file has
#     no rows"); a UTF-16 file is refused naming its encoding;
#   * a sweep's messages: every point off a racket's face says so (it said "off the beam or held
#     fixed"); an axis over an option of another task names it (it said "not an option of this
#     program"); a failed row quotes the value as written (-0.1, not -0.10000000000000001);
#     a -beam_clamp edge between nodes is a note with the held region's ends;
#   * explicit RK under strong Rayleigh damping runs at its computed limit (it was "-ts_dt 0 is
#     not allowed"), and a fixed step 1% above that limit is refused;
#   * -ts_type irk runs (it was "No method missingdiagonal for Mat of type seqkaij") and agrees
#     with the exact modal reference;
#   * a ball at rest struck by a swinging bat runs: BBS and q reported, ACOR NaN in the file;
#   * the bare default run gives no resolution warning, and its ACOR agrees with the exact
#     modal reference to 1e-5.
#
#   tests/cli_inputs.sh path/to/beamimpact scratch_dir
set -uo pipefail
exe=${1:?usage: cli_inputs.sh beamimpact scratch_dir}
dir=${2:?usage: cli_inputs.sh beamimpact scratch_dir}
source "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.." || exit 2
rm -rf "$dir" && mkdir -p "$dir"
field() { sed -nE "s/.* $1 ([-0-9.e+naif]+).*/\1/p" <<<"$out" | head -1; }
run() { out=$("$exe" "$@" 2>&1); rc=$?; }
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }

# --- options without effect ------------------------------------------------------------------
run -grip_stiffness 1e4 -monitor_grip -beam_shear_modulus 1e9 -monitor_segment_until 1e-3 -output none
if [[ $rc -eq 0 ]] && grep -q "note: option(s) with no effect in this run: .*-grip_stiffness 1e4 (it acts only with -grip)" <<<"$out" &&
   grep -q -- "-beam_shear_modulus 1e9 (it acts only with -beam_theory timoshenko; -beam_theory is euler)" <<<"$out" &&
   grep -q -- "-monitor_grip (it acts only with -grip)" <<<"$out" && grep -q -- "-monitor_segment_until 1e-3 (it acts only with -monitor_segment)" <<<"$out"; then
  pass "options without effect: one note naming each with its reason"
else fail "options without effect: exit $rc: $out"; fi
run -grip 0.05,0.2 -grip_stiffness 1e4 -beam_theory timoshenko -beam_shear_modulus 2.6e10 -output none
if [[ $rc -eq 0 ]] && ! grep -q "no effect" <<<"$out"; then pass "with what they need, no note"; else fail "needed options: exit $rc: $out"; fi
run -task sweep -sweep "grip_stiffness=0;1e4;1e5" -output "$dir/grip.h5"
if [[ $rc -ne 0 ]] && grep -q -- "-sweep grip_stiffness=0;1e4;1e5 is not allowed: -grip_stiffness has no effect in this sweep (it acts only with -grip), so every point would be the same" <<<"$out" &&
   ! grep -q "^wrote" <<<"$out"; then
  pass "a sweep axis over an option without effect is refused before any point"
else fail "sweep over grip_stiffness without -grip: exit $rc: $out"; fi
run -task sweep -sweep "beam_theory=euler;timoshenko,beam_shear_modulus=2e10;2.6e10" -impact_window 1e-3 -output "$dir/theory.h5"
if [[ $rc -eq 0 ]] && grep -q "^wrote .*(4 points)" <<<"$out"; then pass "an axis whose condition another axis varies runs (beam_shear_modulus with beam_theory)"
else fail "sweep over beam_theory x beam_shear_modulus: exit $rc: $out"; fi
run -task sweep -sweep_x 0.3:0.9:7 -beam_pivot 0.5 -beam_nodes 40 -grip_mass 1 -impact_window 1e-3 -output "$dir/pivot.h5"
if [[ $rc -eq 0 ]] && [[ $(grep -c "note: -beam_pivot 0.5 is placed on the nearest node" <<<"$out") -eq 1 ]] && [[ $(grep -c "no effect in this run" <<<"$out") -eq 1 ]]; then
  pass "a 7-point sweep says the pivot note and the no-effect note once each"
else fail "notes once per sweep: exit $rc: $(grep -c "nearest node" <<<"$out") pivot notes: $out"; fi
# issue 34: a racket's options that change nothing in its frame are notes; a sweep over one refused
run -options_file options/scenes/racket-strings.opts -strings_frame none -impact_z 0 -head_width 0.3 -strings_nodes 81 -output none
if [[ $rc -eq 0 ]] && grep -q "note: option(s) with no effect in this run: .*-head_width 0.3 (it acts only with -strings_frame held or -strings_frame beam)" <<<"$out" &&
   grep -q -- "-strings_nodes 81 (it acts only with -strings_frame held; -strings_frame is none)" <<<"$out" && grep -q -- "-head_center 0.175 (it acts only with -strings_frame beam; -strings_frame is none)" <<<"$out"; then
  pass "-strings_frame none: the bed's and the head's options are noted"
else fail "-strings_frame none with -head_*: exit $rc: $out"; fi
run -options_file options/scenes/strings-impact.opts -head_center 0.3 -beam_torsion -beam_torsion_stiffness 50 -beam_torsion_inertia 1e-4 -beam_nodes 55 -beam_length 0.9 -ts_dt 1e-4 -output none
if [[ $rc -eq 0 ]] && grep -q -- "-head_center 0.3 (it acts only with -strings_frame beam; -strings_frame is held)" <<<"$out" &&
   grep -q -- "-beam_nodes 55 (it acts only with -strings_frame none or -strings_frame beam)" <<<"$out" && grep -q -- "-beam_length 0.9 (it acts" <<<"$out" &&
   grep -q -- "-beam_torsion (it acts" <<<"$out" && grep -q -- "-beam_torsion_inertia 1e-4 (it acts" <<<"$out"; then
  pass "-strings_frame held: the frame's own options are noted"
else fail "-strings_frame held with -head_center, -beam_*: exit $rc: $out"; fi
run -options_file options/scenes/racket-strings.opts -strings_nodes 81 -beam_nodes 37 -output none
if [[ $rc -eq 0 ]] && grep -q -- "-strings_nodes 81 (it acts only with -strings_frame held; -strings_frame is beam)" <<<"$out" && ! grep -q -- "-beam_nodes 37 (it acts" <<<"$out"; then
  pass "-strings_frame beam: -strings_nodes is noted, -beam_nodes acts"
else fail "-strings_frame beam with -strings_nodes: exit $rc: $out"; fi
run -options_file options/scenes/racket-strings.opts -beam_nodes 37 -task sweep -sweep "strings_nodes=41;81" -output "$dir/strings-nodes.h5"
if [[ $rc -ne 0 ]] && grep -q -- "-sweep strings_nodes=41;81 is not allowed: -strings_nodes has no effect in this sweep (it acts only with -strings_frame held; -strings_frame is beam)" <<<"$out"; then
  pass "a sweep over -strings_nodes on a beam frame is refused"
else fail "sweep strings_nodes on a beam frame: exit $rc: $out"; fi
# -flight after a tennis ball's hit flies the tennis ball, with a note on the baseball's aerodynamics
run -options_file options/scenes/racket-strings.opts -beam_nodes 37 -impact_z 0 -flight -output none
if [[ $rc -eq 0 ]] && grep -q "note: -flight flies the impact's ball (0.057 kg, radius 0.0335 m) with Nathan's baseball aerodynamics" <<<"$out"; then
  pass "-flight after a tennis ball's hit: the impact's ball, a note on the aerodynamics"
else fail "-flight with the tennis ball: exit $rc: $out"; fi
run -options_file options/scenes/racket-strings.opts -beam_nodes 37 -impact_z 0 -flight -flight_cd0 0.55 -output none
if [[ $rc -eq 0 ]] && ! grep -q "baseball aerodynamics" <<<"$out"; then pass "-flight with the ball's own drag: no note"; else fail "-flight -flight_cd0: exit $rc: $out"; fi

# --- section files ---------------------------------------------------------------------------
printf '# x D (m), rows from 0.1 m\n0.1 0.03\n0.5 0.03\n0.94 0.066\n' >"$dir/shifted.profile"
run -beam_profile "$dir/shifted.profile" -beam_youngs_modulus 1.8e10 -beam_density 650 -impact_x 0.7 -ball_speed 10 -impact_window 1e-3 -output none
if [[ $rc -eq 0 ]] && grep -q "note: -beam_profile $dir/shifted.profile: its rows start at x = 0.1 m, not 0: the beam's x is measured from its first row" <<<"$out"; then
  pass "a profile whose x starts at 0.1 m: a note saying how -impact_x is measured"
else fail "shifted profile: exit $rc: $out"; fi
printf '# x D in centimetres\n0 3.0\n40 3.0\n84 6.6\n' >"$dir/cm.profile"
run -task modes -modes_count 2 -beam_profile "$dir/cm.profile" -beam_youngs_modulus 1.8e10 -beam_density 650 -output none
if grep -q "WARNING: -beam_profile $dir/cm.profile gives a beam far outside any bat, racket or test beam: length 84 m .* mass [0-9.e+]* kg .* largest outer diameter 6.6 m .*is the file in centimetres or millimetres" <<<"$out"; then
  pass "a profile in centimetres: a warning naming the file, length, mass, diameter and the units"
else fail "profile in cm: exit $rc: $out"; fi
run -options_file options/bats/r161.opts -beam_theory timoshenko -task modes -modes_count 2 -output none
if [[ $rc -eq 0 ]] && ! grep -q "WARNING\|note:" <<<"$out"; then pass "the shipped R161 (Timoshenko): no warning, no note"; else fail "r161 modes: $out"; fi
run -options_file options/bats/r161.opts -task modes -modes_count 2 -output none
if [[ $rc -eq 0 ]] && grep -q "note: option(s) with no effect in this run: -beam_shear_modulus 1.05e9 (it acts only with -beam_theory timoshenko; -beam_theory is euler)" <<<"$out"; then
  pass "the R161 under Euler-Bernoulli: its shear modulus is a note"
else fail "r161 euler: $out"; fi
printf -- '-ball_speed 2\n-impact_x 0.5\0abc\n' >"$dir/nul.opts"
run -options_file "$dir/nul.opts" -output none
if [[ $rc -ne 0 ]] && grep -q "$dir/nul.opts:2: the line holds a NUL byte (binary data?): an options file is plain text" <<<"$out"; then
  pass "a NUL byte in an options file: refused naming the file and line"
else fail "NUL in options file: exit $rc: $out"; fi
printf '0 0.03\n0.5 0.05\0x\n0.84 0.066\n' >"$dir/nul.profile"
run -beam_profile "$dir/nul.profile" -beam_youngs_modulus 1.8e10 -beam_density 650 -output none
if [[ $rc -ne 0 ]] && grep -q "$dir/nul.profile:2: the line holds a NUL byte" <<<"$out"; then pass "a NUL byte in a profile: refused naming the file and line"; else fail "NUL in profile: exit $rc: $out"; fi
printf '10 0.6\n20 0.5\0\n' >"$dir/nul-cor.txt"
run -ball_law hysteresis -ball_contact_time 1e-3 -ball_test_speed 26.8 -ball_cor_table "$dir/nul-cor.txt" -output none
if [[ $rc -ne 0 ]] && grep -q "ball_cor_table $dir/nul-cor.txt, line 2: the line holds a NUL byte" <<<"$out"; then pass "a NUL byte in a COR table: refused naming the file and line"; else fail "NUL in COR table: exit $rc: $out"; fi
# a UTF-8 byte order mark, CR and CR LF line ends: read as the plain file is (the same numbers)
printf -- '-impact_x 0.3\n-ball_speed 2\n' >"$dir/plain.opts"
printf -- '\xEF\xBB\xBF-impact_x 0.3\n-ball_speed 2\n' >"$dir/bom.opts"
printf -- '-impact_x 0.3\r-ball_speed 2\r' >"$dir/cr.opts"
printf -- '\xEF\xBB\xBF-impact_x 0.3\r\n-ball_speed 2\r\n' >"$dir/crlf.opts"
run -options_file "$dir/plain.opts" -impact_window 1e-3 -output none
want=$(field acor)
for f in bom cr crlf; do
  run -options_file "$dir/$f.opts" -impact_window 1e-3 -output none
  [[ $rc -eq 0 && -n $want && $(field acor) == "$want" ]] && grep -q "x 0.3000 m" <<<"$out" && pass "an options file ($f): read as the plain one (acor $want)" ||
    fail "$f.opts: exit $rc, acor $(field acor) against $want: $out"
done
printf '\xFF\xFE-\0i\0' >"$dir/utf16.opts"
run -options_file "$dir/utf16.opts" -output none
[[ $rc -ne 0 ]] && grep -q -- "-options_file $dir/utf16.opts: the file is UTF-16 text (it starts with the bytes FF FE): save it as UTF-8 or plain ASCII" <<<"$out" &&
  pass "a UTF-16 options file: refused naming its encoding" || fail "utf16.opts: exit $rc: $out"
printf '# x D\n0 0.03\n0.5 0.03\n0.84 0.066\n' >"$dir/plain.profile"
printf '\xEF\xBB\xBF0 0.03\n0.5 0.03\n0.84 0.066\n' >"$dir/bom.profile"
printf '0 0.03\r0.5 0.03\r0.84 0.066\r' >"$dir/cr.profile"
bat=(-beam_youngs_modulus 1.8e10 -beam_density 650 -impact_x 0.7 -impact_window 1e-3 -output none)
run -beam_profile "$dir/plain.profile" "${bat[@]}"
want=$(field acor)
for f in bom cr; do
  run -beam_profile "$dir/$f.profile" "${bat[@]}"
  [[ $rc -eq 0 && -n $want && $(field acor) == "$want" ]] && pass "a profile ($f): read as the plain one (acor $want)" || fail "$f.profile: exit $rc, acor $(field acor) against $want: $out"
done
printf '10 0.6\n20 0.5\n' >"$dir/plain-cor.txt"
printf '\xEF\xBB\xBF10 0.6\r20 0.5\r' >"$dir/bom-cr-cor.txt"
cor=(-ball_law hysteresis -ball_contact_time 1e-3 -ball_test_speed 26.8 -impact_window 1e-3 -output none)
run "${cor[@]}" -ball_cor_table "$dir/plain-cor.txt"
want=$(field acor)
run "${cor[@]}" -ball_cor_table "$dir/bom-cr-cor.txt"
[[ $rc -eq 0 && -n $want && $(field acor) == "$want" ]] && pass "a COR table with a BOM and CR line ends: read as the plain one (acor $want)" || fail "bom-cr-cor.txt: exit $rc, acor $(field acor) against $want: $out"

# --- a sweep's messages ----------------------------------------------------------------------
run -options_file options/scenes/racket-face-map.opts -sweep "impact_x=0.1;0.2,impact_z=0.2" -output "$dir/offface.h5"
[[ $rc -ne 0 ]] && grep -q "no point of the sweep can run: every impact point is off the racket's face (outside the head's outline, where there are no strings)" <<<"$out" &&
  ! grep -q "off the beam or held fixed" <<<"$out" && pass "every point off the racket's face: said so" || fail "off-face sweep: exit $rc: $out"
run -task sweep -sweep "flight_speed=30;40" -output "$dir/flight_axis.h5"
[[ $rc -ne 0 ]] && grep -q -- "-flight_speed is an option of this program, but the impact a sweep runs at each point (-task sweep farms -task impact) does not read it.*-task flight" <<<"$out" &&
  pass "a sweep axis over -flight_speed: named an option of -task flight" || fail "flight_speed axis: exit $rc: $out"
run -task sweep -sweep "bogus_option=1;2" -output "$dir/bogus_axis.h5"
[[ $rc -ne 0 ]] && grep -q -- "-bogus_option is not an option of this program" <<<"$out" && pass "an axis over no option at all: still 'not an option of this program'" || fail "bogus axis: exit $rc: $out"
run -options_file options/scenes/oblique-map.opts -beam_nodes 43 -sweep "impact_x=0.65,impact_offset=-0.1;0.01" -output "$dir/offset.h5"
grep -q "sweep: point 0 (impact_x = 0.65 m, impact_offset = -0.1 m) failed, status 4 (refused by the run's set-up): -impact_offset -0.1 misses the bat" <<<"$out" &&
  pass "a failed row quotes -impact_offset -0.1 as written" || fail "failed row's value: exit $rc: $(grep failed <<<"$out")"

run -beam_clamp 0,0.13 -impact_x 0.6 -output none
if [[ $rc -eq 0 ]] && grep -q "note: -beam_clamp 0,0.13 holds the nodes from x = 0 to x = 0.11 m (h = 0.0275 m)" <<<"$out"; then
  pass "a clamp edge between nodes: a note with the held region's ends"
else fail "clamp note: exit $rc: $out"; fi
run -beam_clamp 0,0.11 -impact_x 0.6 -output none
if [[ $rc -eq 0 ]] && ! grep -q "note: -beam_clamp" <<<"$out"; then pass "a clamp on nodes: no note"; else fail "clamp on nodes: $out"; fi

# --- explicit RK under strong damping ----------------------------------------------------------
for beta in 3e-3 1e-2; do
  run -beam_damping_stiffness $beta -output none
  lim=$(sed -nE 's/^explicit stability limit dt_max ([0-9.e+-]+) s.*/\1/p' <<<"$out")
  if [[ $rc -eq 0 && -n $lim ]] && grep -q "^x " <<<"$out"; then pass "-beam_damping_stiffness $beta: runs, dt_max $lim s"; else fail "-beam_damping_stiffness $beta: exit $rc: $out"; fi
done
run -beam_damping_stiffness 1e-2 -ts_type rk -ts_rk_type 4 -impact_window 1e-4 -output none
lim=$(sed -nE 's/^explicit stability limit dt_max ([0-9.e+-]+) s.*/\1/p' <<<"$out")
above=$(awk -v l="$lim" 'BEGIN { printf "%.6e", 1.01 * l }')
below=$(awk -v l="$lim" 'BEGIN { printf "%.6e", 0.99 * l }')
run -beam_damping_stiffness 1e-2 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt "$below" -impact_window 1e-4 -impact_energy_check -output none
if [[ $rc -eq 0 ]]; then pass "fixed RK4 at 0.99 x its damped limit runs"; else fail "RK4 at 0.99 dt_max: exit $rc: $out"; fi
run -beam_damping_stiffness 1e-2 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -ts_dt "$above" -output none
if [[ $rc -ne 0 ]] && grep -q "is above the stability limit dt_max" <<<"$out"; then pass "fixed RK4 at 1.01 x its damped limit is refused"; else fail "RK4 at 1.01 dt_max: exit $rc: $out"; fi

# --- -ts_type irk ------------------------------------------------------------------------------
run -reference modal -output none
ref=$(field acor)
run -ts_type irk -ts_dt 1e-5 -ts_adapt_type none -output none
if [[ $rc -eq 0 && -n $ref ]] && close "$(field acor)" "$ref" 1e-5; then pass "-ts_type irk runs: ACOR $(field acor) against the modal reference $ref"; else fail "-ts_type irk: exit $rc: $out"; fi

# --- a ball at rest, a swinging bat ------------------------------------------------------------
run -bat_speed 24 -ball_speed 0 -output "$dir/rest.h5"
if [[ $rc -eq 0 ]] && grep -q "batted-ball speed [0-9.]* m/s, collision efficiency q [0-9.]*" <<<"$out"; then
  pass "a ball at rest struck by a swinging bat runs, with BBS and q"
else fail "ball at rest: exit $rc: $out"; fi
if [[ -n $python ]]; then
  r=$("$python" - "$dir/rest.h5" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    r = f["results"]
    get = lambda k: float(np.asarray(r[k] if k in r else r.attrs[k]).ravel()[0])
    acor, bbs, q = get("acor"), get("bbs"), get("collision_efficiency")
    ok = np.isnan(acor) and np.isfinite(bbs) and bbs > 24 and 0 < q < 1
print("ok" if ok else "acor %r bbs %r q %r" % (acor, bbs, q))
PY
)
  [[ $r == ok ]] && pass "ball at rest: acor NaN, bbs and q finite in /results" || fail "ball at rest file: $r"
fi

# --- the bare default run --------------------------------------------------------------------
run -output none
if [[ $rc -eq 0 ]] && ! grep -q WARNING <<<"$out" && close "$(field acor)" "$ref" 1e-5; then
  pass "the bare default run: no resolution warning, ACOR $(field acor) within 1e-5 of the modal reference $ref"
else fail "default run: exit $rc, reference $ref: $out"; fi

echo "cli_inputs: $fails failure(s)"
[[ $fails -eq 0 ]]
