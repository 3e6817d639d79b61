#!/usr/bin/env bash
# -task design through the real executable; one part per ctest test (the last argument):
#   known      the ACOR's maximum along the paper's beam (221 nodes, free-free, the linear ball, the
#              modal integrator) over impact_x, from 0.6 m: the fine sweep's best point (1 mm apart)
#              to its resolution, and its ACOR to 1e-6; the options file holds /design/optimum; with a
#              constraint acor@hit <= 0.597 (almm): the largest ACOR allowed, feasible, the constraint
#              named active; a rerun computes no run; /design/role: the rows TAO's monitor saw (0) are
#              exactly those with a KKT residual, one per iteration, the line search's trials (2) and the
#              differences' points (1) without;
#   gradient   the forward-difference gradient of the ACOR over the scaled Young's modulus at the start
#              (TAO's, from the two designs /design holds) at steps 1e-4 and 1e-3 against central differences
#              of a separate sweep at two relative steps (1e-4, 1e-3): within 2e-3 relative (the
#              forward difference's own error, O(step)); TAO's -tao_test_gradient at the start: TAO's
#              differences and the design's gradient within 1e-2 relative, no option called unused
#              (nor on a rerun that computes nothing);
#   ranks      the same design on 1 and 2 ranks: the same optimum and history to 1e-12;
#   resume     a design stopped after 6 runs (-design_stop_after) and run again: the rerun loads those 6
#              from the journals and computes the fresh design's runs less 6, to the same optimum bit
#              for bit; a third run computes nothing;
#   infeasible feasibility within -tao_catol and a design that ends beyond it: from 0.682 m (ACOR 0.59858) under
#              acor@hit <= 0.597 at -tao_gatol 1e-2 almm (PHR) ends feasible (PETSc 3.18's PHR set -tao_catol to
#              -tao_gatol, 0.01, and stopped "converged" at the start, 2.6e-3 beyond the bound); stopped there
#              (-tao_max_it 0): exit status 3, the violated constraint named with its value and bound, what to try,
#              /design's converged_feasible 0 and status, the options file's second line INFEASIBLE; under
#              acor@hit <= 0.5985 (the start 1.35e-4 beyond it, relative) the start is feasible at -tao_catol 1e-3
#              (/design/feasible 1, exit 0) and infeasible at the default 1e-4 (exit 3); -tao_almm_mu_init under PHR
#              (which ignores it) a note;
#   input      bad input: errors that name the option and what is allowed.
#
#   tests/design_cli.sh path/to/beamimpact scratch_dir mpiexec part
set -uo pipefail
exe=${1:?usage: design_cli.sh beamimpact scratch_dir mpiexec part}
dir=${2:?usage: design_cli.sh beamimpact scratch_dir mpiexec part}
mpiexec=${3:-${MPIEXEC:-mpiexec}}
part=${4:?usage: design_cli.sh beamimpact scratch_dir mpiexec part}
exe=$(readlink -f "$exe")
source "$(dirname "$0")/lib.sh" # MPI env, fail/pass, $python
dir="$dir/$part"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 2
[[ -n "$python" ]] || { echo "SKIP: no Python with h5py"; exit 77; }

scene=(-beam_nodes 221 -ts_type modal -ball_law linear)
design=(-task design -design_variables "impact_x=0.55:1.0:0.6" -design_studies "hit{}" -design_objective "acor@hit" -design_quiet)
optimum() { "$python" -c "import h5py,sys; print('%.17g' % h5py.File(sys.argv[1],'r')['design/optimum'][0])" "$1"; }
near() { "$python" -c "import sys; a,b,t=map(float,sys.argv[1:]); sys.exit(0 if abs(a-b)<=t else 1)" "$1" "$2" "$3"; }
computed() { sed -nE 's/^design: .* runs: ([0-9]+) computed.*/\1/p' "$1"; }

