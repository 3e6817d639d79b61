#!/usr/bin/env bash
# The oblique impact against the measurements (issue 24, docs/model.md section 13): spin and
# launch angle over the offset, the program beside the rigid-body impulse model of
# scripts/references/oblique.py with the experiments' parameters, and the published statements.
#
#   scripts/study_oblique.sh [nathan2012|kensrud2017|all]   (default all; EXE=path/to/beamimpact, OUT=dir)
#
# nathan2012: Nathan, Cantakos, Kesman, Mathew & Lukash, Procedia Eng. 34, 182 (2012): a
#   baseball fired horizontally at 100 mph (44.7 m/s, no spin) onto a 3-inch wood cylinder
#   fixed to a wall. Here: a 30 cm solid ash cylinder of 3 in (options/bats/cylinder-3in.profile),
#   clamped at both ends, struck at its middle; offsets 0 to 1.5 in; mu 0.5; e_T 0.2 and 0.4.
# kensrud2017: Kensrud, Nathan & Smith, Sports Eng. (2017): a bat swung at 75 mph at the impact
#   point onto a ball at rest. Here: the R161 (Timoshenko, free) struck with the ball at rest
#   (-ball_speed 0: the run's contact scales come from the bat's approach speed), turning about its knob at
#   48.55 rad/s (V_cm 27.25 m/s), struck 15 cm from the tip (x = 0.69 m); offsets 0 to 1.5 in;
#   mu 0.5; e_T 0.4 (their "up to 40 % above rolling").
# Each row: the program (-impact_tangential_plane flexible and rigid) and the impulse model with
# the program's own normal restitution e (acor for the fixed cylinder; for the swinging bat the
# ratio of the relative normal speeds, from bbs) and the same e_T and mu. The measured points
# of both papers were not found (scripts/references/README.md): their published statements are
# printed beneath. The normal runs by -ts_type modal at 5e-7 s. Prints `uptime` first.
set -euo pipefail
cd "$(dirname "$0")/.."
EXE=${EXE:-build/dev/beamimpact}
OUT=${OUT:-out/oblique-study}
PY=/usr/bin/python3
what=${1:-all}
mkdir -p "$OUT"
source scripts/mpi-env.sh
echo "# $(uptime)"
OFFSETS="impact_offset=0:0.0381:7" # 0, 0.25, ..., 1.5 in
COMMON=(-options_file options/balls/baseball.opts -ts_type modal -ts_dt 5e-7 -ball_friction 0.5 -impact_window 1e-3 -task sweep -output_overwrite)

# sweep NAME ARGS...: one sweep into $OUT/NAME.h5
sweep() {
  local name=$1
  shift
  "$EXE" "${COMMON[@]}" "$@" -output "$OUT/$name.h5" </dev/null >"$OUT/$name.log" 2>&1 || { echo "FAILED: $name (see $OUT/$name.log)"; exit 1; }
}

if [[ $what == all || $what == nathan2012 ]]; then
  CYL=(-beam_profile options/bats/cylinder-3in.profile -beam_youngs_modulus 1.814e10 -beam_density 649 -beam_nodes 61 -beam_left clamped -beam_right clamped -impact_x 0.15 -ball_speed 44.704)
  for eT in 0.2 0.4; do
    sweep "nathan-eT$eT" "${CYL[@]}" -ball_tangential_cor $eT -sweep "$OFFSETS"
    sweep "nathan-eT$eT-rigid" "${CYL[@]}" -ball_tangential_cor $eT -impact_tangential_plane rigid -sweep "$OFFSETS"
  done
  "$PY" scripts/study_oblique.py nathan2012 "$OUT"
fi
if [[ $what == all || $what == kensrud2017 ]]; then
  BAT=(-options_file options/bats/r161.opts -beam_theory timoshenko -bat_speed 27.25 -bat_angular_velocity 48.55 -ball_speed 0 -impact_x 0.69 -ball_tangential_cor 0.4)
  sweep kensrud "${BAT[@]}" -sweep "$OFFSETS"
  sweep kensrud-rigid "${BAT[@]}" -impact_tangential_plane rigid -sweep "$OFFSETS"
  "$PY" scripts/study_oblique.py kensrud2017 "$OUT"
fi
