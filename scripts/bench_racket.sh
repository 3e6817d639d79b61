#!/usr/bin/env bash
# The strung racket's cost (issue 25; not a test): one impact and the ~100-point face map of
# options/scenes/racket-face-map.opts at the shipped grid and finer, and how they grow with the
# grid. The bed's columns are the frame's nodes, so -beam_nodes sets both (73 nodes: h = 1 cm,
# 25 nodes across the face; the bed's nodes grow as N^2). For each N:
#   dofs        the system's free dofs (frame, roll and bed; the modal run's "modes kept/free")
#   modal       one impact, -ts_type modal: wall time of the whole process (the modes once, the
#               contact, the modal free flight after it)
#   modal/np    the same impact on BENCH_RANKS ranks (the modes' mirror halves, residuals and
#               refinements shared out over them): PETSc's -log_view total, and the process' wall
#   cn          one impact, -ts_type cn at 20 us with -impact_after time (no modes at all)
#   map         the face map (110 points, 98 on the face) with -ts_type modal, the sweep's own
#               "computed N points in T s" (the modes once, every point on them), on one rank
#   map/np      the same on BENCH_RANKS ranks (default: every local core; the sweep's farm hands
#               the points out, each rank computes the modes once)
# and writes a PNG (time against free dofs, log-log) when a Python with matplotlib is found.
# Then the racket's dense route split by its mirror against the whole decomposition
# (-modal_mirror off: the ACOR difference, issue 39's 1e-9), and the two routes of the modal
# engine in the same run (issue 39), one impact each, -ts_type modal at the same step: the dense decomposition of every mode (-modal_modes all) and
# -modal_weight share at -modal_tolerance BENCH_SHARE_TOL (the modes from a partial eigen-solve
# weighed under the ball's load; docs/model.md section 12): wall times, the modes kept and the
# ACOR difference, for the racket at each N and the shelled bat in the rig at one point
# (options/scenes/bbcor-shell.opts at 66 cm: its BBCOR difference; the scene ships with the share
# route at 1e-6). Times: PETSc's -log_view total and, beside it, the process' wall time (which adds
# ~0.45 s of MPI and PETSc start-up here).
#
#   scripts/bench_racket.sh [path/to/beamimpact]
# Environment:
#   BENCH_NODES   frame nodes (default "37 73 145")
#   BENCH_MAP     0: skip the face map (default 1)
#   BENCH_RANKS   ranks of the impact's and the map's second runs (default: nproc)
#   BENCH_PNG     the figure's path (default out/bench-racket.png; "" for none)
#   BENCH_ROUTES  0: skip the dense-against-share table (default 1)
#   BENCH_SHARE_TOL  -modal_tolerance of the share route (default 1e-6)
# Prints `uptime` first: the machine's load makes single runs noisy.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
source "$here/find-exe.sh"
exe=$(find_beamimpact bench_racket.sh "${1:-}") || exit 1
source "$here/mpi-env.sh"
cd "$root"
nodes=${BENCH_NODES:-"37 73 145"}
png=${BENCH_PNG-out/bench-racket.png}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
base=(-options_file options/base/racket-strung.opts -options_file options/base/tennis-ball.opts -impact_x 0.15 -impact_z 0.05)

