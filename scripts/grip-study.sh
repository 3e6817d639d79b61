#!/bin/bash
# The hands' effect on the BBS: R161 at game speed (x = 0.70) and the paper's superball at 1 m/s (x = 0.90, window 20 ms).
B=${1:-build/release/beamimpact}
R="-options_file options/bats/r161.opts -options_file options/balls/baseball.opts -beam_theory timoshenko -options_file options/integrators/rk4.opts -bat_speed 24 -bat_angular_velocity 51 -ball_speed 40 -impact_x 0.70 -impact_window 5e-3"
S="-options_file options/base/aluminium-6mm.opts -options_file options/base/superball-linear.opts -beam_length 1.1 -options_file options/integrators/rk4.opts -impact_x 0.9 -impact_window 0.02"
v(){ h5dump -m %.9g -d /results/$1 ${TMPDIR:-/tmp}/grip-study.h5 | grep -A1 "^   DATA {" | tail -1 | sed 's/.*: //'; }
for base in R S; do for g in "" "-grip 0.05,0.20 -grip_stiffness 1e5 -grip_damping 50" "-grip 0.05,0.20 -grip_stiffness 1e6 -grip_damping 500" "-grip 0.05,0.20 -grip_stiffness 1e6 -grip_damping 500 -grip_mass 1"; do
  timeout 120 $B ${!base} $g -output ${TMPDIR:-/tmp}/grip-study.h5 >/dev/null 2>&1
  echo "$base [$g] bbs $(v bbs) acor $(v acor) peak_grip $(v grip_force_peak) N at $(v grip_force_peak_time) s; U_grip_end $(v grip_stored_end) W_hands $(v hand_work_end) E_err $(v energy_error)"
done; done
