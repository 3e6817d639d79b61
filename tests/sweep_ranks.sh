#!/usr/bin/env bash
# -task sweep at different rank counts, and its edge cases, through the real
# executable:
#   * the same sweep at 1, 2 and 3 ranks (3: oversubscribed, idle rank at the
#     end) gives identical files: every dataset but the timing column
#     /results/wall_time within 1e-12, every attribute but the full command
#     line (options, which holds -output) equal; so does a sweep with a text axis
#     (ts_type=rk;cn;modal);
#   * a row equals -task impact at that point;
#   * more ranks than points, one point, -sweep_ranks_per_case 2 (round-off
#     close to 1 rank per case) and the plot script work;
#   * zero points, bad syntax, an axis that is no option of the program, a value its
#     option does not allow, too many ranks per case, a misspelled option, -output none:
#     each stops before any work with its message; an axis's option also given (-impact_x
#     with -sweep_x) is overridden by the axis, with a note;
#   * a 2-axis sweep (-sweep impact_x=...,beam_thickness=...) at 1 and 2 ranks: every row
#     equals -task impact with the same option values, bit for bit (wall_time aside);
#   * a sweep across a clamped region and off the beam completes: those rows have status 2
#     or 3, a reason naming -impact_x and NaN numbers, the exit status is 2, a rerun
#     recomputes nothing and -sweep_retry_failed recomputes exactly the failed points.
#
#   tests/sweep_ranks.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: sweep_ranks.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: sweep_ranks.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe=$(readlink -f "$exe")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1 # no file of an earlier run is resumed
rm -rf ranks_* edge_* text_*
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh" # MPI env, fail/pass, $python



# same_file A B [tol] [rows-only]: datasets equal within tol (wall_time skipped),
# attributes equal except options (rows-only: /results only, no attributes).
same_file() {
  local a=$1 b=$2 tol=${3:-1e-12} mode=${4:-all}
  if [[ -n "$python" ]]; then
    "$python" - "$a" "$b" "$tol" "$mode" <<'PY'
import sys, h5py, numpy as np
a, b, tol, mode = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r"), float(sys.argv[3]), sys.argv[4]
timing = {"/results/wall_time"}
bad = []
def walk(g, h, path):
    if set(g.keys()) != set(h.keys()):
        bad.append("%s: members differ: %s vs %s" % (path, sorted(g.keys()), sorted(h.keys())))
    for k in g:
        if k not in h: continue
        p = path.rstrip("/") + "/" + k
        if mode == "rows" and not p.startswith("/results"): continue
        if isinstance(g[k], h5py.Group):
            walk(g[k], h[k], p)
        elif p not in timing:
            x, y = g[k][()], h[k][()]
            if x.shape != y.shape:
                bad.append("%s: shape %s vs %s" % (p, x.shape, y.shape))
            elif x.dtype.kind in "OSU":
                if not np.array_equal(x, y): bad.append("%s: text differs" % p)
            elif x.size and not np.all((np.abs(x - y) <= tol * np.maximum(1, np.abs(x))) | (np.isnan(x) & np.isnan(y))):
                bad.append("%s: max difference %g" % (p, np.nanmax(np.abs(x - y))))
walk(a, b, "/")
if mode == "all":
    for k in set(a.attrs) | set(b.attrs):
        if k in ("options", "date", "host", "ranks"): continue  # the run's provenance, not its results
        if k not in a.attrs or k not in b.attrs or a.attrs[k] != b.attrs[k]:
            bad.append("attribute %s: %r vs %r" % (k, a.attrs.get(k), b.attrs.get(k)))
for m in bad: print("   ", m)
sys.exit(1 if bad else 0)
PY
  else # h5dump -m %.17g prints every dataset exactly: compare the text
    if [[ $tol != 1e-12 ]]; then echo "    (not compared within $tol: needs python3 with h5py and numpy)"; return 0; fi
    local g n groups=results
    [[ $mode == all ]] && groups="results sweep"
    for g in $groups; do
      for n in $(h5dump -H -g "/$g" "$a" | sed -nE 's/^ *DATASET "([^"]+)".*/\1/p'); do
        [[ $g/$n == results/wall_time ]] && continue
        cmp -s <(h5dump -m %.17g -d "/$g/$n" "$a" | tail -n +3) <(h5dump -m %.17g -d "/$g/$n" "$b" | tail -n +3) || { echo "    /$g/$n differs"; return 1; }
      done
    done
  fi
}