case $part in
known)
  "$exe" "${scene[@]}" -task sweep -sweep "impact_x=0.60:0.75:151" -sweep_quiet -output fine.h5 >fine.log 2>&1 || { fail "the fine sweep failed"; cat fine.log; }
  read -r xbest abest < <("$python" -c "import h5py,numpy as np; r=h5py.File('fine.h5','r')['results']; i=int(np.argmax(r['acor'][()])); print('%.17g %.17g' % (r['impact_x'][i], r['acor'][i]))")
  "$exe" "${scene[@]}" "${design[@]}" -output d.h5 >d.log 2>&1 || { fail "the design failed"; cat d.log; }
  x=$(optimum d.h5)
  near "$x" "$xbest" 1e-3 && pass "the optimum impact_x $x m: the fine sweep's best $xbest m to its 1 mm" || { fail "optimum $x, the sweep's $xbest"; cat d.log; }
  a=$(sed -nE 's/^design: maximised acor@hit = ([0-9.e+-]+) .*/\1/p' d.log)
  "$python" -c "import sys; a,b=map(float,sys.argv[1:]); sys.exit(0 if a >= b - 1e-6 else 1)" "$a" "$abest" && pass "its ACOR $a >= the sweep's best $abest - 1e-6" || fail "its ACOR $a below the sweep's $abest"
  grep -q "^-impact_x $x\$" d.opts && head -1 d.opts | grep -q "^# beamimpact -task design: the optimum" && pass "d.opts holds /design/optimum exactly" || { fail "d.opts"; cat d.opts; }
  [[ ! -e d.h5.parts ]] && pass "a finished design leaves no journals" || fail "d.h5.parts left"
  "$exe" "${scene[@]}" "${design[@]}" -output d.h5 >again.log 2>&1 && [[ $(computed again.log) == 0 ]] && pass "a rerun computes no run" || fail "the rerun computed $(computed again.log) runs"
  # the roles: an iterate (0) is a row the monitor marked (a finite KKT residual), one per iteration (0..N), a
  # line search's trial (2) is a point TAO asked for that no iteration took; the constrained run has both
  "$python" - d.h5 <<'PY' && pass "/design/role: the iterates exactly the monitor's rows (one per iteration), trials (2) and differences (1) apart" || fail "/design/role"
