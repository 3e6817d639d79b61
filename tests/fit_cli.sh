#!/usr/bin/env bash
# -task fit through the real executable; one part per ctest test (the last argument):
#   roundtrip  data made by the program (a sweep at known ball_k and beam_youngs_modulus: impact_x x
#              ball_speed rows with acor and contact_time), fitted from the middle of the bounds: the
#              known values to 1e-6 relative; the options file headed by the data's name and
#              SHA-256, its values those of /fit/value; a rerun computes no run (all from the file);
#   ranks      the same fit on 1 and 2 ranks: /fit/value, standard_error, correlation to 1e-12;
#   resume     a fit stopped after 10 runs (-fit_stop_after) and run again: the rerun loads those 10
#              from the journals and computes exactly the fresh fit's runs less 10, to the same
#              values bit for bit;
#   identify   E and rho fitted to a uniform free beam's frequencies alone: the warning names both
#              (they enter only as E/rho); with the measured mass added: no warning, both recovered;
#   input      bad input: errors that name the option, the file's line and column, the row;
#   shipped    the shipped fits that take seconds (options/fits/baseball-wall, baseball-wall-table,
#              r161-tap, racket-frame) give the numbers docs/fit.md reports (to 1e-3 of the value,
#              1e-2 of the standard error), a second run of each computes nothing.
#
#   tests/fit_cli.sh path/to/beamimpact scratch_dir mpiexec part
set -uo pipefail
exe=${1:?usage: fit_cli.sh beamimpact scratch_dir mpiexec part}
dir=${2:?usage: fit_cli.sh beamimpact scratch_dir mpiexec part}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
part=${4:?usage: fit_cli.sh beamimpact scratch_dir mpiexec part}
exe=$(readlink -f "$exe")
source "$(dirname "$0")/lib.sh" # MPI env, fail/pass, $python
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir="$dir/$part"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 2
[[ -n "$python" ]] || { echo "SKIP: no Python with h5py"; exit 77; }

# The impact scene: the paper's beam (free-free, N = 21) struck by a linear ball, the modal integrator.
scene=(-beam_nodes 21 -ts_type modal -ball_law linear)
params="ball_k=1e4:5e4,beam_youngs_modulus=5e10:9e10"

# make_data TRUE_K TRUE_E FILE: the program's acor and contact_time over impact_x x ball_speed.
make_data() {
  "$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.3;0.6;0.9,ball_speed=1;2" -ball_k "$1" -beam_youngs_modulus "$2" -sweep_quiet -output gen.h5 >gen.log 2>&1 \
    || { fail "the data's sweep failed"; cat gen.log; exit 1; }
  "$python" - "$3" <<'PY'
import sys, h5py
r = h5py.File("gen.h5", "r")["results"]
with open(sys.argv[1], "w") as f:
    f.write("# made by the program (tests/fit_cli.sh)\nimpact_x,ball_speed,acor,contact_time\n")
    for i in range(len(r["acor"])):
        f.write("%.17g,%.17g,%.17g,%.17g\n" % (r["impact_x"][i], r["ball_speed"][i], r["acor"][i], r["contact_time"][i]))
PY
}

# value FILE NAME: the fitted value of NAME in /fit/value
value() { "$python" -c "import h5py,sys; f=h5py.File(sys.argv[1],'r')['fit']; n=[x.decode() if isinstance(x,bytes) else x for x in f['names'][()]]; print('%.17g' % f['value'][n.index(sys.argv[2])])" "$1" "$2"; }
# near A B TOL: |A - B| <= TOL |B|
near() { "$python" -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t*abs(b) else 1)" "$1" "$2" "$3"; }
computed() { sed -nE 's/^fit: runs: ([0-9]+) computed.*/\1/p' "$1"; }