# run_fails NAME MESSAGE cmd...: the command must fail, print MESSAGE, and leave no output file.
run_fails() {
  local name=$1 msg=$2
  shift 2
  if "$@" >"$name.log" 2>&1; then fail "$name: succeeded, expected an error containing '$msg'"; return; fi
  if ! grep -qF -- "$msg" "$name.log"; then fail "$name: message '$msg' not found in:"; sed 's/^/    /' "$name.log" | head -5; return; fi
  if [[ -e "$name.h5" ]]; then fail "$name: wrote $name.h5 although it failed"; return; fi
  pass "$name: $(grep -F -- "$msg" "$name.log" | head -1 | cut -c1-150)"
}

loud=(-beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -rigid_loss_fraction 0.2)
opts=("${loud[@]}" -sweep_quiet)
sweep_x=(-sweep_x 0:1.1:23)

# --- identical files at 1, 2 and 3 ranks ------------------------------------
"$mpiexec" -n 1 "$exe" -task sweep "${opts[@]}" "${sweep_x[@]}" -output ranks_1.h5 >ranks_1.log 2>&1 || { fail "1 rank sweep failed"; cat ranks_1.log; }
"$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" "${sweep_x[@]}" -output ranks_2.h5 >ranks_2.log 2>&1 || { fail "2 rank sweep failed"; cat ranks_2.log; }
"$mpiexec" -n 3 "$exe" -task sweep "${opts[@]}" "${sweep_x[@]}" -output ranks_3.h5 >ranks_3.log 2>&1 || { fail "3 rank sweep failed"; cat ranks_3.log; }
[[ -s ranks_1.log || -s ranks_2.log ]] && fail "-sweep_quiet printed something: $(cat ranks_1.log ranks_2.log | head -3)"
if same_file ranks_1.h5 ranks_2.h5; then pass "1 and 2 ranks: identical files"; else fail "1 and 2 ranks: files differ"; fi
if same_file ranks_1.h5 ranks_3.h5; then pass "1 and 3 ranks: identical files"; else fail "1 and 3 ranks: files differ"; fi
if [[ -n "$python" ]]; then
  "$python" - ranks_2.h5 <<'PY' && pass "23 rows in case order, complete, rigid columns present" || fail "row layout of ranks_2.h5"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r"); r = f["results"]
assert len(r["x"]) == 23 and np.array_equal(r["case_index"][()], np.arange(23)), r["case_index"][()]
assert np.allclose(r["x"][()], np.linspace(0, 1.1, 23), rtol=0, atol=1e-15)
assert f.attrs["sweep_complete"] == 1 and f.attrs["sweep_cases_done"] == 23 and f.attrs["task"] == b"sweep"
assert np.all(np.isfinite(r["rigid_acor"][()])) and np.all(np.isfinite(r["rigid_forced_loss_fraction"][()]))
PY
fi

# --- a text axis (the integrator, categorical): identical files at 1, 2 and 3 ranks ---------
tx=(-sweep "ts_type=rk;cn;modal,impact_x=0.2;0.55;1.0")
for n in 1 2 3; do
  "$mpiexec" -n $n "$exe" -task sweep "${opts[@]}" "${tx[@]}" -output text_$n.h5 >text_$n.log 2>&1 || { fail "text-axis sweep on $n rank(s)"; cat text_$n.log; }
done
if same_file text_1.h5 text_2.h5 && same_file text_1.h5 text_3.h5; then pass "text axis (ts_type=rk;cn;modal x 3 points) at 1, 2 and 3 ranks: identical files"; else fail "text axis: files differ between rank counts"; fi

# --- a row equals -task impact at that point (0.55 m is case 11) -------------
"$exe" -task impact -beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -impact_x 0.55 -output ranks_impact.h5 >ranks_impact.log 2>&1 || fail "-task impact failed"
"$exe" -task sweep "${opts[@]}" -sweep_x 0.55 -output ranks_one.h5 >/dev/null 2>&1 || fail "one-point sweep failed"
if [[ -n "$python" ]]; then
  "$python" - ranks_impact.h5 ranks_one.h5 ranks_2.h5 <<'PY' && pass "one point: one row, equal to -task impact at 0.55 m and to row 11 of the sweep" || fail "one point / -task impact comparison"
