#!/usr/bin/env bash
# -task flight through the real executable (docs/flight.md):
#   * the scene options/scenes/flight-nathan.opts (A. M. Nathan's calculator, its sheet
#     "BattedBallTrajectory-2") at 1 and 2 ranks: the same numbers; the air density of the
#     sheet's cell D2; the landing 422.292 ft from home plate in 5.5247 s, 0.19 % beyond the
#     sheet's published 421.486 ft in 5.520 s (its first-order step at dt = 0.01 s, as
#     tests/test_flight.cpp shows); every dataset with its unit; the series from the launch
#     height to the located landing (|z| <= 1e-12 m) every 0.01 s; /options_used with units;
#   * bad input refused with the option, the value and what is allowed; a typo suggesting the
#     option meant; -help listing the flight's, the air's and the flight TS's options;
#   * issue 34: the flight's integrator (types, adaptors, steps, tolerances refused or said as
#     they act: a fixed step is printed as one, an adaptive type holds its tolerance, irk runs),
#     the spin's bound (the surface below the speed of sound), the series' memory limit, and
#     -task impact -flight: the -flight_ts_* options used and checked before the impact;
#   * scripts/plot_flight.py on two files (a PNG PIL reads) and refusing an impact file;
#     scripts/h5_to_csv.py reading the flight's /results and /series.
#
#   tests/flight_cli.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: flight_cli.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: flight_cli.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-mpiexec}
exe=$(readlink -f "$exe")
[[ -x $exe ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && dir=$(readlink -f "$dir")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
rm -rf "${dir:?}"/*
source tests/lib.sh # MPI env, fail/pass, $python
[[ -n $python ]] || { echo "FAIL: no python3 with h5py and numpy (Debian: apt-get install python3-h5py python3-matplotlib)"; exit 1; }
scene=options/scenes/flight-nathan.opts

# run NAME RANKS [options...]: the scene into $dir/NAME.h5 (log $dir/NAME.log)
run() {
  local name=$1 np=$2 rc; shift 2
  "$mpiexec" -n "$np" "$exe" -options_file "$scene" "$@" -output "$dir/$name.h5" >"$dir/$name.log" 2>&1
  rc=$?
  if [[ $rc -eq 0 && -f $dir/$name.h5 ]]; then pass "$name runs on $np rank(s)"; return 0; fi
  fail "$name: beamimpact -options_file $scene $* on $np rank(s) (exit $rc)"
  tail -5 "$dir/$name.log" | sed 's/^/      /'
  return 1
}
# expect_fail WHAT PATTERN options...: the executable must fail and say PATTERN on stderr
expect_fail() {
  local what=$1 pat=$2 rc; shift 2
  "$exe" -task flight -output none "$@" >"$dir/out.txt" 2>"$dir/err.txt"
  rc=$?
  if [[ $rc -ne 0 ]] && grep -qF -- "$pat" "$dir/err.txt"; then pass "$what: '$(head -c 160 "$dir/err.txt" | tr '\n' ' ')'"
  else fail "$what: exit $rc, expected a failure naming '$pat'; stderr: $(head -c 300 "$dir/err.txt")"; fi
}

if run nathan 1 && run nathan-np2 2 && run nathan-nospin 1 -flight_spin 0; then
  if "$python" - "$dir/nathan.h5" "$dir/nathan-np2.h5" "$dir/nathan-nospin.h5" <<'EOF'; then pass "scene: the sheet's density, the landing 0.19 % beyond the published one, units, series, 1 = 2 ranks"; else fail "scene numbers (above)"; fi
import sys, h5py, numpy as np
ft = 0.3048
f, g, h = (h5py.File(p, "r") for p in sys.argv[1:4])
bad = []
def check(what, ok):
    if not ok: bad.append(what)
r = f["results"]
check("task attribute", f.attrs["task"] in (b"flight", "flight"))
check("air density = cell D2 (1.1937672240686363)", abs(f.attrs["air_density"] - 1.1937672240686363) < 1e-12)
y = r["landing_y"][0] + 2 * ft  # the sheet's y: from home plate, 2 ft behind the launch point
check("landing 422.292 ft from home plate (%.4f)" % (y / ft), abs(y / ft - 422.2920) < 1e-3)
check("hang time 5.5247 s (%.5f)" % r["hang_time"][0], abs(r["hang_time"][0] - 5.52467) < 1e-5)
check("0.19 %% beyond the published 421.486 ft (%.4f %%)" % (100 * (y / ft / 421.48556894099829 - 1)), 0.0018 < y / ft / 421.48556894099829 - 1 < 0.0020)
check("apex 28.0754 m (%.5f)" % r["apex"][0], abs(r["apex"][0] - 28.07538) < 1e-4)
check("lateral 0", r["landing_x"][0] == 0 and r["bearing"][0] == 0)
check("spin makes it carry: %.2f > %.2f m" % (r["distance"][0], h["results"]["distance"][0]), r["distance"][0] > h["results"]["distance"][0] + 10)
for grp in ("results", "series"):
    for k, d in f[grp].items():
        check("unit of /%s/%s" % (grp, k), len(d.attrs.get("unit", b"")) > 0)
s = f["series"]
t, z = s["time"][()], s["z"][()]
check("series starts at the launch height", t[0] == 0 and abs(z[0] - 0.9144) < 1e-15)
check("series every 0.01 s", np.allclose(np.diff(t[:-1]), 0.01, atol=1e-12, rtol=0))
check("series ends at the located landing", t[-1] == r["hang_time"][0] and abs(z[-1]) <= 1e-12 and (z[:-1] > 0).all())
check("integer counts", r["steps"].dtype.kind == "i" and r["locate_steps"][0] >= 1)
for k in r:
    if k != "wall_time":
        check("/results/%s the same on 2 ranks" % k, r[k][0] == g["results"][k][0])
check("/series the same on 2 ranks", all(np.array_equal(s[k][()], g["series"][k][()]) for k in s))
u = f["options_used"]
check("/options_used: the speed as given, in m/s", abs(u.attrs["flight_speed"] - 46.05557) < 1e-4 and u["unit"].attrs["flight_speed"] in (b"m/s", "m/s") and u["given"].attrs["flight_speed"] == 1)
check("/options_used: the default -flight_cd0, dimensionless, not given", u.attrs["flight_cd0"] == 0.3008 and u["unit"].attrs["flight_cd0"] in (b"1", "1") and u["given"].attrs["flight_cd0"] == 0)
check("/options_used: every -flight_* and -air_* option", all(k in u.attrs for k in ("flight_cd0", "flight_constants", "flight_series_dt", "air_temperature", "air_pressure", "air_humidity", "air_elevation", "air_density")))
for b in bad: print("   ", b)
sys.exit(1 if bad else 0)
EOF
  grep -q "^flight: distance 128.1050 m  apex 28.0754 m" "$dir/nathan.log" && pass "summary line" || fail "summary line: $(head -1 "$dir/nathan.log")"
  [[ $(grep -c "^flight:" "$dir/nathan-np2.log") -eq 1 ]] && pass "one summary on 2 ranks" || fail "summary lines on 2 ranks: $(grep -c "^flight:" "$dir/nathan-np2.log")"

  # The plot of two files, and an impact file refused.
  if "$python" scripts/plot_flight.py "$dir/nathan.h5" "$dir/nathan-nospin.h5" -o "$dir/flight.png" >"$dir/plot.log" 2>&1 &&
     "$python" -c "from PIL import Image; im = Image.open('$dir/flight.png'); assert im.size[0] > 500 and im.size[1] > 300, im.size"; then
    pass "plot_flight.py draws two trajectories"
  else fail "plot_flight.py: $(tail -3 "$dir/plot.log")"; fi
  "$exe" -task impact -impact_x 0.5 -output "$dir/impact.h5" >/dev/null 2>&1
  if ! "$python" scripts/plot_flight.py "$dir/impact.h5" -o "$dir/bad.png" 2>"$dir/err.txt" && grep -q "not a -task flight file" "$dir/err.txt"; then
    pass "plot_flight.py refuses an impact file"
  else fail "plot_flight.py on an impact file: $(cat "$dir/err.txt")"; fi
  if "$python" scripts/h5_to_csv.py "$dir/nathan.h5" >"$dir/results.csv" && grep -q "distance (m)" "$dir/results.csv" &&
     "$python" scripts/h5_to_csv.py "$dir/nathan.h5" series >"$dir/series.csv" && [[ $(wc -l <"$dir/series.csv") -eq 555 ]]; then
    pass "h5_to_csv.py reads /results and /series (554 samples)"
  else fail "h5_to_csv.py on the flight file (series rows: $(wc -l <"$dir/series.csv"))"; fi
fi

expect_fail "negative speed" "-flight_speed -3 is not allowed: it must be > 0 (m/s)" -flight_speed -3
expect_fail "humidity above 100" "-air_humidity 120 is not allowed: it must be in [0, 100] (%)" -air_humidity 120
expect_fail "launch into the ground" "-flight_height 0 with -flight_angle -5" -flight_height 0 -flight_angle -5
expect_fail "air without density" "give an air density of" -air_pressure 1000 -air_temperature 50 -air_humidity 100
expect_fail "a type that cannot roll back" "-flight_ts_type euler is not allowed: use one of rk, cn, theta, beuler, bdf, arkimex, rosw, irk, alpha (the types that can roll back a step" -flight_ts_type euler
expect_fail "no landing in time" "has not landed after -flight_ts_max_time 1 s" -flight_ts_max_time 1
expect_fail "a typo" "(did you mean -flight_speed?)" -flight_sped 40
expect_fail "a typo of the flight TS's option" "(did you mean -flight_ts_rtol?)" -flight_ts_rtoll 1e-8
expect_fail "an unknown -flight_constants" "-flight_constants si is not known: use one of calculator, exact" -flight_constants si

# issue 34, the flight's integrator and its bounds: each refusal names the option, the value and
# what is allowed; each run that PETSc's defaults made silently wrong now says what it does.
expect_fail "an unknown type" "-flight_ts_type bogus is not allowed: use one of rk, cn, theta, beuler, bdf, arkimex, rosw, irk, alpha" -flight_ts_type bogus
expect_fail "an unknown adaptor" "-flight_ts_adapt_type cfl is not allowed: use one of none, basic, dsp" -flight_ts_adapt_type cfl
expect_fail "a negative step" "-flight_ts_dt -1 is not allowed: it must be > 0 (s)" -flight_ts_dt -1
expect_fail "a negative tolerance" "-flight_ts_rtol -1 is not allowed: it must be >= 0" -flight_ts_rtol -1
expect_fail "a fixed step far too long" "the ball's state is not finite at t = 20 s after a step of 10 s (the fixed -flight_ts_dt is far too long" -flight_ts_adapt_type none -flight_ts_dt 10
expect_fail "an adaptor for a tableau without an estimate" "-flight_ts_adapt_type basic is not allowed with -flight_ts_type rk 1fe: that method has no embedded error estimate" -flight_ts_rk_type 1fe -flight_ts_adapt_type basic
expect_fail "a spin beyond the speed of sound" "-flight_spin 1e9 is not allowed: a spin of 1e+09 rad/s moves the ball's surface at 3.68881e+07 m/s (-flight_ball_radius 0.0368881 m), beyond the speed of sound in air (343 m/s)" -flight_spin 1e9
expect_fail "a spin whose sum is beyond it" "-flight_spin 7000 with -flight_sidespin 7000 is not allowed" -flight_spin 7000 -flight_sidespin 7000
expect_fail "a series beyond the memory limit" "-flight_series_dt 1e-09 s (a sample every 1e-09 s for up to -flight_ts_max_time 60 s) would need about 3.84e+03 GB, above the limit of 1 GB (-max_memory" -flight_series_dt 1e-9 -max_memory 1
# expect_run WHAT PATTERN options...: the executable must succeed and print PATTERN
expect_run() {
  local what=$1 pat=$2 rc; shift 2
  "$exe" -task flight -output none "$@" >"$dir/out.txt" 2>&1
  rc=$?
  if [[ $rc -eq 0 ]] && grep -qF -- "$pat" "$dir/out.txt"; then pass "$what: '$(grep -F -- "$pat" "$dir/out.txt" | head -1 | cut -c1-160)'"
  else fail "$what: exit $rc, expected '$pat'; output: $(head -c 400 "$dir/out.txt")"; fi
}
expect_run "rk 5dp with rtol 1e-3 (the landing was not located)" "ts rk 5dp  rtol 0.001  atol 1e-10" -flight_ts_rtol 1e-3
expect_run "irk (it failed in MatKAIJSetAIJ): a fixed step, said" "ts irk  fixed step 0.001 s (no error control)" -flight_ts_type irk
expect_run "beuler adapts (it took fixed 1 ms steps)" "ts beuler  rtol 1e-06  atol 1e-06" -flight_ts_type beuler -flight_ts_rtol 1e-6 -flight_ts_atol 1e-6
expect_run "rk 1fe: its fixed step is said, not a tolerance" "ts rk 1fe  fixed step 0.001 s (no error control)" -flight_ts_rk_type 1fe
expect_run "rk 4 with -flight_ts_rtol: a note" "note: option(s) with no effect in this run: -flight_ts_rtol 1e-6 (the flight's step is fixed, -flight_ts_dt 0.001 s: -flight_ts_type rk 4 has no error estimate)" -flight_ts_rk_type 4 -flight_ts_rtol 1e-6
expect_run "a spin just below the bound flies" "flight: distance" -flight_spin 9290

# -task impact -flight: the flight's integrator options act and are checked before the impact;
# a pitch spinning beyond the bound is refused (a round bat, its modes: cheap)
hit=(-options_file options/bats/r161.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -ts_type modal -impact_x 0.7 -ball_speed 40 -flight)
bat=("${hit[@]}" -impact_offset 0.02 -output none)
out=$("$exe" "${bat[@]}" -flight_ts_rtol 1e-8 -flight_ts_rk_type 3bs 2>&1); rc=$?
if [[ $rc -eq 0 ]] && grep -q "^flight: distance" <<<"$out" && ! grep -q "not used" <<<"$out"; then pass "-task impact -flight with -flight_ts_*: used, no note"
else fail "-task impact -flight -flight_ts_rtol: exit $rc: $out"; fi
out=$("$exe" "${bat[@]}" -flight_ts_type bogus 2>&1); rc=$?
if [[ $rc -ne 0 ]] && grep -q "flight_ts_type bogus is not allowed" <<<"$out" && ! grep -q "^x " <<<"$out"; then pass "-task impact -flight -flight_ts_type bogus: refused before the impact"
else fail "-task impact -flight -flight_ts_type bogus: exit $rc: $out"; fi
# a sweep writes no trajectory: it keeps none, so -flight_series_dt is a note and no memory
# limit applies to it (a point kept 680 MB at 1e-6 s); the numbers are the single runs'
out=$("$exe" "${hit[@]}" -task sweep -sweep "impact_offset=0.01;0.02" -flight_series_dt 1e-6 -max_memory 0.01 -output "$dir/flights.h5" 2>&1); rc=$?
single=$("$exe" "${bat[@]}" 2>&1 | sed -nE 's/^flight: distance ([0-9.]+) m.*/\1/p')
swept=$("$python" -c "import h5py,sys; print('%.2f' % h5py.File(sys.argv[1],'r')['results/distance'][1])" "$dir/flights.h5" 2>/dev/null)
if [[ $rc -eq 0 ]] && grep -q "note: 1 option(s) set but not used by this task: -flight_series_dt 1e-6" <<<"$out" && [[ -n $single && $swept == "$single" ]]; then
  pass "a sweep with -flight keeps no series: -flight_series_dt 1e-6 a note under -max_memory 0.01, the carry the single run's ($swept m)"
else fail "sweep -flight -flight_series_dt: exit $rc, carry '$swept' against '$single': $out"; fi
out=$("$exe" "${bat[@]}" -ball_spin 1e9 2>&1); rc=$?
if [[ $rc -ne 0 ]] && grep -q "ball_spin 1e9 is not allowed: it moves the ball's surface at 3.69e+07 m/s (-ball_radius 0.0369 m), beyond the speed of sound in air (343 m/s)" <<<"$out"; then pass "-ball_spin 1e9: refused"
else fail "-ball_spin 1e9 -flight: exit $rc: $out"; fi

"$exe" -help >"$dir/help.txt" 2>&1
for o in -flight_speed -flight_spin -flight_spin_decay_time -air_pressure -air_density -flight_ts_type -flight_ts_rtol; do
  grep -q -- "^  $o " "$dir/help.txt" || fail "-help does not list $o"
done
grep -q "^PETSc options of the flight's integrator" "$dir/help.txt" && grep -q -- "^  -flight_ts_rk_type <5dp>" "$dir/help.txt" && pass "-help lists the flight TS's table with its defaults" || fail "-help has no table of the flight TS's options"
grep -q "^  -task .*flight" "$dir/help.txt" && pass "-help lists -task flight and the flight's options" || fail "-help does not list -task flight"

((fails == 0)) && echo "flight_cli: all passed" || echo "flight_cli: $fails failure(s)"
exit $((fails > 0))