case $part in
roundtrip)
  make_data 2.2e4 6.3e10 data.csv
  "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output fit.h5 >fit.log 2>&1 || { fail "the fit failed"; cat fit.log; }
  k=$(value fit.h5 ball_k) E=$(value fit.h5 beam_youngs_modulus)
  near "$k" 2.2e4 1e-6 && pass "ball_k recovered: $k (2.2e4)" || fail "ball_k $k, not 2.2e4 to 1e-6"
  near "$E" 6.3e10 1e-6 && pass "beam_youngs_modulus recovered: $E (6.3e10)" || fail "beam_youngs_modulus $E, not 6.3e10 to 1e-6"
  sha=$(sha256sum data.csv | cut -d' ' -f1)
  head -2 fit.opts | grep -q "data: data.csv  SHA-256 $sha" && pass "fit.opts is headed by the data's name and SHA-256" || { fail "fit.opts header"; head -3 fit.opts; }
  grep -q "^-ball_k $k\$" fit.opts && grep -q "^-beam_youngs_modulus $E\$" fit.opts && pass "fit.opts holds /fit/value exactly" || { fail "fit.opts values"; cat fit.opts; }
  grep -q "ball_k .* +- " fit.opts && grep -q "chi^2 = " fit.opts && pass "fit.opts has the chi^2 and the standard errors" || fail "fit.opts lacks chi^2 or standard errors"
  [[ ! -e fit.h5.parts ]] && pass "a finished fit leaves no journals" || fail "fit.h5.parts left: $(ls -A fit.h5.parts)"
  "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output fit.h5 >again.log 2>&1 || { fail "the rerun failed"; cat again.log; }
  [[ $(computed again.log) == 0 ]] && pass "a rerun computes no run ($(grep -m1 'known from' again.log))" || fail "the rerun computed $(computed again.log) runs"
  # the options file includes: an impact with it gives the data's row
  "$exe" "${scene[@]}" -options_file fit.opts -impact_x 0.6 -ball_speed 1 -output one.h5 >one.log 2>&1 || { fail "an impact with -options_file fit.opts failed"; cat one.log; }
  a=$("$python" -c "import h5py; print('%.17g' % h5py.File('one.h5','r')['results/acor'][0])")
  b=$(sed -n '5p' data.csv | cut -d, -f3)
  near "$a" "$b" 1e-8 && pass "an impact with the fitted options gives the data's acor ($a, $b)" || fail "acor with fit.opts $a, data $b"
  ;;
ranks)
  make_data 2.2e4 6.3e10 data.csv
  "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output one.h5 >one.log 2>&1 || { fail "1 rank failed"; cat one.log; }
  "$mpiexec" -n 2 "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output two.h5 >two.log 2>&1 || { fail "2 ranks failed"; cat two.log; }
  "$python" - <<'PY' && pass "1 and 2 ranks: the same fit to 1e-12" || fail "1 and 2 ranks differ"
import h5py, numpy as np, sys
a, b = h5py.File("one.h5", "r")["fit"], h5py.File("two.h5", "r")["fit"]
bad = 0
for k in ("value", "standard_error", "correlation", "residuals/fitted", "history/chi2"):
    x, y = a[k][()], b[k][()]
    d = np.max(np.abs(x - y) / np.maximum(np.abs(x), 1e-300))
    print("   %-18s max relative difference %.3g" % (k, d))
    bad += not (x.shape == y.shape and d <= 1e-12)
sys.exit(bad)
PY
  ;;
