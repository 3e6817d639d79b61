#!/usr/bin/env bash
# -task sweep at different rank counts, and its edge cases, through the real
# executable:
#   * the same sweep at 1, 2 and 3 ranks (3: oversubscribed, idle rank at the
#     end) gives identical files: every dataset but the timing column
#     /results/wall_time within 1e-12, every attribute but the full command
#     line (options, which holds -output) equal;
#   * a row equals -task impact at that point;
#   * more ranks than points, one point, -sweep_ranks_per_case 2 (round-off
#     close to 1 rank per case) and the plot script work;
#   * zero points, a point off the beam or on a held point, bad syntax,
#     too many ranks per case, a misspelled option, -output none: each stops
#     before any work with its message; -impact_x is refused (the points come from -sweep_x).
#
#   tests/sweep_ranks.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: sweep_ranks.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: sweep_ranks.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe=$(readlink -f "$exe")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && cd "$dir" || exit 1
rm -rf ranks_* edge_*
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
            elif x.size and not np.all((np.abs(x - y) <= tol * np.maximum(1, np.abs(x))) | (np.isnan(x) & np.isnan(y))):
                bad.append("%s: max difference %g" % (p, np.nanmax(np.abs(x - y))))
walk(a, b, "/")
if mode == "all":
    for k in set(a.attrs) | set(b.attrs):
        if k == "options": continue
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

# --- a row equals -task impact at that point (0.55 m is case 11) -------------
"$exe" -task impact -beam_nodes 21 -ts_type rk -ts_rk_type 4 -ts_adapt_type none -impact_x 0.55 -output ranks_impact.h5 >ranks_impact.log 2>&1 || fail "-task impact failed"
"$exe" -task sweep "${opts[@]}" -sweep_x 0.55 -output ranks_one.h5 >/dev/null 2>&1 || fail "one-point sweep failed"
if [[ -n "$python" ]]; then
  "$python" - ranks_impact.h5 ranks_one.h5 ranks_2.h5 <<'PY' && pass "one point: one row, equal to -task impact at 0.55 m and to row 11 of the sweep" || fail "one point / -task impact comparison"
import sys, h5py, numpy as np
imp, one, sw = (h5py.File(p, "r")["results"] for p in sys.argv[1:4])
assert len(one["x"]) == 1, len(one["x"])
for k in imp:
    if k == "wall_time": continue
    a, b, c = imp[k][0], one[k][0], sw[k][11]
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
run_fails edge_outside "-sweep_x point 2, x = 1.2" "$exe" -task sweep "${opts[@]}" -sweep_x 0.2,0.5,1.2 -output edge_outside.h5
run_fails edge_negative "must lie on the beam" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x -0.1:0.5:4 -output edge_negative.h5
run_fails edge_held "is held fixed" "$exe" -task sweep "${opts[@]}" -beam_left clamped -sweep_x 0:1.1:12 -output edge_held.h5
run_fails edge_syntax "a range is start:stop:count" "$exe" -task sweep "${opts[@]}" -sweep_x 0:1.1 -output edge_syntax.h5
run_fails edge_nox "-task sweep needs the impact points" "$exe" -task sweep "${opts[@]}" -output edge_nox.h5
# -impact_x has no effect in a sweep: refused with a message naming it.
if ! "$exe" -task sweep "${loud[@]}" -sweep_x 0.2,0.7 -impact_x 0.3 -output edge_impact_x.h5 >edge_impact_x.log 2>&1 \
  && grep -q -- "-impact_x 0.3 has no effect with -task sweep" edge_impact_x.log; then
  pass "-impact_x with -sweep_x: refused"
else
  fail "-impact_x with -sweep_x"; cat edge_impact_x.log
fi
run_fails edge_rpc "-sweep_ranks_per_case 3 is not allowed with 2 MPI ranks" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -sweep_ranks_per_case 3 -output edge_rpc.h5
run_fails edge_typo "-ts_rk_typo" "$mpiexec" -n 2 "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -ts_rk_typo 4 -output edge_typo.h5
run_fails edge_none "give -output FILE.h5" "$exe" -task sweep "${opts[@]}" -sweep_x 0.1,0.2 -output none

# --- the plot script ----------------------------------------------------------
if [[ -n "$python" ]] && "$python" -c "import matplotlib" 2>/dev/null; then
  if "$python" "$src/scripts/plot_acor.py" ranks_1.h5 edge_more_ranks.h5 -o ranks_plot.png >ranks_plot.log 2>&1 && [[ -s ranks_plot.png ]]; then pass "plot_acor.py: two files on one PNG"; else fail "plot_acor.py"; cat ranks_plot.log; fi
fi

if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
echo "all checks passed"