# wall SECONDS of one command (its output in $tmp/log); fails loudly
wall() {
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >"$tmp/log" 2>&1 || { echo "bench_racket.sh: failed: $*" >&2; tail -3 "$tmp/log" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}

uptime
ranks=${BENCH_RANKS:-$(nproc)}
# -log_view's total of the last run
petsc() { sed -nE 's/^Time \(sec\): +([0-9.e+-]+).*/\1/p' "$tmp/log" | head -1; }
printf "%6s %8s %12s %18s %12s %12s %10s %12s\n" N dofs "modal (s)" "modal/np$ranks (s)" "cn (s)" "map (s)" "map pts/s" \
  "map/np$ranks (s)"
rows=""
for n in $nodes; do
  tm=$(wall "$exe" "${base[@]}" -beam_nodes "$n" -ts_type modal -output none)
  dofs=$(sed -nE 's/.*modes [0-9]+\/([0-9]+).*/\1/p' "$tmp/log" | tail -1) # the summary's "modes kept/free"
  tmw=$(wall mpirun -n "$ranks" "$exe" "${base[@]}" -beam_nodes "$n" -ts_type modal -output none -log_view)
  tmn="$(printf %.3f "$(petsc)") ($tmw)"
  tc=$(wall "$exe" "${base[@]}" -beam_nodes "$n" -ts_type cn -ts_dt 2e-5 -ts_adapt_type none -impact_after time -output none)
  tmap=nan rate=nan tnp=nan
  if [[ ${BENCH_MAP:-1} != 0 ]]; then
    wall "$exe" -options_file options/scenes/racket-face-map.opts -beam_nodes "$n" -output "$tmp/map.h5" >/dev/null
    tmap=$(sed -nE 's/.*computed ([0-9]+) points in ([0-9.e+-]+) s.*/\2/p' "$tmp/log")
    rate=$(sed -nE 's/.*computed [0-9]+ points in [0-9.e+-]+ s \(([0-9.e+-]+) points\/s\).*/\1/p' "$tmp/log")
    rm -rf "$tmp/map.h5" "$tmp/map.h5.parts"
    wall mpirun -n "$ranks" "$exe" -options_file options/scenes/racket-face-map.opts -beam_nodes "$n" \
      -output "$tmp/map.h5" >/dev/null
    tnp=$(sed -nE 's/.*computed ([0-9]+) points in ([0-9.e+-]+) s.*/\2/p' "$tmp/log")
    rm -rf "$tmp/map.h5" "$tmp/map.h5.parts"
  fi
  printf "%6s %8s %12s %18s %12s %12s %10s %12s\n" "$n" "$dofs" "$tm" "$tmn" "$tc" "$tmap" "$rate" "$tnp"
  rows+="$n $dofs $tm $tc $tmap"$'\n'
done

# key FILE NAME: a result of the impact's file, all its digits
key() { /usr/bin/python3 -c "import h5py; print(repr(float(h5py.File('$1')['results']['$2'][()])))"; }
routes() { # routes LABEL KEY OPTIONS...: the dense route and the share route, one row
  local label=$1 k=$2; shift 2
  local td ts pd ps kd ks ad as
  td=$(wall "$exe" "$@" -ts_type modal -modal_modes all -log_view -output "$tmp/dense.h5")
  pd=$(petsc)
  kd=$(sed -nE 's/.*modes ([0-9]+\/[0-9]+).*/\1/p' "$tmp/log" | tail -1)
  ts=$(wall "$exe" "$@" -ts_type modal -modal_weight share -modal_tolerance "$tol" -log_view -output "$tmp/share.h5")
  ps=$(petsc)
  ks=$(sed -nE 's/.*modes ([0-9]+\/[0-9]+).*/\1/p' "$tmp/log" | tail -1)
  ad=$(key "$tmp/dense.h5" "$k") as=$(key "$tmp/share.h5" "$k")
  printf "%-22s %8.3f %8.3f %8.3f %8.3f %12s %12s %-6s %.3e\n" "$label" "$pd" "$td" "$ps" "$ts" "$kd" "$ks" "$k" \
    "$(awk -v a="$ad" -v b="$as" 'BEGIN { d = b - a; print d < 0 ? -d : d }')"
}
if [[ ${BENCH_ROUTES:-1} != 0 ]]; then
  echo "the racket's dense route split by its mirror (-modal_mirror auto, the default) against the whole decomposition"
  echo "(-modal_mirror off), one impact each on one rank: PETSc's -log_view total and the process' wall, s"
  printf "%-22s %8s %8s %8s %8s %-6s %s\n" case "mirror" "(wall)" "off" "(wall)" key "|difference|"
  for n in $nodes; do
    ta=$(wall "$exe" "${base[@]}" -beam_nodes "$n" -ts_type modal -modal_modes all -log_view -output "$tmp/mirror.h5")
    pa=$(petsc)
    to=$(wall "$exe" "${base[@]}" -beam_nodes "$n" -ts_type modal -modal_modes all -modal_mirror off -log_view \
      -output "$tmp/off.h5")
    po=$(petsc)
    ka=$(key "$tmp/mirror.h5" acor) ko=$(key "$tmp/off.h5" acor)
    printf "%-22s %8.3f %8.3f %8.3f %8.3f %-6s %.3e\n" "racket N = $n" "$pa" "$ta" "$po" "$to" acor \
      "$(awk -v a="$ka" -v b="$ko" 'BEGIN { d = b - a; print d < 0 ? -d : d }')"
  done
  tol=${BENCH_SHARE_TOL:-1e-6}
  echo "the modal engine's routes: dense (-modal_modes all) and -modal_weight share -modal_tolerance $tol"
  uptime
  echo "times: PETSc's -log_view total (the run after MPI's and PETSc's start-up) and the process' wall time, s"
  printf "%-22s %8s %8s %8s %8s %12s %12s %-6s %s\n" case "dense" "(wall)" "share" "(wall)" "dense modes" "share modes" key "|difference|"
  for n in $nodes; do routes "racket N = $n" acor "${base[@]}" -beam_nodes "$n"; done
  routes "shelled bat, 66 cm" bbcor -options_file options/scenes/bbcor-shell.opts -task impact -impact_x 0.66
fi

[[ -n $png ]] || exit 0
py=""
for c in /usr/bin/python3 python3; do
  if command -v "$c" >/dev/null && "$c" -c 'import matplotlib' 2>/dev/null; then py=$c; break; fi
done
[[ -n $py ]] || { echo "bench_racket.sh: no Python with matplotlib (Debian: python3-matplotlib): no figure" >&2; exit 0; }
mkdir -p "$(dirname "$png")"
"$py" - "$png" <<<"$rows" 3<&0 <<'EOF'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
rows = [l.split() for l in open("/dev/fd/3").read().splitlines() if l.strip()]  # the table, on fd 3
n = [int(r[0]) for r in rows]
dofs = [float(r[1]) for r in rows]
fig, ax = plt.subplots(figsize=(6, 4))
for k, label in ((2, "one impact, -ts_type modal (the modes once)"), (3, "one impact, cn, -impact_after time"), (4, "face map, 110 points, modal")):
    t = [float(r[k]) for r in rows]
    if all(v == v for v in t):
        ax.loglog(dofs, t, "o-", label=label)
for d, m in zip(dofs, n):
    ax.annotate("N = %d" % m, (d, ax.get_ylim()[0]), fontsize=7, rotation=90, va="bottom")
ax.set_xlabel("free dofs (frame, roll and string bed)")
ax.set_ylabel("wall time (s)")
ax.set_title("the strung racket's cost against the grid", fontsize=10)
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
print("wrote %s" % sys.argv[1])
EOF