import sys, h5py, numpy as np
imp, one, sw = (h5py.File(p, "r")["results"] for p in sys.argv[1:4])
assert len(one["x"]) == 1, len(one["x"])
for k in imp:
    if k in ("wall_time", "rigid_acor"): continue  # rigid_acor: the sweep's -rigid_loss_fraction 0.2, f = 0 in -task impact
    a, b, c = imp[k][0], one[k][0], sw[k][11]
    if np.isnan(a):  # a column that does not apply: NaN in all three
        assert np.isnan(b) and np.isnan(c), (k, a, b, c)
        continue
    assert abs(a - b) <= 1e-12 * max(1, abs(a)) and abs(a - c) <= 1e-12 * max(1, abs(a)), (k, a, b, c)
PY
fi

# --- more ranks than points; several ranks per case ---------------------------
"$mpiexec" -n 3 "$exe" -task sweep "${opts[@]}" -sweep_x 0.2,0.7 -output edge_more_ranks.h5 >edge_more_ranks.log 2>&1 \
  && pass "3 ranks, 2 points: done" || { fail "3 ranks, 2 points"; cat edge_more_ranks.log; }
"$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" "${sweep_x[@]}" -sweep_ranks_per_case 2 -output edge_rpc2.h5 >edge_rpc2.log 2>&1 || { fail "-sweep_ranks_per_case 2"; cat edge_rpc2.log; }
if same_file ranks_1.h5 edge_rpc2.h5 1e-9 rows; then pass "-sweep_ranks_per_case 2: rows within 1e-9 of 1 rank per case"; else fail "-sweep_ranks_per_case 2 differs from 1 rank per case"; fi
"$mpiexec" -n 3 "$exe" -task sweep "${opts[@]}" -sweep_x 0.2,0.7 -sweep_ranks_per_case 2 -output edge_rpc_left.h5 >edge_rpc_left.log 2>&1 \
  && pass "3 ranks, 2 per case: the rank left over stays idle" || { fail "3 ranks, 2 per case"; cat edge_rpc_left.log; }

# --- errors, each before any work ---------------------------------------------
run_fails edge_zero "gives no impact points" "$exe" -task sweep "${opts[@]}" -sweep_x 0:1:0 -output edge_zero.h5
run_fails edge_syntax "a range is start:stop:count" "$exe" -task sweep "${opts[@]}" -sweep_x 0:1.1 -output edge_syntax.h5
run_fails edge_nox "-task sweep needs its axes" "$exe" -task sweep "${opts[@]}" -output edge_nox.h5
run_fails edge_noopt "-bogus_speed is not an option of this program" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep "impact_x=0.3;0.5,bogus_speed=1;2" -output edge_noopt.h5
run_fails edge_range "point 1 (impact_x = 0.3 m, ball_speed = -1 m/s): -ball_speed -1 is not allowed" "$exe" -task sweep "${opts[@]}" -sweep "impact_x=0.3;0.5,ball_speed=2;-1" -output edge_range.h5
run_fails edge_int "point 1 (beam_nodes = 21.5): -beam_nodes 21.5 is not allowed: it must be a whole number >= 5" "$exe" -task sweep -ts_type rk -ts_rk_type 4 -ts_adapt_type none -sweep "beam_nodes=21;21.5" -output edge_int.h5
run_fails edge_spec "the fourth field of start:stop:count:log must be 'log'" "$exe" -task sweep "${opts[@]}" -sweep "ball_speed=1:4:3:lin" -output edge_spec.h5
run_fails edge_twice "both vary impact_x" "$exe" -task sweep "${opts[@]}" -sweep_x 0.2 -sweep "impact_x=0.3" -output edge_twice.h5
run_fails edge_reserved "belongs to the task or the sweep itself" "$exe" -task sweep "${opts[@]}" -sweep "sweep_quiet=1" -output edge_reserved.h5
# An option an axis varies, also given (e.g. by a scene's options file): the axis overrides it, and says so.
if "$exe" -task sweep "${loud[@]}" -sweep_x 0.2,0.7 -impact_x 0.3 -output edge_impact_x.h5 >edge_impact_x.log 2>&1 \
  && grep -q -- "the axis impact_x overrides -impact_x 0.3 given in the options" edge_impact_x.log && same_file edge_more_ranks.h5 edge_impact_x.h5 1e-12 rows; then
  pass "-impact_x with -sweep_x: overridden by the axis (announced), rows as without it"
