#!/usr/bin/env bash
# The user-facing plots and exports (issue 15) through the real executable and the scripts:
#   * a short impact of options/scenes/animation.opts (7 snapshots 0-6 ms, ball and energy
#     series), a plain impact with the ball only, a -task modes file and a 2 x 2 sweep with two
#     failed points (off the beam);
#   * scripts/plot_impact.py draws force, energy and snapshot PNGs (and the modes PNG) that PIL
#     reads back with the expected size; asked for the energies of the file run without
#     -monitor_energy it fails naming -monitor_energy (and -snapshot_times for snapshots);
#   * /modes_energy of a truncated modal free flight: the flexible modes' energies sum to
#     vibration_fraction x E_in, the rigid ones' are the translation and rotation fractions, and
#     plot_impact.py --mode-energies draws it; with the barrel's shell each mode is labelled by its
#     part, the wall's summing to wall_fraction, and the fractions close to 1 + energy_error;
#   * scripts/animate_impact.py writes a GIF with exactly the frames asked for (--frames 4 of 7)
#     and all 7 by default; an .mp4 without ffmpeg on PATH fails naming ffmpeg;
#   * scripts/h5_to_csv.py: /results (impact and sweep, with its axes, status and reason),
#     /events, /series and /snapshots: one row per dataset entry, every number equal to the
#     HDF5 value read here with h5py, counts without a decimal point, NaN as nan, the header's
#     units the datasets' unit attributes;
#   * scripts/plot_sweep.py on a free and a clamped sweep: the points with two or more contacts
#     ringed (counted here from /results/contacts), the Eq. (11) rigid-body curve drawn for the
#     free beam only;
#   * scripts/plot_bbcor_map.py and plot_oblique_map.py on small sweeps: the best point they
#     print is the one h5py finds, each refuses the other's file; plot_racket_map.py on a small
#     face map: its largest ACOR and centre of percussion as h5py finds them;
#   * the scripts check what they are given before drawing: -o naming the file they read is
#     refused before any drawing, the file unchanged (plot_sweep.py, h5_to_csv.py; it was a
#     traceback), -o with no image format refused; plot_sweep.py --relative-to a value its text
#     axis lacks, or on a map or a file without a text axis, refused naming the value (it was
#     ignored); plot_strings.py --modes 0 refused naming the option (it said "has no bed modes").
#
#   tests/plots.sh path/to/beamimpact scratch_dir
# Runs from the repository root (found from this script's path); needs a Python with h5py,
# numpy, matplotlib and PIL (Debian: python3-h5py python3-matplotlib).
set -uo pipefail

