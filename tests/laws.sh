#!/usr/bin/env bash
# The contact laws through the real executable (model/contact_laws/, one file each, registered
# in model/contact_law.cpp):
#   * -help lists every registered law as a choice of -ball_law, and each law's options;
#   * an unknown law is refused naming every known one; an option of another law than the one
#     chosen is refused naming both laws;
#   * every law runs the default beam (1.1 m, both ends free, struck at 0.9 m by the 42 g ball
#     at 1 m/s, RK4) with the energy balanced to the integrator's accuracy, its ACOR corrected by
#     -ball_loss_factor only when it is elastic (its rigid-wall COR, recorded as ball_wall_cor,
#     is 1), and its parameters and wall values in the run record;
#   * the Hertz ball's recorded wall values against its closed form, and its energy balance
#     falling with the step.
#
#   tests/laws.sh path/to/beamimpact scratch_dir
set -uo pipefail
exe=${1:?usage: laws.sh beamimpact scratch_dir}
dir=${2:?usage: laws.sh beamimpact scratch_dir}
source "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.." || exit 2
rm -rf "$dir" && mkdir -p "$dir"

help=$("$exe" -help 2>&1)
laws=$(sed -nE 's/^  -ball_law <.*\(choose one of\) (.*) \(docs\/options\.md\)$/\1/p' <<<"$help")
[[ $laws == *linear* && $laws == *hysteresis* ]] && pass "-help lists the laws: $laws" || fail "-help: -ball_law choices '$laws'"
for opt in -ball_k -ball_k1 -ball_m -ball_n -ball_cor -ball_contact_time -ball_test_speed -ball_cor_table; do
  grep -qE -- "^  $opt <" <<<"$help" || fail "-help does not list $opt"
done

out=$("$exe" -options_file options/impact.opts -ball_law rubber -output none 2>&1); rc=$?
known=$(sed 's/ /, /g' <<<"$laws")
[[ $rc -ne 0 ]] && grep -q -- "-ball_law rubber is not known: use one of $known" <<<"$out" && pass "an unknown law is refused naming $known" || fail "-ball_law rubber: exit $rc: $out"
out=$("$exe" -options_file options/impact.opts -ball_law hysteresis -output none 2>&1); rc=$?
[[ $rc -ne 0 ]] && grep -q -- "-ball_k is a linear parameter but -ball_law is hysteresis: give -ball_law linear, or the hysteresis law's options (-ball_k1" <<<"$out" &&
  pass "an option of another law is refused naming both laws" || fail "-ball_k with -ball_law hysteresis: exit $rc: $out"

scene=(-options_file options/base/aluminium-6mm.opts -options_file options/integrators/rk4.opts -beam_length 1.1 -beam_left free -beam_right free
  -ball_mass 0.042 -ball_speed 1 -task impact -impact_x 0.9)
for law in $laws; do
  out=$("$exe" "${scene[@]}" -ball_law "$law" -output "$dir/$law.h5" 2>&1); rc=$?
  if [[ $rc -ne 0 ]]; then fail "-ball_law $law on the default beam: exit $rc: $out"; continue; fi
  [[ -n $python ]] || continue
  msg=$("$python" - "$dir/$law.h5" "$law" <<'PY'
import h5py, sys
f = h5py.File(sys.argv[1]); a = f.attrs; r = lambda k: float(f["results"][k][0])
law = a["ball_law"].decode() if isinstance(a["ball_law"], bytes) else a["ball_law"]
e_wall, lf = float(a["ball_wall_cor"]), float(a["ball_loss_factor"])
bad = []
if law != sys.argv[2]: bad.append("ball_law %s" % law)
if abs(r("energy_error")) > 1e-5: bad.append("energy_error %.3g" % r("energy_error"))
elastic = e_wall == 1.0
want = r("acor") * (lf if elastic else 1.0)
if abs(r("acor_corrected") - want) > 1e-15: bad.append("acor_corrected %.17g, want %.17g" % (r("acor_corrected"), want))
if not (0 < e_wall <= 1 and float(a["ball_wall_contact_time"]) > 0 and float(a["ball_wall_max_compression"]) > 0): bad.append("wall values")
if elastic and abs(r("ball_dissipated_end")) > 1e-12: bad.append("an elastic ball dissipated %.3g J" % r("ball_dissipated_end"))
if not elastic and not r("ball_dissipated_end") > 0: bad.append("a lossy ball dissipated nothing")
print("; ".join(bad) if bad else "ok energy_error %.2g, acor %.6f, acor_corrected %.6f, wall e %.4f, tau %.4g s" % (r("energy_error"), r("acor"), r("acor_corrected"), e_wall, float(a["ball_wall_contact_time"])))
PY
)
  [[ $msg == ok* ]] && pass "-ball_law $law: ${msg#ok }" || fail "-ball_law $law: $msg"