else
  fail "-impact_x with -sweep_x"; cat edge_impact_x.log
fi
run_fails edge_rpc "-sweep_ranks_per_case 3 is not allowed with 2 MPI ranks" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -sweep_ranks_per_case 3 -output edge_rpc.h5
run_fails edge_typo "-beam_thicknes" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -beam_thicknes 0.01 -output edge_typo.h5
# A misspelt PETSc option (close to a known one) is an error with the suggestion, before any point runs;
# a known one left over by another integrator is a note (as -options_left prints): a scene composes with a later -ts_type.
run_fails edge_petsc_typo "-ts_rk_typo 4 (did you mean -ts_rk_type?)" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -ts_rk_typo 4 -output edge_petsc_typo.h5
if "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -ts_theta_theta 0.6 -output edge_petsc_left.h5 >edge_petsc_left.log 2>&1 \
  && grep -q "note: 1 PETSc solver option(s) set but not used by this integrator: -ts_theta_theta 0.6" edge_petsc_left.log; then
  pass "a left-over PETSc solver option is a one-line note"
else
  fail "edge_petsc_left"; cat edge_petsc_left.log
fi
run_fails edge_none "give -output FILE.h5" "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -output none

# --- a 2-axis sweep: every row equals -task impact with the same option values -----
ax2=(-sweep "impact_x=0.3;0.55;1.02,beam_thickness=5e-3;6.5e-3")
"$mpiexec" -n 1 "$exe" -task sweep "${opts[@]}" "${ax2[@]}" -output ax2_1.h5 >ax2_1.log 2>&1 || { fail "2-axis sweep, 1 rank"; cat ax2_1.log; }
"$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" "${ax2[@]}" -output ax2_2.h5 >ax2_2.log 2>&1 || { fail "2-axis sweep, 2 ranks"; cat ax2_2.log; }
if [[ -n "$python" ]]; then
  k=0
  for x in 0.3 0.55 1.02; do
    for a in 5e-3 6.5e-3; do
      "$exe" -task impact "${loud[@]:0:8}" -impact_x $x -beam_thickness $a -output ax2_impact_$k.h5 >ax2_impact_$k.log 2>&1 || fail "-task impact -impact_x $x -beam_thickness $a"
      k=$((k + 1))
    done
  done
  "$python" - ax2_1.h5 ax2_2.h5 ax2_impact_{0..5}.h5 <<'PY' && pass "2-axis sweep (3 x 2 points) at 1 and 2 ranks: every row equals -task impact bit for bit (wall_time aside)" || fail "2-axis sweep rows differ from -task impact"