exe=${1:?usage: plots.sh beamimpact scratch_dir}
dir=${2:?usage: plots.sh beamimpact scratch_dir}
exe=$(readlink -f "$exe")
[[ -x $exe ]] || { echo "FAIL: $1 is not an executable"; exit 1; }
mkdir -p "$dir" && dir=$(readlink -f "$dir")
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
rm -rf "${dir:?}"/*
source tests/lib.sh # MPI env, fail/pass, $python
[[ -n $python ]] || { echo "FAIL: no python3 with h5py and numpy (Debian: apt-get install python3-h5py python3-matplotlib)"; exit 1; }
"$python" -c "import matplotlib, PIL" 2>/dev/null || { echo "FAIL: $python has no matplotlib/PIL (Debian: apt-get install python3-matplotlib)"; exit 1; }

# run NAME [options...]: beamimpact into $dir/NAME.h5 (log $dir/NAME.log); a sweep with failed points exits 2
run() {
  local name=$1 rc; shift
  "$exe" "$@" -output "$dir/$name.h5" >"$dir/$name.log" 2>&1
  rc=$?
  if [[ -f $dir/$name.h5 && ($rc -eq 0 || ($rc -eq 2 && $name == sweep)) ]]; then pass "$name runs (exit $rc)"; return 0; fi
  fail "$name: beamimpact $* (exit $rc)"
  tail -5 "$dir/$name.log" | sed 's/^/      /'
  return 1
}
# expect_fail WHAT PATTERN command...: the command must fail and say PATTERN on stderr
expect_fail() {
  local what=$1 pat=$2 rc; shift 2
  "$@" >"$dir/out.txt" 2>"$dir/err.txt"
  rc=$?
  if [[ $rc -ne 0 ]] && grep -qF -- "$pat" "$dir/err.txt"; then pass "$what: exit $rc, '$(head -c 160 "$dir/err.txt" | tr '\n' ' ')'"
  else fail "$what: exit $rc, expected a failure naming '$pat'; stderr: $(head -c 300 "$dir/err.txt")"; fi
}
# images KIND FILE...: every file is a valid PNG (or GIF) of a sane size, per PIL
images() {
  "$python" - "$@" <<'EOF'
import sys
from PIL import Image
kind, files, bad = sys.argv[1], sys.argv[2:], 0
for p in files:
    try:
        with Image.open(p) as im:
            fmt, size = im.format, im.size
            im.verify()
        ok = fmt == kind and size[0] >= 300 and size[1] >= 200
    except Exception as err:  # missing, truncated or not an image
        fmt, size, ok = repr(err), None, False
    print(("ok:   %s: %s %s" if ok else "FAIL: %s: %s %s") % (p, fmt, size))
    bad += not ok
sys.exit(1 if bad else 0)
EOF
}
t0=$SECONDS
times=0,0.001,0.002,0.003,0.004,0.005,0.006
run impact -options_file options/scenes/animation.opts -snapshot_times $times -impact_max_time 0.006
run plain -options_file options/impact.opts -monitor_ball -impact_max_time 0.006
run modes -options_file options/scenes/modes.opts -beam_left free
run sweep -options_file options/default.opts -sweep_x 0.5,1.2 -sweep "beam_nodes=21;41" -sweep_quiet
echo "      (runs: $((SECONDS - t0)) s)"

# --- plot_impact.py ------------------------------------------------------------------------------
if scripts/plot_impact.py "$dir/impact.h5" -o "$dir/impact" >"$dir/plot.log" 2>&1; then pass "plot_impact.py impact.h5: $(grep -c wrote "$dir/plot.log") PNGs"
else fail "plot_impact.py impact.h5: $(tail -3 "$dir/plot.log")"; fi
if images PNG "$dir"/impact-{force,energy,snapshots}.png; then pass "force, energy and snapshot PNGs are valid images"; else fail "plot_impact.py PNGs"; fi
if scripts/plot_impact.py "$dir/modes.h5" --modes >"$dir/plotm.log" 2>&1 && images PNG "$dir/modes-modes.png"; then pass "plot_impact.py --modes on a -task modes file: modes-modes.png"
else fail "plot_impact.py --modes: $(tail -3 "$dir/plotm.log")"; fi
expect_fail "plot_impact.py --energy without -monitor_energy" "-monitor_energy" scripts/plot_impact.py "$dir/plain.h5" --energy -o "$dir/plain"
expect_fail "plot_impact.py --snapshots without -snapshot_times" "-snapshot_times" scripts/plot_impact.py "$dir/plain.h5" --snapshots -o "$dir/plain"
[[ ! -e $dir/plain-energy.png ]] && pass "no energy PNG was written for plain.h5" || fail "plain-energy.png written from a file without energies"
if scripts/plot_impact.py "$dir/plain.h5" -o "$dir/plain" >"$dir/plotp.log" 2>&1 && grep -q "no energy plot.*-monitor_energy" "$dir/plotp.log" &&
   [[ -f $dir/plain-force.png && ! -e $dir/plain-energy.png ]]; then pass "plot_impact.py plain.h5: the force only, the missing plots named with their options"
else fail "plot_impact.py plain.h5: $(cat "$dir/plotp.log")"; fi
# /modes_energy (docs/model.md section 12) of a truncated modal free flight (the paper's beam at
# N = 161, -modal_tolerance 1e-6: 133 of 161 modes): one row per kept mode, frequencies ascending
# and 0 for the two rigid modes, fraction = energy / E_in (E_in = m v^2 / 2 from the root's
# ball_mass and ball_speed, the beam at rest), the flexible modes' energies summing to
# /results/vibration_fraction times E_in and the rigid ones' to translation_fraction and
# rotation_fraction (1e-9); then plot_impact.py --mode-energies draws it.
if run modal -options_file options/impact.opts -beam_nodes 161 -modal_tolerance 1e-6 -impact_x 0.9; then
  me=$("$python" - "$dir/modal.h5" <<'EOF'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    if "modes_energy" not in f:
        print("no /modes_energy"); sys.exit()
    g, R = f["modes_energy"], f["results"]
    e, x, fr, rig = g["energy"][()], g["fraction"][()], g["frequency"][()], g["rigid"][()].astype(bool)
    E_in = 0.5 * f.attrs["ball_mass"] * f.attrs["ball_speed"] ** 2
    vib, tr, rot = (float(R[k][0]) for k in ("vibration_fraction", "translation_fraction", "rotation_fraction"))
    kept = int(f.attrs["modal_modes_kept"])
    bad = []
    if not (len(e) == len(x) == len(fr) == len(rig) == kept < 161): bad.append("rows %d, modal_modes_kept %d (of 161)" % (len(e), kept))
    if rig.sum() != 2 or np.any(fr[rig] != 0) or not np.all(np.diff(fr[~rig]) > 0) or not fr[~rig][0] > 0: bad.append("frequencies %s, rigid %s" % (fr[:4], rig[:4]))
    if not np.allclose(x, e / E_in, rtol=1e-12, atol=0): bad.append("fraction is not energy / E_in")
    if not abs(e[~rig].sum() - vib * E_in) <= 1e-9 * vib * E_in: bad.append("flexible sum %.15g J, vibration_fraction x E_in %.15g J" % (e[~rig].sum(), vib * E_in))
    if not np.allclose(x[rig], [tr, rot], rtol=1e-9, atol=0): bad.append("rigid %s, translation and rotation fractions %g %g" % (x[rig], tr, rot))
    print("ok %d modes, flexible sum %.6g J = %.6g x E_in" % (len(e), e[~rig].sum(), vib) if not bad else "bad: " + "; ".join(bad))
EOF
)
  [[ $me == ok* ]] && pass "/modes_energy: ${me#ok }; rigid ones the translation and rotation fractions" || fail "/modes_energy: $me"
  rm -f "$dir/modal-mode-energies.png"
  if scripts/plot_impact.py "$dir/modal.h5" --mode-energies -o "$dir/modal" >"$dir/plotme.log" 2>&1 && images PNG "$dir/modal-mode-energies.png"; then
    pass "plot_impact.py --mode-energies: modal-mode-energies.png"
  else fail "plot_impact.py --mode-energies: $(tail -3 "$dir/plotme.log")"; fi
fi
# The barrel wall's modes in /modes_energy (issue 34): the aluminium bat with its shell (N = 41,
# -ts_type modal): each mode labelled by its part (/modes_energy/part), the "wall" modes summing to
# /results/wall_fraction and the "bending" ones to vibration_fraction (1e-10 of E_in), the rigid
# ones to translation_ and rotation_fraction; the *_fraction columns and the ball's rebound add up
# to 1 + energy_error; plot_impact.py prints the parts beside their columns (the wall's used to be
# drawn as ordinary "mode 3/4/6", and its 17 % was in no fraction column).
if run wall -options_file options/bats/aluminium-bat.opts -options_file options/balls/baseball.opts -beam_shell -beam_nodes 41 -ts_type modal -impact_x 0.66; then
  me=$("$python" - "$dir/wall.h5" <<'EOF2'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    g, R = f["modes_energy"], f["results"]
    if "part" not in g:
        print("no /modes_energy/part"); sys.exit()
    part = np.array([p.decode() if isinstance(p, bytes) else p for p in g["part"][()]])
    x, rig = g["fraction"][()], g["rigid"][()].astype(bool)
    col = lambda k: float(R[k][0]) if k in R else float("nan")
    bad = []
    for label, rigid, column in (("translation", True, "translation_fraction"), ("rotation", True, "rotation_fraction"), ("bending", False, "vibration_fraction"), ("wall", False, "wall_fraction")):
        got = x[(part == label) & (rig == rigid)].sum()
        if not abs(got - col(column)) <= 1e-10: bad.append("%s modes %.12g, %s %.12g" % (label, got, column, col(column)))
    shares = [k for k in R if k.endswith("_fraction") and not k.startswith("rigid_") and np.isfinite(col(k))]
    total = sum(col(k) for k in shares)
    if not abs(total - 1 - col("energy_error")) <= 1e-12: bad.append("the fractions %s sum to %.15g, 1 + energy_error = %.15g" % (shares, total, 1 + col("energy_error")))
    if not col("wall_fraction") > 0.05: bad.append("wall_fraction %g" % col("wall_fraction"))
    print("ok wall %.4g, bending %.4g; %d fractions sum to 1 %+.1e" % (col("wall_fraction"), col("vibration_fraction"), len(shares), total - 1) if not bad else "bad: " + "; ".join(bad))
EOF2
)
  [[ $me == ok* ]] && pass "/modes_energy with the shell: ${me#ok }" || fail "/modes_energy with the shell: $me"
  if out=$(scripts/plot_impact.py "$dir/wall.h5" --mode-energies -o "$dir/wall" 2>&1) && grep -q "mode energies by part .*bending [0-9.e-]* (vibration_fraction .*; wall [0-9.e-]* (wall_fraction " <<<"$out" &&
     images PNG "$dir/wall-mode-energies.png"; then
    pass "plot_impact.py --mode-energies labels the wall's modes by their part, beside wall_fraction"
  else fail "plot_impact.py --mode-energies with the shell: $out"; fi
fi
if run nowindow -options_file options/impact.opts -impact_window 0; then # no free flight: no /modes_energy
  expect_fail "plot_impact.py --mode-energies with -impact_window 0" "(-impact_window > 0)" scripts/plot_impact.py "$dir/nowindow.h5" --mode-energies -o "$dir/nowindow"
fi

# --- animate_impact.py ---------------------------------------------------------------------------
# frames FILE: the GIF's frame count per PIL
frames() { "$python" -c "from PIL import Image; im = Image.open('$1'); print(im.n_frames if im.format == 'GIF' else -1)" 2>/dev/null || echo -1; }
if scripts/animate_impact.py "$dir/impact.h5" -o "$dir/four.gif" --frames 4 >"$dir/anim.log" 2>&1; then
  n=$(frames "$dir/four.gif")
  check_gif=$([[ $n == 4 ]] && echo ok)
  [[ -n $check_gif ]] && pass "animate_impact.py --frames 4: GIF with $n frames ($(stat -c %s "$dir/four.gif") bytes)" || fail "animate_impact.py --frames 4: $n frames, expected 4"
else fail "animate_impact.py --frames 4: $(tail -3 "$dir/anim.log")"; fi
if scripts/animate_impact.py "$dir/impact.h5" -o "$dir/all.gif" >"$dir/anim2.log" 2>&1; then
  n=$(frames "$dir/all.gif")
  [[ $n == 7 ]] && pass "animate_impact.py: one frame per snapshot time ($n of 7)" || fail "animate_impact.py: $n frames, expected 7 (the snapshot times)"
  images GIF "$dir/all.gif" >/dev/null || fail "all.gif is not a valid GIF of >= 300 x 200 pixels"
else fail "animate_impact.py: $(tail -3 "$dir/anim2.log")"; fi
if command -v ffmpeg >/dev/null; then
  scripts/animate_impact.py "$dir/impact.h5" -o "$dir/all.mp4" --frames 3 >/dev/null 2>&1 && [[ -s $dir/all.mp4 ]] && pass "MP4 with ffmpeg" || fail "MP4 with ffmpeg on PATH"
else
  expect_fail "animate_impact.py -o .mp4 without ffmpeg" "ffmpeg" scripts/animate_impact.py "$dir/impact.h5" -o "$dir/all.mp4"
fi
expect_fail "animate_impact.py on a file without snapshots" "-snapshot_times" scripts/animate_impact.py "$dir/plain.h5" -o "$dir/plain.gif"

# A racket's bed in pictures (issue 25): the strung racket off its axis with 5 snapshots, the bed's
# deflection from its frame in /snapshots/bed ([time][z x] of the bed's grid, NaN off the bed, 0
# before the hit, largest under the ball's disc mid-contact); plot_strings.py draws them and the
# racket's -task modes bed shapes; animate_impact.py adds the bed's panel.
if run racketsnap -options_file options/scenes/racket-strings.opts -snapshot_times 0,0.0015,0.003,0.0045,0.006 -monitor_ball; then
  bedcheck=$("$python" - "$dir/racketsnap.h5" <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
g = f["snapshots"]
nx, nz = len(g["bed_x"]), len(g["bed_z"])
b = g["bed"][()].reshape(len(g["time"]), nz, nx)
mid = b[2]
i, j = np.unravel_index(np.nanargmax(mid), mid.shape)
xc = float(np.ravel(f.attrs["impact_x"])[0]) - float(np.ravel(f.attrs["head_center"])[0])
zc = float(np.ravel(f.attrs["impact_z"])[0])
ok = np.all(np.nan_to_num(b[0]) == 0) and abs(g["bed_x"][j] - xc) <= 0.011 and abs(g["bed_z"][i] - zc) <= 0.011 and np.isnan(b).any()
print("ok" if ok else "bad", "peak at x %.3f z %.3f (ball at %.3f, %.3f)" % (g["bed_x"][j], g["bed_z"][i], xc, zc))
EOF
)
  [[ $bedcheck == ok* ]] && pass "racket snapshots: the bed at rest before the hit, its pocket under the ball mid-contact (${bedcheck#ok })" || fail "racket snapshots: $bedcheck"
  if out=$("$python" scripts/plot_strings.py "$dir/racketsnap.h5" -o "$dir/racketsnap.png" --snapshots 4 2>&1) && images PNG "$dir/racketsnap.png" >/dev/null; then pass "plot_strings.py on snapshots: $out"
  else fail "plot_strings.py racketsnap.h5: $out"; fi
  if scripts/animate_impact.py "$dir/racketsnap.h5" -o "$dir/racketsnap.gif" >"$dir/anim3.log" 2>&1 && [[ $(frames "$dir/racketsnap.gif") == 5 ]]; then pass "animate_impact.py with the bed's panel: 5 frames"
  else fail "animate_impact.py racketsnap.h5: $(tail -3 "$dir/anim3.log")"; fi
fi

# --- h5_to_csv.py: every cell against h5py ---------------------------------------------------------
# csv_check FILE GROUP CSV: row count, header units, values, counts as integers, nan
csv_check() {
  "$python" - "$@" <<'EOF'
import csv, math, re, sys
import h5py, numpy as np
path, group, out = sys.argv[1:4]
COUNTS = {"contacts", "steps", "rejected_steps", "event_steps", "function_evals", "kind", "status", "case_index", "beam_nodes", "ended_in_contact"}
bad, checked = [], 0
with open(out, newline="") as fh:
    rows = list(csv.reader(fh))
head, body = rows[0], rows[1:]
with h5py.File(path, "r") as f:
    g = f[group]
    n = None
    for j, h in enumerate(head):
        m = re.match(r"^([^ \[]+)(\[[^\]]*\])?(?: \((.*)\))?$", h)
        name, sub, u = m.group(1), m.group(2), m.group(3) or ""
        ds = g[name]
        unit = ds.attrs.get("unit", b"")
        unit = unit.decode() if isinstance(unit, bytes) else str(unit)
        if u and not unit.startswith(u):
            bad.append("%s: header unit %r, dataset unit %r" % (h, u, unit))
        v = ds[()]
        if sub:  # snapshots y[t=...]: column k of y.T, at the time in the header
            k = int(np.argmin(np.abs(f[group + "/time"][()] - float(sub[3:-1]))))
            v = v[k]
        n = len(v) if n is None else n
        if len(v) != len(body):
            bad.append("%s: %d rows, dataset length %d" % (h, len(body), len(v)))
            continue
        cells = [r[j] for r in body]
        if v.dtype.kind in "OS":
            exp = [x.decode() if isinstance(x, bytes) else str(x) for x in v]
            if cells != exp:
                bad.append("%s: strings differ" % h)
            checked += len(cells)
            continue
        for c, x in zip(cells, v.astype(float)):
            if math.isnan(x):
                ok = c == "nan"
            elif name in COUNTS:
                ok = re.fullmatch(r"-?[0-9]+", c) is not None and int(c) == x
            else:
                ok = c not in ("", "nan") and float(c) == x  # exact: the text reads back as the same double
            if not ok:
                bad.append("%s: cell %r, HDF5 %r" % (h, c, x))
                break
            checked += 1
    # every 1-D dataset of the table's length is a column
    names = {re.split(r"[ \[]", h)[0] for h in head}
    for k, ds in g.items():
        if isinstance(ds, h5py.Dataset) and ds.ndim == 1 and len(ds) == len(body) and k not in names:
            bad.append("dataset %s/%s is not a column" % (group, k))
for b in bad[:8]:
    print("      " + b)
print("%d rows, %d columns, %d cells checked" % (len(body), len(head), checked))
sys.exit(1 if bad or not body else 0)
EOF
}
for spec in impact:results impact:events impact:series impact:snapshots sweep:results; do
  h5=${spec%%:*} grp=${spec#*:}
  csv="$dir/$h5-$grp.csv"
  if scripts/h5_to_csv.py "$dir/$h5.h5" "$grp" -o "$csv" 2>"$dir/csv.err"; then
    if out=$(csv_check "$dir/$h5.h5" "$grp" "$csv"); then pass "h5_to_csv.py $h5.h5 $grp: equal to the HDF5 values (${out##*$'\n'})"
    else fail "h5_to_csv.py $h5.h5 $grp: $out"; fi
  else fail "h5_to_csv.py $h5.h5 $grp: $(cat "$dir/csv.err")"; fi
done
# the default group to stdout; the sweep's failed rows: status 2, the reason, nan numbers; integers bare
scripts/h5_to_csv.py "$dir/impact.h5" >"$dir/stdout.csv" 2>/dev/null
cmp -s "$dir/stdout.csv" "$dir/impact-results.csv" && pass "h5_to_csv.py FILE (no GROUP, stdout) = /results" || fail "h5_to_csv.py FILE to stdout differs from /results -o"
row=$(sed -n 5p "$dir/sweep-results.csv")
[[ $(sed -n 1p "$dir/sweep-results.csv") == "case_index (1),impact_x (m),beam_nodes (1),status (1),reason (text),x (m),"* ]] &&
  pass "sweep CSV header: case_index, the axes, status, reason first" || fail "sweep CSV header: $(sed -n 1p "$dir/sweep-results.csv" | cut -c1-120)"
[[ $row == 3,1.2,41,2,*"impact point must lie on the beam"*,nan,nan,* ]] && pass "failed sweep row: ${row:0:90}..." || fail "failed sweep row: ${row:0:200}"
expect_fail "h5_to_csv.py on a group the file lacks" "-monitor_ball" scripts/h5_to_csv.py "$dir/modes.h5" series

# scripts/plot_sweep.py says what it drew: the points with two or more contacts ringed (their
# number read here from /results/contacts), failed points, and the rigid-body Eq. (11) curve
# only for a free beam (Eq. (11) is the free rigid body), not for one clamped at x = 0.
run free -options_file options/default.opts -sweep_x 0.05:1.1:22 -sweep_quiet
run clamped -options_file options/default.opts -beam_left clamped -sweep_x 0.05:1.1:22 -sweep_quiet
for name in free clamped; do
  out=$("$python" scripts/plot_sweep.py "$dir/$name.h5" -o "$dir/$name.png" 2>&1) || fail "plot_sweep.py $name: $out"
  multi=$("$python" -c "import h5py, sys; r = h5py.File(sys.argv[1])['results']; print(int(((r['contacts'][()] >= 2) & (r['status'][()] == 0)).sum()))" "$dir/$name.h5")
  curve=$([[ $name == free ]] && echo "drawn" || echo "not drawn (the beam is held or pivoted)")
  grep -qF "$dir/$name.h5: 22 point(s), $multi with two or more contacts (ringed), 0 failed (x); rigid-body Eq. (11) curve: $curve" <<<"$out" \
    && pass "plot_sweep.py $name: $multi double contact(s) ringed, Eq. (11) curve $curve" || fail "plot_sweep.py $name: expected $multi ringed and the curve $curve: $out"
done
images PNG "$dir/free.png" "$dir/clamped.png" && pass "plot_sweep.py PNGs valid" || fail "plot_sweep.py PNGs"
# -o naming the input: refused, the file unchanged; -o with no image format: refused
before=$(sha256sum "$dir/free.h5" | cut -c1-64)
expect_fail "plot_sweep.py FILE acor -o FILE" "-o $dir/free.h5 is not allowed: it is the input file $dir/free.h5, which the output would overwrite; give another -o (e.g. $dir/free.png)" \
  "$python" scripts/plot_sweep.py "$dir/free.h5" acor -o "$dir/free.h5"
grep -q "point(s)" "$dir/out.txt" && fail "plot_sweep.py -o FILE: refused only after drawing ($(cat "$dir/out.txt"))"
expect_fail "h5_to_csv.py FILE -o FILE" "it is the input file $dir/free.h5, which the output would overwrite; give another -o (e.g. $dir/free.csv)" scripts/h5_to_csv.py "$dir/free.h5" -o "$dir/free.h5"
[[ $(sha256sum "$dir/free.h5" | cut -c1-64) == "$before" ]] && pass "the input is unchanged after both" || fail "the input free.h5 was changed"
expect_fail "plot_sweep.py -o out.h5 (not an image)" "-o $dir/new.h5 is not allowed: .h5 is not an image format" "$python" scripts/plot_sweep.py "$dir/free.h5" -o "$dir/new.h5"
[[ -e $dir/new.h5 ]] && fail "plot_sweep.py wrote $dir/new.h5"
# --relative-to: a value of the text axis, on curves; anything else refused naming the value
run textaxis -task sweep -beam_nodes 21 -impact_window 1e-3 -sweep "ts_type=rk;cn,impact_x=0.3;0.6" -sweep_quiet
out=$("$python" scripts/plot_sweep.py "$dir/textaxis.h5" --relative-to cn -o "$dir/textaxis.png" 2>&1) && images PNG "$dir/textaxis.png" >/dev/null \
  && pass "plot_sweep.py --relative-to cn on a ts_type sweep draws" || fail "plot_sweep.py --relative-to cn: $out"
expect_fail "plot_sweep.py --relative-to a value the text axis lacks" "--relative-to bogus is not allowed: the text axis ts_type of $dir/textaxis.h5 has the values rk, cn" \
  "$python" scripts/plot_sweep.py "$dir/textaxis.h5" --relative-to bogus -o "$dir/x.png"
expect_fail "plot_sweep.py --relative-to on a file without a text axis" "--relative-to rk is not allowed: it draws COLUMN minus its value at rk of a text axis" \
  "$python" scripts/plot_sweep.py "$dir/free.h5" --relative-to rk -o "$dir/x.png"

# The maps of issues 23 and 24, each on a small sweep (coarse grids), its printed best point
# against the same maximum found here with h5py, and each refusing the other's file:
#   * plot_bbcor_map.py on a 2 x 2 x 2 sweep of the aluminium bat's shell (x, wall thickness x shell
#     modulus, N = 43, n = 2 only) in the BBCOR rig: "best BBCOR" the largest bbcor of the file;
#   * plot_oblique_map.py on a 2 x 3 sweep of the R161 swing over impact_x x impact_offset with
#     -flight: "best distance" the largest distance, and at each impact point the best offset.
run bbmap -options_file options/scenes/bbcor-shell.opts -task sweep -impact_after time -impact_window 1e-3 -beam_nodes 43 -shell_harmonics 2 -sweep_x 0.62,0.66 \
  -sweep barrel_wall_thickness=2e-3:3e-3:2,shell_youngs_modulus=5e10:1e11:2 -sweep_quiet
run obmap -options_file options/scenes/oblique-map.opts -beam_nodes 43 -sweep impact_x=0.62:0.7:2,impact_offset=0:0.02:3 -sweep_quiet
if out=$("$python" scripts/plot_bbcor_map.py "$dir/bbmap.h5" -o "$dir/bbmap.png" 2>&1); then
  want=$("$python" - "$dir/bbmap.h5" <<'EOF'
import sys, h5py, numpy as np
r = h5py.File(sys.argv[1])["results"]
ok = (r["status"][()] == 0) & np.isfinite(r["bbcor"][()])
b = np.where(ok, r["bbcor"][()], -np.inf)
k = int(np.argmax(b))
print("best BBCOR %.4f at wall %.2f mm" % (b[k], r["barrel_wall_thickness"][k] * 1e3))
print("hoop frequency %.0f Hz" % r["hoop_frequency"][k])
print("%d ok" % ok.sum())
EOF
)
  best=$(sed -n 1p <<<"$want"); hoop=$(sed -n 2p <<<"$want"); nok=$(sed -n 3p <<<"$want")
  grep -qF "$best" <<<"$out" && grep -qF "$hoop" <<<"$(head -1 <<<"$out")" && [[ $nok == "8 ok" ]] \
    && pass "plot_bbcor_map.py: '$best', $hoop, as h5py finds it ($nok points)" || fail "plot_bbcor_map.py: expected '$best' ($hoop, $nok points): $out"
  [[ $(grep -c "^  wall " <<<"$out") == 2 ]] && pass "plot_bbcor_map.py: one line per wall thickness (2)" || fail "plot_bbcor_map.py per-thickness lines: $out"
else fail "plot_bbcor_map.py bbmap.h5: $out"; fi
if out=$("$python" scripts/plot_oblique_map.py "$dir/obmap.h5" -o "$dir/obmap.png" 2>&1); then
  want=$("$python" - "$dir/obmap.h5" <<'EOF'
import sys, h5py, numpy as np
r = h5py.File(sys.argv[1])["results"]
ok = (r["status"][()] == 0) & np.isfinite(r["distance"][()])
d = np.where(ok, r["distance"][()], -np.inf)
x, D = r["impact_x"][()], r["impact_offset"][()]
k = int(np.argmax(d))
print("best distance: %.4g m at impact_x %.3f m, impact_offset %.4f m" % (d[k], x[k], D[k]))
for xv in np.unique(x):
    j = np.where(x == xv)[0][np.argmax(d[x == xv])]
    print("  impact_x %.3f m: best impact_offset %.4f m (distance %.4g)" % (xv, D[j], d[j]))
EOF
)
  [[ $(grep -v "^wrote" <<<"$out") == "$want" ]] && pass "plot_oblique_map.py: the best point and the best offset at each x as h5py finds them ($(head -1 <<<"$want"))" \
    || fail "plot_oblique_map.py: expected
$want
got
$out"
else fail "plot_oblique_map.py obmap.h5: $out"; fi
images PNG "$dir/bbmap.png" "$dir/obmap.png" && pass "map PNGs valid" || fail "map PNGs"
expect_fail "plot_bbcor_map.py on the oblique map" "is not a sweep over barrel_wall_thickness" "$python" scripts/plot_bbcor_map.py "$dir/obmap.h5" -o "$dir/x.png"
expect_fail "plot_oblique_map.py on the BBCOR map" "is not a sweep over impact_x and impact_offset" "$python" scripts/plot_oblique_map.py "$dir/bbmap.h5" -o "$dir/x.png"
expect_fail "plot_sweep.py --map --relative-to on a map of two numeric axes" "--relative-to bogus is not allowed: it draws COLUMN minus its value at bogus of a text axis" \
  "$python" scripts/plot_sweep.py "$dir/obmap.h5" distance --map --relative-to bogus -o "$dir/x.png"
[[ -e $dir/x.png ]] && fail "a refused plot wrote $dir/x.png"

# plot_racket_map.py on a 3 x 3 face map of the strung racket: the largest ACOR and the centre of
# percussion it prints are h5py's maximum and I_cm / (M d) from the file's attributes; the frame's
# node from a -task modes file of the same racket lies on the head; it refuses the oblique map.
run facemap -options_file options/scenes/racket-face-map.opts -sweep impact_x=0.10:0.28:3,impact_z=-0.10:0.10:3 -sweep_quiet
run racketmodes -options_file options/base/racket-strung.opts -task modes -modes_count 8
if out=$("$python" scripts/plot_racket_map.py "$dir/facemap.h5" --modes "$dir/racketmodes.h5" -o "$dir/facemap.png" 2>&1); then
  want=$("$python" - "$dir/facemap.h5" <<'EOF'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
r = f["results"]
ok = (r["status"][()] == 0) & np.isfinite(r["acor"][()])
a = np.where(ok, r["acor"][()], -np.inf)
k = int(np.argmax(a))
print("largest ACOR %.4f at impact_x %.3f m, impact_z %.3f m" % (a[k], r["impact_x"][k], r["impact_z"][k]))
g = lambda n: float(np.ravel(f.attrs[n])[0])
hand = g("beam_length") - 0.03
print("cop %.4f" % (g("beam_center_of_mass") - g("beam_inertia_cm") / (g("beam_mass") * (hand - g("beam_center_of_mass")))))
EOF
)
  got_best=$(grep '^largest ACOR' <<<"$out") got_cop=$(sed -nE 's/^centre of percussion .*: x = ([0-9.]+) m .*/cop \1/p' <<<"$out")
  node=$(sed -nE 's/^node: x = ([0-9.]+) m .*/\1/p' <<<"$out")
  [[ "$got_best"$'\n'"$got_cop" == "$want" ]] && awk -v n="$node" 'BEGIN { exit !(n > 0.015 && n < 0.335) }' \
    && pass "plot_racket_map.py: the largest ACOR and the centre of percussion as h5py finds them ($(head -1 <<<"$want")), the node on the head ($node m)" \
    || fail "plot_racket_map.py: expected