resume)
  make_data 2.2e4 6.3e10 data.csv
  "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output fresh.h5 >fresh.log 2>&1 || { fail "the fresh fit failed"; cat fresh.log; }
  if "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output fit.h5 -fit_stop_after 10 >stop.log 2>&1; then fail "-fit_stop_after 10 did not stop the fit"
  else grep -q "stopped after 10 runs" stop.log && pass "stopped after 10 runs" || { fail "stop: unclear message"; cat stop.log; }; fi
  [[ -e fit.h5.parts && ! -e fit.h5.parts/lock ]] && pass "the stopped fit left its journals and no lock" || fail "fit.h5.parts: $(ls -A fit.h5.parts 2>&1)"
  "$exe" "${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output fit.h5 >resume.log 2>&1 || { fail "the resumed fit failed"; cat resume.log; }
  grep -q "fit: 10 runs known from an earlier fit into fit.h5 (0 from its file, 10 from the journals" resume.log && pass "the rerun loads the 10 runs from the journals" \
    || { fail "the rerun did not load 10 runs"; grep known resume.log; }
  n_fresh=$(computed fresh.log) n_resume=$(computed resume.log)
  [[ $((n_resume + 10)) == "$n_fresh" ]] && pass "the rerun computes $n_resume runs, the fresh fit's $n_fresh less the 10 it had: none again" || fail "rerun computed $n_resume, fresh $n_fresh"
  cmp -s <(grep '^-' fresh.opts) <(grep '^-' fit.opts) && pass "the same fitted values bit for bit" || fail "the resumed fit's values differ: $(grep '^-' fresh.opts fit.opts)"
  ;;
identify)
  # The paper's beam's first three free-free frequencies at two lengths (E 7e10, rho 2700), and its mass.
  { echo "beam_length,frequency_1,frequency_2,frequency_3,mass"
    for L in 0.8 1.1; do
      "$exe" -task modes -beam_nodes 41 -beam_length $L -modes_count 5 -output m$L.h5 >/dev/null 2>&1 || fail "modes at $L"
      "$python" -c "import h5py; f=h5py.File('m$L.h5','r'); q=f['modes/frequency'][()]; print('$L,%.17g,%.17g,%.17g,%.17g' % (q[2], q[3], q[4], f.attrs['beam_mass']))"
    done; } >with_mass.csv
  cut -d, -f1-4 with_mass.csv >frequencies.csv
  fit_modes=(-task fit -fit_task modes -beam_nodes 41 -fit_parameters "beam_youngs_modulus=5e10:9e10,beam_density=2000:3500")
  "$exe" "${fit_modes[@]}" -fit_data frequencies.csv -output er.h5 >er.log 2>&1 || { fail "the E, rho fit failed"; cat er.log; }
  grep -q "warning: the parameters are not identifiable from these data: moving along +0.71 log beam_youngs_modulus + 0.71 log beam_density changes no fitted value" er.log \
    && pass "frequencies alone: E and rho named as not identifiable" || { fail "no identifiability warning naming E and rho"; cat er.log; }
  grep -q "beam_youngs_modulus .* inf " er.log && pass "... their standard errors infinite" || fail "finite standard errors for E and rho alone"
  "$exe" "${fit_modes[@]}" -fit_data with_mass.csv -output erm.h5 >erm.log 2>&1 || { fail "the E, rho, mass fit failed"; cat erm.log; }
  grep -q "not identifiable" erm.log && fail "with the mass: still not identifiable" || pass "with the measured mass: identifiable"
  near "$(value erm.h5 beam_youngs_modulus)" 7e10 1e-6 && near "$(value erm.h5 beam_density)" 2700 1e-6 && pass "... and E, rho recovered to 1e-6" || fail "E, rho not recovered: $(grep -A3 parameter erm.log)"
  ;;