import sys, h5py, numpy as np
one, two = (h5py.File(p, "r") for p in sys.argv[1:3])
imps = [h5py.File(p, "r")["results"] for p in sys.argv[3:9]]
xs, aa = [0.3, 0.55, 1.02], [5e-3, 6.5e-3]
for f in (one, two):
    r = f["results"]
    assert list(f["sweep/impact_x"][()]) == [x for x in xs for a in aa], f["sweep/impact_x"][()]
    assert list(f["sweep/beam_thickness"][()]) == [a for x in xs for a in aa]
    assert r["impact_x"].attrs["unit"] in (b"m", "m") and r["beam_thickness"].attrs["unit"] in (b"m", "m")
    assert np.all(r["status"][()] == 0) and all(s in (b"", "") for s in r["reason"][()])
    for i, imp in enumerate(imps):
        assert r["impact_x"][i] == xs[i // 2] and r["beam_thickness"][i] == aa[i % 2]
        for k in imp:
            if k in ("wall_time", "rigid_acor"): continue  # rigid_acor: the sweep's f = 0.2, 0 for -task impact
            a, b = imp[k][0], r[k][i]
            assert a == b or (np.isnan(a) and np.isnan(b)), (f.filename, i, k, a, b)
PY
fi

# --- across a clamped region and off the beam: failed rows, exit status 2 --------
fx=(-beam_clamp 0,0.2 -sweep "impact_x=-0.1;0.1;0.5;1.2,ball_speed=1;2")
"$mpiexec" -n 2 "$exe" -task sweep "${loud[@]}" "${fx[@]}" -output fail_2.h5 >fail_2.log 2>&1
rc=$?
if ((rc == 2)) && grep -q "^sweep: 6 of 8 points failed: 4 with status 2 (impact point off the beam), 2 with status 3 (impact point held fixed)" fail_2.log; then
  pass "clamped region and off-beam points: completed, exit status 2, summary: $(grep -o '6 of 8 points failed' fail_2.log)"
else
  fail "clamped/off-beam sweep: exit status $rc"; cat fail_2.log
fi
if [[ -n "$python" ]]; then
  "$python" - fail_2.h5 <<'PY' && pass "failed rows: status 2/3, reason names -impact_x and its value, numbers NaN; the others computed" || fail "failed rows of fail_2.h5"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r"); r = f["results"]
st, reason, x = r["status"][()], [s.decode() if isinstance(s, bytes) else s for s in r["reason"][()]], r["impact_x"][()]
assert f.attrs["sweep_complete"] == 1 and len(st) == 8
assert list(st) == [2, 2, 3, 3, 0, 0, 2, 2], st
for i in range(8):
    if st[i] == 0:
        assert reason[i] == "" and np.isfinite(r["acor"][i]), i
    else:
        assert reason[i].startswith("-impact_x %g is not allowed" % x[i]), reason[i]
        assert ("held fixed" in reason[i]) == (st[i] == 3) and np.isnan(r["acor"][i]) and np.isnan(r["x"][i]), (i, reason[i])
PY
fi
"$exe" -task sweep "${loud[@]}" "${fx[@]}" -output fail_2.h5 >fail_again.log 2>&1
rc=$?
((rc == 2)) && grep -q "all 8 points were already done; nothing to compute" fail_again.log && pass "rerun: nothing recomputed (the failed points neither), exit status 2" || { fail "rerun of the failing sweep (exit $rc)"; cat fail_again.log; }
"$exe" -task sweep "${loud[@]}" "${fx[@]}" -sweep_retry_failed -output fail_2.h5 >fail_retry.log 2>&1
rc=$?
((rc == 2)) && grep -q "resuming fail_2.h5: 2 of 8 points already done, 6 to compute" fail_retry.log && grep -q "^sweep: computed 6 points" fail_retry.log \
  && pass "-sweep_retry_failed: computes exactly the 6 failed points again" || { fail "-sweep_retry_failed (exit $rc)"; cat fail_retry.log; }

# --- the plot scripts -----------------------------------------------------------
if [[ -n "$python" ]] && "$python" -c "import matplotlib" 2>/dev/null; then
  if "$python" "$src/scripts/plot_sweep.py" ax2_2.h5 acor -o ax2_curves.png >ax2_curves.log 2>&1 && [[ -s ax2_curves.png ]]; then pass "plot_sweep.py: 2 axes, curves"; else fail "plot_sweep.py curves"; cat ax2_curves.log; fi
  if "$python" "$src/scripts/plot_sweep.py" fail_2.h5 acor --map -o fail_map.png >fail_map.log 2>&1 && [[ -s fail_map.png ]]; then pass "plot_sweep.py: 2-D map with failed points marked"; else fail "plot_sweep.py map"; cat fail_map.log; fi
  if "$python" "$src/scripts/plot_sweep.py" ranks_1.h5 -o ranks_sweep.png >ranks_sweep.log 2>&1 && [[ -s ranks_sweep.png ]]; then pass "plot_sweep.py: one axis"; else fail "plot_sweep.py one axis"; cat ranks_sweep.log; fi
fi
if [[ -n "$python" ]] && "$python" -c "import matplotlib" 2>/dev/null; then
  if "$python" "$src/scripts/plot_sweep.py" ranks_1.h5 edge_more_ranks.h5 -o ranks_plot.png >ranks_plot.log 2>&1 && [[ -s ranks_plot.png ]]; then pass "plot_sweep.py: two files on one PNG (the ACOR figure)"; else fail "plot_sweep.py two files"; cat ranks_plot.log; fi
fi

if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
echo "all checks passed"