$want
and a node on the head, got
$out"
else fail "plot_racket_map.py facemap.h5: $out"; fi
images PNG "$dir/facemap.png" && pass "face map PNG valid" || fail "face map PNG"
expect_fail "plot_racket_map.py on the oblique map" "is not a sweep over impact_x and impact_z" "$python" scripts/plot_racket_map.py "$dir/obmap.h5" -o "$dir/x.png"
if [[ -f $dir/racketmodes.h5 ]]; then
  if out=$("$python" scripts/plot_strings.py "$dir/racketmodes.h5" -o "$dir/racketmodes.png" 2>&1) && images PNG "$dir/racketmodes.png" >/dev/null; then pass "plot_strings.py on a racket's modes: $out"
  else fail "plot_strings.py racketmodes.h5: $out"; fi
fi

# plot_convergence.py's orders rest only on points above the error floor, and say so: errors
# c h^4 at h = 1/2, 1/4, 1/8 then two points at a floor of 1e-10 give p = 4 from 3 points with
# 2 left out; all at the floor give no number (the defect: "order 0.34, expected 4").
conv=$("$python" - <<'EOF'
import sys
sys.path.insert(0, "scripts")
import numpy as np
import plot_convergence as pc
h = 0.5 ** np.arange(1, 6)
e = 1e-3 * h ** 4
e[3:] = 1e-10
print(pc.order_text(*pc.fit_order(h, e, 1e-10), expected=4))
print(pc.order_text(*pc.fit_order(h, np.full(5, 1e-12), 1e-10), expected=4))
EOF
)
grep -qx "p = 4.00, expected 4; from the 3 points above the error floor, 2 at it left out" <<<"$conv" && grep -qx "at the error floor: no order (5 of 5 points at or below it, expected 4)" <<<"$conv" \
  && pass "plot_convergence.py: orders from points above the error floor only, labelled" || fail "plot_convergence.py orders: $conv"