import h5py, numpy as np, sys
d = h5py.File(sys.argv[1], "r")["design"]
role, kkt, it = d["role"][()], d["kkt_residual"][()], d["iteration"][()]
print("   roles:", {int(r): int((role == r).sum()) for r in np.unique(role)})
ok = set(np.unique(role)) <= {0, 1, 2} and np.array_equal(role == 0, np.isfinite(kkt))
ok = ok and (role == 2).sum() > 0 and sorted(it[role == 0]) == list(range((role == 0).sum()))
sys.exit(0 if ok else 1)
PY
  # constrained: the largest ACOR below 0.597 (on the rising side from 0.6 m: the sweep's crossing)
  "$exe" "${scene[@]}" "${design[@]}" -design_constraints "acor@hit<=0.597" -output c.h5 >c.log 2>&1 || { fail "the constrained design failed"; cat c.log; }
  xc=$("$python" -c "
import h5py,numpy as np; r=h5py.File('fine.h5','r')['results']; x=r['impact_x'][()]; a=r['acor'][()]
i=np.nonzero((a[:-1]<0.597)&(a[1:]>=0.597))[0][0]; print('%.17g' % (x[i]+(0.597-a[i])*(x[i+1]-x[i])/(a[i+1]-a[i])))")
  x=$(optimum c.h5)
  near "$x" "$xc" 1e-3 && pass "constrained: impact_x $x m, the sweep's crossing of 0.597 at $xc m" || { fail "constrained optimum $x, the crossing $xc"; cat c.log; }
  grep -q "acor@hit .* <= 0.597  (active)" c.log && grep -q "^design: feasible" c.log && pass "the constraint is named active, the optimum feasible" || { fail "constraint report"; cat c.log; }
  # almm's iterates are its outer iterations only (its subsolver's are not TAO's: no monitor of the program there)
  n=$(sed -nE 's/^design: TAO almm: .* after ([0-9]+) iterations.*/\1/p' c.log)
  "$python" - c.h5 "$n" <<'PY' && pass "almm: /design's iterates (role 0) one per outer iteration 0..$n" || fail "almm's iterates in /design"
import h5py, numpy as np, sys
d, n = h5py.File(sys.argv[1], "r")["design"], int(sys.argv[2])
it = d["iteration"][()][d["role"][()] == 0]
print("   iterations of the iterates:", sorted(int(i) for i in it), "TAO's:", n)
sys.exit(0 if len(set(it)) == len(it) and set(it) <= set(range(n + 1)) else 1)
PY
  ;;
gradient)
  # d acor / d u of E = 5e10 + u 4e10 at 7e10 Pa (impact_x 0.62 m): smooth in E (no node crossed)
  gd=(-task design -design_variables "beam_youngs_modulus=5e10:9e10:7e10" -design_studies "hit{impact_x=0.62}" -design_objective "acor@hit" -design_quiet -tao_max_it 0)
  for h in 1e-4 1e-3; do
    "$exe" "${scene[@]}" -impact_x 0.62 -task sweep -sweep "beam_youngs_modulus=$("$python" -c "print('%.17g;%.17g' % (7e10*(1-$h), 7e10*(1+$h)))")" -sweep_quiet -output c$h.h5 >c.log 2>&1 || { fail "the sweep failed"; cat c.log; }
    gc=$("$python" -c "import h5py; a=h5py.File('c$h.h5','r')['results/acor'][()]; print('%.17g' % (abs(a[1]-a[0])/(2*$h*7e10)*4e10))")
    for s in 1e-4 1e-3; do
      "$exe" "${scene[@]}" "${gd[@]}" -design_difference_step $s -output g$s.h5 >g.log 2>&1 || { fail "the design failed"; cat g.log; }
      # TAO's gradient: the iterate's and its difference point's objectives in /design (role 0 and 1)
      g=$("$python" -c "import h5py,numpy as np; d=h5py.File('g$s.h5','r')['design']; E=d['beam_youngs_modulus'][()]; a=d['objective'][()]; print('%.17g' % abs((a[1]-a[0])/(E[1]-E[0])*4e10))")
      "$python" -c "import sys; a,b=map(float,sys.argv[1:]); print('   forward step %s: %.8g, central (h %s): %.8g, relative %.2g' % ('$s', a, '$h', b, abs(a-b)/b)); sys.exit(0 if abs(a-b)<=2e-3*b else 1)" "$g" "$gc" \
        && pass "gradient at step $s against central differences at h $h" || fail "gradient $g at step $s, central $gc at h $h"
    done
  done
  # TAO's own gradient test (-tao_test_gradient: TAO's finite differences against the design's
  # gradient at the start): the two within 1e-2 relative, the angle's cosine 1; the test's
  # option read (no note), and on a rerun that computes nothing no option is called unused
  "$exe" "${scene[@]}" "${gd[@]}" -tao_test_gradient -output t.h5 >t.log 2>&1 || { fail "the gradient test failed"; cat t.log; }
  rel=$(sed -nE 's/^ *2-norm \|\|G - Gfd\|\|\/\|\|G\|\| = ([0-9.e+-]+),.*/\1/p' t.log | head -1)
  [[ -n $rel ]] && "$python" -c "import sys; sys.exit(0 if float(sys.argv[1]) <= 1e-2 else 1)" "$rel" &&
    grep -q "angle cosine = (Gfd'G)/||Gfd||||G|| = 1\." t.log &&
    pass "TAO's gradient test: ||G - Gfd||/||G|| = $rel" || { fail "TAO's gradient test: '$rel'"; cat t.log; }
  grep -q "not used" t.log && fail "a note calls an option unused: $(grep 'not used' t.log)" || pass "-tao_test_gradient read, no note"
  "$exe" "${scene[@]}" "${gd[@]}" -tao_test_gradient -output t.h5 >t2.log 2>&1 && ! grep -q "not used" t2.log &&
    pass "a rerun that computes nothing calls no option unused" || { fail "the rerun's notes"; cat t2.log; }
  ;;
ranks)
  "$exe" "${scene[@]}" "${design[@]}" -output one.h5 >one.log 2>&1 || { fail "1 rank failed"; cat one.log; }
  "$mpiexec" -n 2 "$exe" "${scene[@]}" "${design[@]}" -output two.h5 >two.log 2>&1 || { fail "2 ranks failed"; cat two.log; }
  "$python" - <<'PY' && pass "1 and 2 ranks: the same optimum and history to 1e-12" || fail "1 and 2 ranks differ"
