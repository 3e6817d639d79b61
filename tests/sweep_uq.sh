#!/usr/bin/env bash
# Sampled sweeps through the real executable (docs/uncertainty.md), on the paper's linear beam
# struck by the linear-spring superball (options/base/default-scene.opts, -ts_type modal):
#   1. a sampled sweep with Saltelli's design on 1 and 2 ranks: identical files (every dataset
#      but wall_time bit for bit, /statistics, /exceedance and /sobol included);
#   2. the known answer: the linear system's ACOR does not depend on the ball's speed, so its
#      Sobol' indices for ball_speed are 0 (within 1e-6 and inside their intervals) while
#      impact_x's total index is near 1 (its interval reaching 0.95);
#   3. the mean of the sampled ACOR (impact_x uniform on [0.3, 0.8]; random and Sobol' points)
#      against the integral of a fine grid sweep (101 points, Simpson) within 3 reported standard
#      errors; the quantiles against the grid's empirical quantiles;
#   4. an empirical CSV axis read from an options file's directory, a table axis, a grid axis
#      times the sample (the same sample rows at each grid value);
#   5. bad specs refused before any work, the message naming the option, the value and what is
#      allowed; the sampling options without a sampled axis a note;
#   6. scripts/h5_to_csv.py exports /statistics, /exceedance and /sobol.
#
#   tests/sweep_uq.sh path/to/beamimpact scratch_dir [mpiexec]
set -uo pipefail