# The string bed's shapes (issue 25): scripts/plot_strings.py on the shipped scene at 31 nodes (a
# valid PNG, one line naming it), and a beam's modes file refused with what writes the bed's.
if run strings -options_file options/scenes/strings-modes.opts -strings_nodes 31; then
  if out=$("$python" scripts/plot_strings.py "$dir/strings.h5" -o "$dir/strings.png" 2>&1) && images PNG "$dir/strings.png" >/dev/null; then pass "plot_strings.py: $out"
  else fail "plot_strings.py strings.h5: $out"; fi
  expect_fail "plot_strings.py on a beam's modes file" "no string bed's picture" "$python" scripts/plot_strings.py "$dir/modes.h5" -o "$dir/not-strings.png"
  expect_fail "plot_strings.py --modes 0" "argument --modes: 0 is not allowed: the number of modes to draw must be at least 1" \
    "$python" scripts/plot_strings.py "$dir/strings.h5" --modes 0 -o "$dir/no-modes.png"
fi

# scripts/plot_fit.py (issue 36) on a small fit of data made by the program (3 impacts, ball_k): a
# valid PNG, its line naming the columns and parameters; a modes file refused as not a fit.
"$exe" -task sweep -beam_nodes 21 -ts_type modal -ball_law linear -ball_k 2.2e4 -sweep "impact_x=0.3;0.6;0.9" -sweep_quiet -output "$dir/fitgen.h5" >"$dir/fitgen.log" 2>&1
"$python" -c "
import h5py; r = h5py.File('$dir/fitgen.h5', 'r')['results']
print('impact_x,acor,contact_time'); [print('%.17g,%.17g,%.17g' % (r['impact_x'][i], r['acor'][i], r['contact_time'][i])) for i in range(3)]" >"$dir/fit.csv"
if run fit -task fit -beam_nodes 21 -ts_type modal -ball_law linear -fit_data "$dir/fit.csv" -fit_parameters "ball_k=1e4:5e4"; then
  if out=$("$python" scripts/plot_fit.py "$dir/fit.h5" -o "$dir/fit.png" 2>&1) && images PNG "$dir/fit.png" >/dev/null && grep -q "2 measured columns, 1 parameters" <<<"$out"; then pass "plot_fit.py: $out"
  else fail "plot_fit.py fit.h5: $out"; fi
  expect_fail "plot_fit.py on a modes file" "is not a -task fit file" "$python" scripts/plot_fit.py "$dir/modes.h5" -o "$dir/not-fit.png"
fi

echo "plots: $fails failure(s), $SECONDS s"
[[ $fails -eq 0 ]]