import h5py, numpy as np
a, b = h5py.File("one.h5", "r")["design"], h5py.File("two.h5", "r")["design"]
bad = 0
for k in ("optimum", "objective", "impact_x", "kkt_residual"):
    x, y = a[k][()], b[k][()]
    ok = x.shape == y.shape and np.allclose(x, y, rtol=1e-12, atol=0, equal_nan=True)
    print("   %-14s %s" % (k, "same" if ok else "differs"))
    bad += not ok
raise SystemExit(bad)
PY
  ;;
resume)
  "$exe" "${scene[@]}" "${design[@]}" -output fresh.h5 >fresh.log 2>&1 || { fail "the fresh design failed"; cat fresh.log; }
  n=$(computed fresh.log)
  "$exe" "${scene[@]}" "${design[@]}" -design_stop_after 6 -output r.h5 >stop.log 2>&1 && fail "-design_stop_after 6 did not stop the design"
  [[ -d r.h5.parts ]] && pass "the stopped design left its journals" || fail "no r.h5.parts after the stop"
  "$exe" "${scene[@]}" "${design[@]}" -output r.h5 >resume.log 2>&1 || { fail "the resumed design failed"; cat resume.log; }
  grep -q "6 runs known from an earlier design" resume.log && [[ $(computed resume.log) == $((n - 6)) ]] && pass "the resume loads 6 runs and computes $((n - 6)) of $n" \
    || { fail "the resume computed $(computed resume.log) of $n"; grep "known\|runs:" resume.log; }
  [[ $(optimum r.h5) == $(optimum fresh.h5) ]] && pass "the same optimum bit for bit" || fail "optimum $(optimum r.h5), fresh $(optimum fresh.h5)"
  "$exe" "${scene[@]}" "${design[@]}" -output r.h5 >third.log 2>&1 && [[ $(computed third.log) == 0 ]] && pass "a third run computes nothing" || fail "the third run computed $(computed third.log)"
  ;;
infeasible)
  con=(-design_constraints "acor@hit<=0.597")
  start=(-design_variables "impact_x=0.55:1.0:0.682") # the ACOR's maximum, 0.59858: 2.6e-3 beyond 0.597 (relative)
  "$exe" "${scene[@]}" "${design[@]}" "${start[@]}" "${con[@]}" -tao_gatol 1e-2 -tao_almm_mu_init 1e4 -output g.h5 >g.log 2>&1
  rc=$?
  ((rc == 0)) && grep -q "^design: feasible: every constraint holds within -tao_catol 0.0001" g.log && grep -q "keeps -tao_catol 0.0001" g.log \
    && pass "-tao_gatol 1e-2: almm (PHR) ends feasible, -tao_catol 1e-4 kept (the note says so)" || { fail "-tao_gatol 1e-2: exit $rc"; cat g.log; }
  grep -q "^design: note: -tao_almm_mu_init has no effect: almm's PHR formulation" g.log && pass "-tao_almm_mu_init under PHR: a note, no effect" || fail "no note on -tao_almm_mu_init"
  "$exe" "${scene[@]}" "${design[@]}" "${start[@]}" "${con[@]}" -tao_max_it 0 -output s.h5 >s.log 2>&1
  rc=$?
  ((rc == 3)) && pass "stopped beyond the bound: exit status 3" || { fail "exit status $rc, not 3"; cat s.log; }
  grep -q "^design: INFEASIBLE: the run ended at a design that violates 1 constraint" s.log \
    && grep -q "^design:   violated: acor@hit = 0.5985810.*, its bound <= 0.597" s.log && grep -q "^design: try: a smaller -tao_gatol" s.log \
    && pass "the summary: INFEASIBLE, the constraint, its value and bound, what to try" || { fail "the summary"; cat s.log; }
  ! grep -q "^design: feasible" s.log && pass "... and no feasible line" || fail "a feasible line beside INFEASIBLE"
  "$python" -c "
