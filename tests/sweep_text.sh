#!/usr/bin/env bash
# Text (categorical) sweep axes through the real executable (docs/sweep.md, "Text axes"):
#   * the two documented examples in short form: -sweep "ts_type=rk;cn;alpha2;modal" over the
#     impact point on the default beam, and -sweep "beam_theory=euler;timoshenko" over the
#     impact point on the R161 bat (options/scenes/r161-acor.opts, the baseball at 40 m/s);
#     /results/<axis> and /sweep/<axis> are strings in case order, with the attribute values (the
#     labels as given, in order), sweep_axis_kinds says which axes are text; every row equals
#     -task impact with the same option values, bit for bit (wall_time aside);
#   * plot_sweep.py draws one curve per value (the lines it prints name each value and its point
#     count, read here from /results), wall_time on a log scale, and the difference to -ts_type
#     modal (--relative-to modal); the PNGs are valid images;
#   * the values the program knows are checked before any work, the error naming the axis, the
#     value and the allowed ones (ts_type, beam_theory), and nothing is written; a value only the
#     run refuses (an unknown -ts_rk_type) is a failed row, status 4, with the run's reason;
#     quoted numbers stay text (ts_rk_type='4';'3': the strings "4", "3", each row equal to
#     -task impact -ts_rk_type 4 or 3); a value given twice and an unclosed quote are refused.
#
#   tests/sweep_text.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: sweep_text.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: sweep_text.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
exe=$(readlink -f "$exe")
[[ -x $exe ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
rm -rf "$dir" && mkdir -p "$dir" && dir=$(readlink -f "$dir")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1 # the options files name their bases from the repository root
source tests/lib.sh                               # MPI env, fail/pass, $python
[[ -n $python ]] || { echo "FAIL: no python3 with h5py and numpy (Debian: apt-get install python3-h5py python3-matplotlib)"; exit 1; }

# refused NAME MESSAGE... -- command...: fails before any work, says every MESSAGE, writes nothing
refused() {
  local name=$1 msgs=() m ok=1
  shift
  while [[ $1 != -- ]]; do msgs+=("$1"); shift; done
  shift
  if "$@" -output "$dir/$name.h5" >"$dir/$name.log" 2>&1; then fail "$name: accepted"; return; fi
  for m in "${msgs[@]}"; do grep -qF -- "$m" "$dir/$name.log" || ok=0; done
  if ((ok)) && [[ ! -e $dir/$name.h5 ]]; then pass "$name: $(grep -m1 error "$dir/$name.log" | cut -c1-170)"
  else fail "$name: expected '${msgs[*]}' and no file: $(cat "$dir/$name.log")"; fi
}

# same_rows SWEEP AXIS VALUE IMPACT...: the sweep's rows with AXIS = VALUE (in impact_x order)
# equal the -task impact files given (one per impact point, in order), bit for bit
same_rows() {
  "$python" - "$@" <<'PY'
import sys, h5py, numpy as np
sweep, axis, value, impacts = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
r = h5py.File(sweep, "r")["results"]
labels = [v.decode() if isinstance(v, bytes) else v for v in r[axis][()]]
rows = [i for i, v in enumerate(labels) if v == value]
rows.sort(key=lambda i: r["impact_x"][i])
assert len(rows) == len(impacts), (rows, impacts)
for i, p in zip(rows, impacts):
    imp = h5py.File(p, "r")["results"]
    for k in imp:
        if k == "wall_time": continue
        a, b = imp[k][0], r[k][i]
        assert a == b or (np.isnan(a) and np.isnan(b)), (p, k, a, b)
print("%d row(s) with %s = %s" % (len(rows), axis, value))
PY
}

# --- the integrators over the impact point on the default beam (3 points x 4 types, 2 ranks) ---
ts=(-options_file options/default.opts -sweep "ts_type=rk;cn;alpha2;modal" -sweep_x 0.3:0.9:3)
"$mpiexec" -n 2 "$exe" "${ts[@]}" -output "$dir/ts.h5" >"$dir/ts.log" 2>&1 || { fail "ts_type sweep"; cat "$dir/ts.log"; }
grep -q "^sweep: 12 points, impact_x from 0.3 to 0.9 m (3) x ts_type rk, cn, alpha2, modal (4)," "$dir/ts.log" \
  && pass "announced: $(grep -m1 '^sweep: 12 points' "$dir/ts.log" | cut -c1-120)" || fail "announcement: $(head -5 "$dir/ts.log")"
if out=$("$python" - "$dir/ts.h5" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
r, s = f["results"], f["sweep"]
text = lambda d: [v.decode() if isinstance(v, bytes) else v for v in d[()]]
order = ["rk", "cn", "alpha2", "modal"]
assert text(r["ts_type"]) == order * 3, text(r["ts_type"])
assert text(s["ts_type"]) == order * 3
assert list(r["ts_type"].attrs["values"]) == order and list(s["ts_type"].attrs["values"]) == order
assert list(r["impact_x"][()]) == [0.3] * 4 + [0.6] * 4 + [0.9] * 4
assert f.attrs["sweep_axes"] in (b"impact_x,ts_type", "impact_x,ts_type") and f.attrs["sweep_axis_kinds"] in (b"number,text", "number,text")
assert np.all(r["status"][()] == 0) and np.all(np.isfinite(r["acor"][()]))
# the integrators agree on the ACOR to their accuracy, and are not one run copied four times
a = r["acor"][()].reshape(3, 4)
assert np.all(np.abs(a - a[:, 3:4]) < 1e-4) and np.all(a[:, 0] != a[:, 1]), a
print("12 rows, ts_type rk/cn/alpha2/modal in case order with the attribute values; ACOR spread %.1e" % np.ptp(a, axis=1).max())
PY
); then pass "ts.h5: $out"; else fail "ts.h5 layout: $out"; fi
for t in cn modal; do
  for x in 0.3 0.6 0.9; do "$exe" -options_file options/impact.opts -ts_type $t -impact_x $x -output "$dir/imp-$t-$x.h5" >/dev/null 2>&1 || fail "-task impact -ts_type $t -impact_x $x"; done
  out=$(same_rows "$dir/ts.h5" ts_type $t "$dir"/imp-$t-{0.3,0.6,0.9}.h5 2>&1) && pass "ts.h5: $out equal -task impact -ts_type $t, bit for bit" || fail "ts.h5 rows of $t differ from -task impact: $out"
done

# --- the plots: one curve per integrator ---
plot() { # plot NAME args...: plot_sweep.py, its log in $dir/NAME.log
  local name=$1
  shift
  scripts/plot_sweep.py "$@" -o "$dir/$name.png" >"$dir/$name.log" 2>&1 || { fail "plot_sweep.py $*: $(cat "$dir/$name.log")"; return 1; }
}
if plot ts-acor "$dir/ts.h5" acor && plot ts-wall "$dir/ts.h5" wall_time --logy && plot ts-error "$dir/ts.h5" acor --relative-to modal --logy; then
  n=0
  for t in rk cn alpha2 modal; do grep -qF "$dir/ts.h5: $t: 3 point(s), 0 with two or more contacts (ringed), 0 failed (x)" "$dir/ts-acor.log" && n=$((n + 1)); done
  ((n == 4)) && pass "plot_sweep.py: one curve per ts_type value (4 of 4 named with their 3 points)" || fail "plot_sweep.py curves: $(cat "$dir/ts-acor.log")"
  grep -q "modal: the reference (--relative-to), 0 on a log scale: not drawn" "$dir/ts-error.log" && pass "--relative-to modal: the others against -ts_type modal" || fail "--relative-to: $(cat "$dir/ts-error.log")"
  "$python" -c "
import sys
from PIL import Image
for p in sys.argv[1:]:
    im = Image.open(p); im.verify(); assert im.format == 'PNG' and im.size[0] >= 300 and im.size[1] >= 200, (p, im.size)
" "$dir"/ts-{acor,wall,error}.png && pass "the three PNGs are valid images" || fail "plot_sweep.py PNGs"
fi

# --- Euler-Bernoulli and Timoshenko over the impact point on the R161 bat (2 x 2, coarser grid) ---
r161=(-options_file options/scenes/r161-acor.opts -sweep "beam_theory=euler;timoshenko" -sweep_x 0.6,0.7 -beam_nodes 85 -impact_window 2e-3 -sweep_quiet)
"$mpiexec" -n 2 "$exe" "${r161[@]}" -output "$dir/r161.h5" >"$dir/r161.log" 2>&1 || { fail "beam_theory sweep"; cat "$dir/r161.log"; }
for th in euler timoshenko; do
  for x in 0.6 0.7; do
    "$exe" -options_file options/scenes/r161-acor.opts -task impact -beam_theory $th -impact_x $x -beam_nodes 85 -impact_window 2e-3 -output "$dir/bat-$th-$x.h5" >/dev/null 2>&1 || fail "-task impact -beam_theory $th"
  done
  out=$(same_rows "$dir/r161.h5" beam_theory $th "$dir"/bat-$th-{0.6,0.7}.h5 2>&1) && pass "r161.h5: $out equal -task impact, bit for bit" || fail "r161.h5 rows of $th: $out"
done
if plot r161 "$dir/r161.h5" acor; then
  grep -qF "$dir/r161.h5: timoshenko: 2 point(s)" "$dir/r161.log" && pass "plot_sweep.py: Euler-Bernoulli and Timoshenko curves of the bat's ACOR" || fail "r161 plot: $(cat "$dir/r161.log")"
fi

# --- checked before any work; refused by the run; numbers kept as text ---
q=(-task sweep -beam_nodes 21 -sweep_quiet)
refused ts_bogus "ts_type=rk;bogus: 'bogus' is not a TS type of this program: use one of" "rk, " "cn, " "rosw" "modal" -- "$exe" "${q[@]}" -sweep "impact_x=0.5,ts_type=rk;bogus"
refused theory_bogus "bogus" "timoshenko" -- "$exe" "${q[@]}" -sweep "beam_theory=euler;bogus,impact_x=0.5"
refused twice "'cn' is given twice" -- "$exe" "${q[@]}" -sweep "ts_type=cn;rk;cn"
refused quote "a quote is not closed" -- "$exe" "${q[@]}" -sweep "ts_type='rk;cn"
"$exe" "${q[@]}" -ts_type rk -ts_adapt_type none -sweep "ts_rk_type=4;bogus,impact_x=0.5" -output "$dir/rk_bogus.h5" >"$dir/rk_bogus.log" 2>&1
rc=$?
if ((rc == 2)) && "$python" - "$dir/rk_bogus.h5" <<'PY'
import sys, h5py, numpy as np
r = h5py.File(sys.argv[1], "r")["results"]
text = lambda d: [v.decode() if isinstance(v, bytes) else v for v in d[()]]
assert text(r["ts_rk_type"]) == ["4", "bogus"] and list(r["status"][()]) == [0, 4], (text(r["ts_rk_type"]), r["status"][()])
assert "bogus" in text(r["reason"])[1] and np.isnan(r["acor"][1]) and np.isfinite(r["acor"][0])
PY
then pass "ts_rk_type=4;bogus: a failed row, status 4, the run's reason; exit status 2"; else fail "ts_rk_type=4;bogus (exit $rc): $(cat "$dir/rk_bogus.log")"; fi
"$exe" "${q[@]}" -ts_type rk -ts_adapt_type none -sweep "ts_rk_type='4';'3',impact_x=0.5" -output "$dir/rk_quoted.h5" >"$dir/rk_quoted.log" 2>&1 || fail "ts_rk_type='4';'3': $(cat "$dir/rk_quoted.log")"
for k in 4 3; do
  "$exe" -task impact -beam_nodes 21 -ts_type rk -ts_adapt_type none -ts_rk_type $k -impact_x 0.5 -output "$dir/rk$k.h5" >/dev/null 2>&1 || fail "-task impact -ts_rk_type $k"
  out=$(same_rows "$dir/rk_quoted.h5" ts_rk_type $k "$dir/rk$k.h5" 2>&1) && pass "ts_rk_type='4';'3' stays text: $out equals -task impact -ts_rk_type $k" || fail "quoted numbers: $out"
done

echo "sweep_text: $fails failure(s), $SECONDS s"
[[ $fails -eq 0 ]]