exe=${1:?usage: sweep_uq.sh beamimpact scratch_dir [mpiexec]}
dir=${2:?usage: sweep_uq.sh beamimpact scratch_dir [mpiexec]}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
exe=$(readlink -f "$exe")
src=$(readlink -f "$(dirname "${BASH_SOURCE[0]}")/..")
[[ -x "$exe" ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && cd "$dir" || exit 1
rm -rf uq_* uqdir
source "$src/tests/lib.sh" # MPI env, fail/pass, $python
[[ -n "$python" ]] || { echo "SKIP: no Python with h5py and numpy"; exit 77; }

scene=(-options_file "$src/options/base/default-scene.opts" -task sweep -sweep_quiet)

# 1. ranks
sobol=("${scene[@]}" -sweep "impact_x=uniform:0.3:0.8,ball_speed=uniform:0.5:2" -sweep_samples 64 -sweep_sampling sobol -sweep_sobol -sweep_exceedance "acor>0.59,bbs<=0.6")
"$exe" "${sobol[@]}" -output uq_np1.h5 >uq_np1.log 2>&1 || { fail "1-rank sampled sweep"; cat uq_np1.log; }
"$mpiexec" -n 2 "$exe" "${sobol[@]}" -output uq_np2.h5 >uq_np2.log 2>&1 || { fail "2-rank sampled sweep"; cat uq_np2.log; }
"$python" - uq_np1.h5 uq_np2.h5 <<'PY' && pass "1 and 2 ranks: identical points, /statistics, /exceedance and /sobol" || fail "1 and 2 ranks differ"
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = []
def walk(g, h, path):
    if set(g.keys()) != set(h.keys()): bad.append(path + ": members differ")
    for k in g:
        p = path + "/" + k
        if isinstance(g[k], h5py.Group): walk(g[k], h[k], p)
        elif p != "/results/wall_time" and not np.array_equal(g[k][()], h[k][()], equal_nan=g[k].dtype.kind == "f"): bad.append(p)
walk(a, b, "")
for g in ("statistics", "sobol", "exceedance"):
    if g not in a: bad.append("no /" + g)
assert a["results/case_index"].shape == (256,), a["results/case_index"].shape  # N (d + 2) = 64 * 4
for m in bad: print("   ", m)
sys.exit(1 if bad else 0)
PY

# 2. the known answer
"$python" - uq_np1.h5 <<'PY' && pass "ACOR's Sobol' indices: ball_speed 0, impact_x total near 1" || fail "ACOR's Sobol' indices"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
s = f["sobol/acor"]
inputs = [x.decode() if isinstance(x, bytes) else x for x in s.attrs["inputs"]]
assert inputs == ["impact_x", "ball_speed"], inputs
S, T, Sci, Tci = s["first"][0], s["total"][0], s["first_ci"][0], s["total_ci"][0]
print("      S", S, "ST", T, "ST interval", Tci.tolist())
assert abs(S[1]) < 1e-6 and abs(T[1]) < 1e-6, (S, T)
assert Sci[1][0] <= S[1] <= Sci[1][1] and Tci[1][0] <= T[1] <= Tci[1][1]
assert T[0] > 0.8 and Tci[0][1] >= 0.95, (T, Tci)
assert s["first"].attrs["units"] in ("1", b"1")
e = f["exceedance/acor>0.59"]
p, lo, hi = e["probability"][0], e["ci_low"][0], e["ci_high"][0]
acor = f["results/acor"][()].reshape(64, 4)[:, :2].ravel()  # A and B rows
assert p == np.mean(acor > 0.59) and lo < p < hi, (p, lo, hi)
PY

# 3. the mean against the integral of a fine grid sweep
"$exe" "${scene[@]}" -sweep "impact_x=0.3:0.8:101" -output uq_grid.h5 >uq_grid.log 2>&1 || { fail "grid sweep"; cat uq_grid.log; }
for sampling in random sobol; do
  "$exe" "${scene[@]}" -sweep "impact_x=uniform:0.3:0.8" -sweep_samples 200 -sweep_sampling $sampling -sweep_seed 5 -output uq_mean_$sampling.h5 >uq_mean_$sampling.log 2>&1 \
    || { fail "$sampling sweep"; cat uq_mean_$sampling.log; }
  "$python" - uq_grid.h5 uq_mean_$sampling.h5 $sampling <<'PY' && pass "$sampling: mean ACOR within 3 standard errors of the grid's integral" || fail "$sampling: mean against the grid"
import sys, h5py, numpy as np
g, s = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
y = g["results/acor"][()]
h = 0.5 / 100
integral = h / 3 * (y[0] + y[-1] + 4 * y[1:-1:2].sum() + 2 * y[2:-1:2].sum()) / 0.5  # Simpson, over the interval's length
st = s["statistics/acor"]
mean, sem = st["mean"][0], st["sem"][0]
print("      %s: mean %.6f +- %.2g, grid %.6f, difference %.2f sem" % (sys.argv[3], mean, sem, integral, (mean - integral) / sem))
assert abs(mean - integral) < 3 * sem, (mean, integral, sem)
assert st["count"][0] == 200 and s["statistics/points"][0] == 200 and s["statistics/failed"][0] == 0
assert abs(st["q50"][0] - np.median(y)) < 4 * st["q50_se"][0] + 1e-4, (st["q50"][0], np.median(y))
PY
done

# 4. a CSV of measured values from an options file's directory, a table, and a grid axis times the sample
mkdir -p uqdir/sub
printf '# measured impact points (m)\nplayer,x\n1,0.52\n2,0.55\n3,0.61\n4,0.58\n' >uqdir/sub/points.csv
printf -- '-sweep "impact_x=csv:points.csv:x,ball_speed=1@1;2@3,beam_nodes=21;41"\n' >uqdir/sub/study.opts
"$exe" "${scene[@]}" -options_file uqdir/sub/study.opts -sweep_samples 16 -output uq_csv.h5 >uq_csv.log 2>&1 || { fail "CSV axis"; cat uq_csv.log; }
"$python" - uq_csv.h5 <<'PY' && pass "CSV and table axes; the grid axis times the same sample rows" || fail "CSV and table axes"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
x, v, n = f["results/impact_x"][()], f["results/ball_speed"][()], f["results/beam_nodes"][()]
assert set(x) <= {0.52, 0.55, 0.61, 0.58} and set(v) <= {1, 2}, (set(x), set(v))
assert list(n) == [21] * 16 + [41] * 16 and np.array_equal(x[:16], x[16:]) and np.array_equal(v[:16], v[16:])
assert list(f["statistics/beam_nodes"][()]) == [21, 41] and f["statistics/acor/mean"].shape == (2,)
PY

# 5. refusals
refused() { # refused NAME PATTERN... -- OPTIONS: the run fails before any work with every PATTERN in its message
  local name=$1 out
  shift
  local pats=()
  while [[ $1 != -- ]]; do pats+=("$1"); shift; done
  shift
  if out=$("$exe" "${scene[@]}" "$@" -output uq_bad.h5 2>&1); then fail "$name: accepted"; return; fi
  for p in "${pats[@]}"; do grep -qF -- "$p" <<<"$out" || { fail "$name: the message lacks '$p': $out"; return; }; done
  [[ -e uq_bad.h5 ]] && { fail "$name: wrote a file"; rm -f uq_bad.h5; return; }
  pass "$name refused: $(grep -m1 -F -- "${pats[0]}" <<<"$out" | cut -c1-150)"
}
refused "a law's parameters" '-sweep "impact_x=normal:0.7"' "normal:MEAN:STD" -- -sweep "impact_x=normal:0.7" -sweep_samples 10
refused "a negative STD" "STD must be > 0" -- -sweep "impact_x=normal:0.7:-0.1" -sweep_samples 10
refused "an unknown law" "'gauss' is not a distribution" "truncnormal:MEAN:STD:LO:HI" -- -sweep "impact_x=gauss:0.7:0.1" -sweep_samples 10
refused "a text option sampled" "ts_type=normal:1:2" "only a numeric option" -- -sweep "ts_type=normal:1:2" -sweep_samples 10
refused "a whole-number option" "beam_nodes=normal:30:2" "whole numbers" -- -sweep "beam_nodes=normal:30:2" -sweep_samples 10
refused "no -sweep_samples" "-sweep_samples N" -- -sweep "impact_x=uniform:0.3:0.8"
refused "a bad -sweep_samples" "-sweep_samples" -- -sweep "impact_x=uniform:0.3:0.8" -sweep_samples 0
refused "a bad -sweep_sampling" "-sweep_sampling" "sobolx" "random" -- -sweep "impact_x=uniform:0.3:0.8" -sweep_samples 10 -sweep_sampling sobolx
refused "an unknown exceedance column" '-sweep_exceedance "acorr>0.5"' "'acorr' is not a numeric column" -- -sweep "impact_x=uniform:0.3:0.8" -sweep_samples 10 -sweep_exceedance "acorr>0.5"
refused "an exceedance without a value" "is not COLUMN>VALUE" -- -sweep "impact_x=uniform:0.3:0.8" -sweep_samples 10 -sweep_exceedance "acor>"
refused "a missing CSV" "csv:nonexistent.csv" "cannot open" -- -sweep "impact_x=csv:nonexistent.csv" -sweep_samples 10
out=$("$exe" "${scene[@]}" -sweep "impact_x=0.4;0.5" -sweep_samples 10 -sweep_sobol -output uq_note.h5 2>&1)
grep -q "note: -sweep_samples has no effect: no axis of the sweep is sampled" <<<"$out" && grep -q "note: -sweep_sobol has no effect" <<<"$out" \
  && pass "the sampling options without a sampled axis: notes" || fail "no note for -sweep_samples without a sampled axis: $out"

# 6. the export
for g in statistics exceedance sobol; do
  "$python" "$src/scripts/h5_to_csv.py" uq_np1.h5 $g --units none -o uq_$g.csv 2>uq_csv_$g.log || { fail "h5_to_csv.py $g"; cat uq_csv_$g.log; }
done
"$python" - <<'PY' && pass "h5_to_csv.py: /statistics, /exceedance and /sobol as tables" || fail "h5_to_csv.py tables"
import csv, h5py
f = h5py.File("uq_np1.h5", "r")
st = list(csv.DictReader(open("uq_statistics.csv")))
row = [r for r in st if r["column"] == "acor"][0]
assert float(row["mean"]) == f["statistics/acor/mean"][0] and "q95_se" in row, row
so = list(csv.DictReader(open("uq_sobol.csv")))
r = [r for r in so if r["column"] == "acor" and r["input"] == "impact_x"][0]
assert float(r["total"]) == f["sobol/acor/total"][0][0] and float(r["total_high"]) == f["sobol/acor/total_ci"][0][0][1]
ex = list(csv.DictReader(open("uq_exceedance.csv")))
assert [r["condition"] for r in ex] == ["acor>0.59", "bbs<=0.6"], ex
PY

if ((fails)); then echo "$fails check(s) failed"; exit 1; fi
echo "all checks passed"