import h5py, sys; d = h5py.File('s.h5', 'r')['design']; s = d.attrs['status']; s = s.decode() if isinstance(s, bytes) else s
print('   converged_feasible', d.attrs['converged_feasible'], 'status', s, 'feasible', list(d['feasible'][()]))
sys.exit(0 if d.attrs['converged_feasible'] == 0 and s.startswith('INFEASIBLE') and 'acor@hit' in s and d['feasible'][0] == 0 else 1)" \
    && pass "/design: converged_feasible 0, its status names the constraint" || fail "/design's status"
  sed -n 2p s.opts | grep -q "^# INFEASIBLE: NOT an optimum" && pass "the options file's second line: INFEASIBLE" || { fail "s.opts"; head -3 s.opts; }
  # within -tao_catol is feasible: the start 1.35e-4 beyond 0.5985
  near=(-design_constraints "acor@hit<=0.5985" -tao_max_it 0)
  "$exe" "${scene[@]}" "${design[@]}" "${start[@]}" "${near[@]}" -tao_catol 1e-3 -output w.h5 >w.log 2>&1
  rc=$?
  ((rc == 0)) && grep -q "^design: feasible: every constraint holds within -tao_catol 0.001" w.log \
    && "$python" -c "import h5py,sys; d=h5py.File('w.h5','r')['design']; sys.exit(0 if d['feasible'][0] == 1 and d.attrs['converged_feasible'] == 1 else 1)" \
    && pass "1.35e-4 beyond the bound, -tao_catol 1e-3: feasible (summary, /design/feasible, converged_feasible)" || { fail "within -tao_catol: exit $rc"; cat w.log; }
  "$exe" "${scene[@]}" "${design[@]}" "${start[@]}" "${near[@]}" -output x.h5 >x.log 2>&1
  rc=$?
  ((rc == 3)) && "$python" -c "import h5py,sys; sys.exit(0 if h5py.File('x.h5','r')['design/feasible'][0] == 0 else 1)" \
    && pass "... and at the default -tao_catol 1e-4: infeasible, exit 3" || { fail "beyond -tao_catol 1e-4: exit $rc"; cat x.log; }
  ;;
input)
  expect() { # expect REGEX ARGS...: the run fails with a message matching REGEX
    local re=$1; shift
    if "$exe" "${scene[@]}" "$@" -output none >in.log 2>&1; then fail "accepted: $*"; elif grep -Eq -- "$re" in.log; then pass "refused: $re"; else fail "message for $*: $(grep -m1 error in.log)"; fi
  }
  expect "needs its variables: -design_variables" -task design -design_objective "mass"
  expect "needs its objective: -design_objective" -task design -design_variables "impact_x=0.5:0.9"
  expect "-design_objective \"bogus@hit\" is not allowed: 'bogus@hit': bogus is not a column" "${design[@]}" -design_objective "bogus@hit"
  expect "no study rig in -design_studies" "${design[@]}" -design_objective "max(bbcor@rig)"
  expect "the reduction 'top' is not max, min or mean" "${design[@]}" -design_objective "top(acor@hit)"
  expect "has 3 points: say max" "${design[@]}" -design_studies "hit{ball_speed=1:3:3}"
  expect "'acor@hit<0.5' is not QUANTITY<=BOUND" "${design[@]}" -design_constraints "acor@hit<0.5"
  expect "the study hit sets impact_x, a design variable" "${design[@]}" -design_studies "hit{impact_x=0.5}"
  expect "-design_studies: 'hit' is not NAME\{SETTING,...\}" "${design[@]}" -design_studies "hit"
  expect "neither REDUCTION\(COLUMN@STUDY\) nor COLUMN@STUDY nor a number of the bat" "${design[@]}" -design_objective "weight"
  expect "-tao_type almm needs constraints" "${design[@]}" -tao_type almm
  expect "-tao_type bqnls ignores -design_constraints: with constraints the design needs almm" "${design[@]}" -design_constraints "acor@hit<=0.597" -tao_type bqnls
  ;;
*) echo "unknown part $part"; exit 2 ;;
esac
((fails == 0)) && echo "design_cli $part: all passed" || { echo "design_cli $part: $fails failed"; exit 1; }
