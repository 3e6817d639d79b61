#!/usr/bin/env bash
# The contact laws through the real executable (model/contact_laws/, one file each, registered
# in model/contact_law.cpp):
#   * -help lists every registered law as a choice of -ball_law, and each law's options;
#   * an unknown law is refused naming every known one; an option of another law than the one
#     chosen is refused naming both laws;
#   * every law runs the default beam (1.1 m, both ends free, struck at 0.9 m by the 42 g ball
#     at 1 m/s, RK4) with the energy balanced to the integrator's accuracy, its ACOR corrected by
#     -ball_loss_factor only when it is elastic (its rigid-wall COR, recorded as ball_wall_cor,
#     is 1), and its parameters and wall values in the run record.
#
#   tests/laws.sh path/to/beamimpact scratch_dir
set -uo pipefail
exe=${1:?usage: laws.sh beamimpact scratch_dir}
dir=${2:?usage: laws.sh beamimpact scratch_dir}
source "$(dirname "$0")/lib.sh"
cd "$(dirname "$0")/.." || exit 2
rm -rf "$dir" && mkdir -p "$dir"

help=$("$exe" -help 2>&1)
laws=$(sed -nE 's/^  -ball_law <.*\(choose one of\) (.*) \(\)$/\1/p' <<<"$help")
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

((fails == 0)) && echo "all law checks passed" || { echo "$fails law check(s) failed"; exit 1; }
