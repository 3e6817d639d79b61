#!/usr/bin/env bash
# The strung racket against the published anchors (issue 25, docs/racket-anchors.md): rebound
# speed over impact sites and speeds in the conditions of Glynn, King & Mitchell 2011, Goodwill &
# Haake 2001 and Cross & Lindsey's hand-held racket; power and dwell time against string tension
# (Cross 2000; Bower & Cross 2005 in play) with a stiffer frame; the free frame's fundamental and the bed's frequency against
# measured rackets. The racket is options/bats/racket-pure-drive.opts (mass, balance and
# swingweight of a measured Babolat Pure Drive), the ball options/balls/tennis-ball-fast.opts.
#
#   scripts/study_racket.sh [sites|tension|modes|all]   (default all; EXE=path/to/beamimpact, OUT=dir)
#
# sites:   a free racket, 3 x 2 sites (x = head centre, +-8 cm; z = 0, 6 cm) x 6 speeds 16-27 m/s
#          x 2 tensions (210, 270 N): Glynn et al.'s grid (their 9 sites, 6 speeds, 2 tensions;
#          their sites, tensions and measured speeds were not found, these are ours). Across the
#          face at 16.5 m/s (Cross & Lindsey's hand-held racket). Goodwill & Haake's supports: the
#          head clamped (-strings_frame held) at the string centre, 15-30 m/s, and the racket
#          pinned at its tip (-beam_right pinned), 3 sites on the axis, 25 m/s.
# tension: a free racket struck at the head's centre, 200-300 N, 15 and 25 m/s; the same with
#          the frame's EI doubled (a property table written into OUT); 180 and 280 N at 25 and
#          30 m/s against the ball speeds Bower & Cross 2005 measured in play.
# modes:   -task modes of the free strung racket, and of the bed in a held frame at 250 N and at
#          175 N (the tension left after stringing, Cross & Bower 2001).
# REUSE=1 keeps the files of an earlier run. Every impact by -ts_type modal (the structure is linear; exact between the contact's steps).
# Costs about 3 minutes of one core on an idle machine. Prints `uptime` first.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/find-exe.sh
EXE=$(find_beamimpact study_racket.sh "${EXE:-}")
OUT=${OUT:-out/racket-study}
PY=/usr/bin/python3
what=${1:-all}
mkdir -p "$OUT"
source scripts/mpi-env.sh
echo "# $(uptime)"
RACKET=(-options_file options/bats/racket-pure-drive.opts -options_file options/balls/tennis-ball-fast.opts -ts_type modal)
XC=0.5075 # the head's centre (-head_center), from the butt
# the stiffer frame: the shipped table with EI (column 2) doubled
awk '/^#/ || NF == 0 {print; next} {$2 = 2 * $2; print}' options/bats/racket-pure-drive.properties >"$OUT/stiff.properties"

# run NAME ARGS...: one run (-task sweep or modes) into $OUT/NAME.h5 (REUSE=1: keep an existing one)
run() {
  local name=$1
  shift
  [[ ${REUSE:-0} == 1 && -f $OUT/$name.h5 ]] && return 0
  nice -n 5 "$EXE" "${RACKET[@]}" "$@" -output "$OUT/$name.h5" -output_overwrite </dev/null >"$OUT/$name.log" 2>&1 || { echo "FAILED: $name (see $OUT/$name.log)"; exit 1; }
}

# the free strung racket's modes; its log also gives the mass, balance and inertias the tables use
run modes-free -task modes -modes_count 10
if [[ $what == all || $what == sites ]]; then
  run glynn -task sweep -sweep "strings_tension=210;270,impact_x=0.4275;$XC;0.5875,impact_z=0;0.06,ball_speed=16:27:6"
  run across -task sweep -impact_x $XC -ball_speed 16.5 -sweep "impact_z=0:0.08:5"
  # held: the bed alone in its own coordinates (x along the head from its end: the centre is
  # half -head_length); the frame's table and roll are not used (-beam_torsion 0: see the notes
  # in docs/racket-anchors.md)
  run clamped -task sweep -strings_frame held -beam_torsion 0 -impact_x 0.1675 -sweep "strings_tension=210;270,ball_speed=15:30:4"
  run tip-pinned -task sweep -beam_right pinned -ball_speed 25 -sweep "impact_x=0.4475;$XC;0.5675"
  "$PY" scripts/study_racket.py sites "$OUT"
fi
if [[ $what == all || $what == tension ]]; then
  run tension -task sweep -impact_x $XC -sweep "ball_speed=15;25,strings_tension=200:300:5"
  run tension-stiff -task sweep -beam_properties "$OUT/stiff.properties" -impact_x $XC -sweep "ball_speed=15;25,strings_tension=200:300:5"
  # Bower & Cross 2005's two tensions in play, at the relative speeds of a groundstroke
  run bower -task sweep -impact_x $XC -sweep "ball_speed=25;30,strings_tension=180;280"
  "$PY" scripts/study_racket.py tension "$OUT"
fi
if [[ $what == all || $what == modes ]]; then
  run modes-free-stiff -task modes -modes_count 4 -beam_properties "$OUT/stiff.properties"
  run modes-held-250 -task modes -strings_frame held -beam_torsion 0 -strings_nodes 121 -modes_count 4
  run modes-held-175 -task modes -strings_frame held -beam_torsion 0 -strings_nodes 121 -modes_count 4 -strings_tension 175
  "$PY" scripts/study_racket.py modes "$OUT"
fi