done

# The Hertz ball (F = k c^(3/2), k = 5e5 N/m^(3/2), 42 g): its recorded wall values against the
# closed form of a power law p = 3/2 (c_max = ((p+1) m v^2/(2k))^(1/(p+1)),
# t = 2 (c_max/v) B(1/(p+1), 1/2)/(p+1)), and its energy balance on the default beam falling
# with RK4's step (at least as dt^2: the force is not C^2 at c = 0).
for dt in 1e-5 5e-6; do
  "$exe" "${scene[@]}" -ball_law hertz -ts_dt $dt -output "$dir/hertz-$dt.h5" >"$dir/hertz-$dt.txt" 2>&1 || fail "-ball_law hertz -ts_dt $dt: $(cat "$dir/hertz-$dt.txt")"
done
if [[ -n $python ]]; then
  msg=$("$python" - "$dir/hertz-1e-5.h5" "$dir/hertz-5e-6.h5" <<'PY'
import h5py, math, sys
f1, f2 = h5py.File(sys.argv[1]), h5py.File(sys.argv[2]); a = f1.attrs
m, v, k, p = float(a["ball_mass"]), float(a["ball_speed"]), float(a["ball_hertz_k"]), 1.5
c_max = ((p + 1) * m * v * v / (2 * k)) ** (1 / (p + 1))
q = 1 / (p + 1); tau = 2 * c_max / v * math.gamma(q) * math.gamma(0.5) / math.gamma(q + 0.5) / (p + 1)
e1, e2 = (abs(float(f["results"]["energy_error"][0])) for f in (f1, f2))
bad = []
if k != 5e5: bad.append("ball_hertz_k %g" % k)
if abs(float(a["ball_wall_max_compression"]) / c_max - 1) > 1e-12: bad.append("ball_wall_max_compression %.17g, closed form %.17g" % (float(a["ball_wall_max_compression"]), c_max))
if abs(float(a["ball_wall_contact_time"]) / tau - 1) > 1e-12: bad.append("ball_wall_contact_time %.17g, closed form %.17g" % (float(a["ball_wall_contact_time"]), tau))
if float(a["ball_wall_cor"]) != 1.0: bad.append("ball_wall_cor %g" % float(a["ball_wall_cor"]))
if not (e1 < 3e-8 and e1 / e2 > 4.5): bad.append("energy_error %.3g at 1e-5 s, %.3g at 5e-6 s" % (e1, e2))
print("; ".join(bad) if bad else "ok wall tau %.6g s and c_max %.6g m as the closed form; energy_error %.2g -> %.2g (x%.1f) when dt halves" % (tau, c_max, e1, e2, e1 / e2))
PY
)
  [[ $msg == ok* ]] && pass "-ball_law hertz: ${msg#ok }" || fail "-ball_law hertz: $msg"
fi

((fails == 0)) && echo "all law checks passed" || { echo "$fails law check(s) failed"; exit 1; }