input)
  make_data 2.2e4 6.3e10 data.csv
  base=("${scene[@]}" -task fit -fit_data data.csv -fit_parameters "$params" -output f.h5)
  expect() { # expect PATTERN ARGS...: the fit fails with a message matching PATTERN
    local pat=$1; shift
    if "$exe" "$@" >bad.log 2>&1; then fail "accepted: $*"; elif grep -qE -- "$pat" bad.log; then pass "refused: $(grep -m1 error bad.log | cut -c1-150)"; else fail "unclear: $(cat bad.log)"; fi
  }
  expect "needs its measurements: -fit_data" "${scene[@]}" -task fit -fit_parameters "$params" -output f.h5
  expect "needs the options to fit: -fit_parameters" "${scene[@]}" -task fit -fit_data data.csv -output f.h5
  expect "-fit_data nosuch.csv cannot be read" "${scene[@]}" -task fit -fit_data nosuch.csv -fit_parameters "$params" -output f.h5
  expect "-fit_parameters .*: -ball_kk is not a real-valued option" "${base[@]}" -fit_parameters "ball_kk=1:2"
  expect "its start, the value -ball_k 90000 given in the options, is outside its bounds" "${base[@]}" -ball_k 9e4
  sed 's/^impact_x,/impact_y,/' data.csv >badcol.csv
  expect "column 'impact_y' is neither an option of the program" "${base[@]}" -fit_data badcol.csv
  sed '3s/,1,/,fast,/' data.csv >badcell.csv
  expect "badcell.csv line 3, column 'ball_speed': 'fast' is not a number" "${base[@]}" -fit_data badcell.csv
  sed '3s/^0.29999999999999999,/1.5,/' data.csv >offbeam.csv
  expect "-fit_data offbeam.csv row 1 \(line 3: impact_x=1.5, ball_speed=1\): the run at ball_k=.* failed" "${base[@]}" -fit_data offbeam.csv
  echo "-ball_k 2e4" >in.opts
  expect "-fit_options_output in.opts is not allowed: it is an input of this run" "${base[@]}" -options_file in.opts -fit_options_output in.opts
  echo "a note" >note.txt
  expect "-fit_options_output note.txt is not allowed: it exists and is not an options file a fit wrote" "${base[@]}" -fit_options_output note.txt
  expect "-fit_sigmaa acor=0.01 \\(did you mean -fit_sigma\\?\\)" "${base[@]}" -fit_sigmaa acor=0.01
  grep -q "iteration  1" bad.log && fail "... but only after the fit ran" || pass "... before the fit's first iteration"
  ;;
shipped)
  # check FIT NAME VALUE SE: /fit/value and standard_error of NAME in FIT-fit.h5
  check() {
    local v s
    v=$(value "$1-fit.h5" "$2")
    s=$("$python" -c "import h5py,sys; f=h5py.File(sys.argv[1],'r')['fit']; n=[x.decode() if isinstance(x,bytes) else x for x in f['names'][()]]; print('%.17g' % f['standard_error'][n.index(sys.argv[2])])" "$1-fit.h5" "$2")
    near "$v" "$3" 1e-3 && near "$s" "$4" 1e-2 && pass "$1: $2 = $v +- $s (docs: $3 +- $4)" || fail "$1: $2 = $v +- $s, docs/fit.md says $3 +- $4"
  }
  for fit in baseball-wall baseball-wall-table r161-tap racket-frame; do
    "$exe" -options_file "$root/options/fits/$fit.opts" -fit_quiet >"$fit.log" 2>&1 || { fail "$fit failed"; cat "$fit.log"; continue; }
  done
  check baseball-wall ball_m 1.905 0.05654
  check baseball-wall ball_k1 4.716e8 1.886e8
  check baseball-wall ball_n 10.432 0.3104
  check baseball-wall-table ball_m 2.0021 0.06035
  check r161-tap beam_youngs_modulus 1.6848e10 3.615e8
  check r161-tap beam_shear_modulus 1.369e9 1.309e8
  check r161-tap beam_density 660.86 7.618
  check racket-frame beam_EI 126.18 50.49
  check racket-frame beam_mu 0.45165 0.001388
  check racket-frame strings_tension 148.59 49.53
  "$exe" -options_file "$root/options/fits/r161-tap.opts" -fit_quiet >again.log 2>&1 && [[ $(computed again.log) == 0 ]] && pass "r161-tap again: no run computed" || fail "r161-tap again: $(computed again.log) runs"
  ;;
*) echo "unknown part $part"; exit 2 ;;
esac
((fails == 0)) && echo "fit_cli $part: all passed" || { echo "fit_cli $part: $fails failed"; exit 1; }
