#!/usr/bin/env python3
"""Spin off the strings against the measurements (issue 39, docs/racket-anchors.md "Spin off the
strings"): oblique impacts of options/balls/tennis-ball-fast.opts on the bed of
options/bats/racket-pure-drive.opts, mu 0.4, a rigid grip (no -ball_tangential_cor), -ts_type
modal, in three in-plane models of the bed: the mains locked (-impact_tangential_plane rigid),
free to slide on their tension alone (the default -strings_inplane_stiffness, no notching) and
on a spring of 1e5 N/m (a few mm of slide, as filmed).

  * Cross's string-bed fits as quoted in issue 39 (v_t2 = 0.648 v_t1 + 0.300 R w1,
    w2 = 0.400 w1 + 0.583 v_t1 / R, v_n2 = 0.420 v_n1): v_n2 / v_n1 = 0.42 is a racket free to
    recoil (a head-clamped bed gives 0.8), so here the free racket at rest struck at the head's
    centre at 16.5 m/s (Cross & Lindsey's hand-held speed; Cross's own speeds were not reached),
    20 and 45 deg, w1 = 0 and w1 = 100 rad/s (the spin coefficients by difference);
  * Lindsey's clamped racket (Tennis Warehouse University, "String Movement and Spin", 2011):
    25.0 m/s (56 mph) at 40 deg, 3820 rpm of backspin in (w1 = -400 rad/s), 231 and 276 N
    (52, 62 lb): spin out 1207-1803 rpm measured over 14 strings (nylon 1207-1531, gut
    1524-1642, polyester 1555-1803).

    /usr/bin/python3 scripts/study_racket_spin.py [path/to/beamimpact]     (about 40 s)
"""
import glob
import math
import os
import subprocess
import sys
import tempfile

import h5py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
R_BALL = 0.0335
PLANES = [("locked", ["-impact_tangential_plane", "rigid"]), ("slide, tension", []),
          ("slide, 1e5 N/m", ["-strings_inplane_stiffness", "1e5"])]


def exe():
    if len(sys.argv) > 1:
        return os.path.abspath(sys.argv[1])
    for c in [os.path.join(ROOT, "build/release/beamimpact")] + sorted(glob.glob(os.path.join(ROOT, "build/*/beamimpact"))):
        if os.access(c, os.X_OK):
            return c
    sys.exit("study_racket_spin.py: no build/*/beamimpact; build one or pass its path")


def run(args, out):
    base = [exe(), "-options_file", "options/bats/racket-pure-drive.opts", "-options_file",
            "options/balls/tennis-ball-fast.opts", "-ts_type", "modal", "-ball_friction", "0.4"]
    path = os.path.join(out, "run.h5")
    p = subprocess.run(base + args + ["-output", path, "-output_overwrite"], cwd=ROOT, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("study_racket_spin.py: failed: %s\n%s" % (" ".join(args), p.stdout[-2000:] + p.stderr[-2000:]))
    with h5py.File(path) as f:
        r = f["results"]
        return {k: float(r[k][()].ravel()[0]) for k in ("exit_speed", "launch_angle", "spin", "spin_rpm",
                                                     "strings_slide_peak", "acor")}


def components(r):
    a = math.radians(r["launch_angle"])
    return r["exit_speed"] * math.cos(a), r["exit_speed"] * math.sin(a), r["spin"]


def fits(out):
    v = 16.5
    print("| angle | bed | v_t2/v_t1 (0.648) | R w2/v_t1 (0.583) | v_n2/v_n1 (0.420) | dv_t2/(R dw1) (0.300) "
          "| dw2/dw1 (0.400) | rebound angle (fit) | slide |")
    print("|---|---|---|---|---|---|---|---|---|")
    for angle in (20, 45):
        vn1, vt1 = v * math.cos(math.radians(angle)), v * math.sin(math.radians(angle))
        fit = math.degrees(math.atan2(0.648 * vt1, 0.420 * vn1))
        for name, extra in PLANES:
            common = ["-impact_x", "0.5075", "-ball_speed", str(v), "-impact_angle", str(angle)] + extra
            r0, r1 = run(common, out), run(common + ["-ball_spin", "-100"], out)
            n0, t0, w0 = components(r0)
            n1, t1, w1 = components(r1)
            print("| %d | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.1f (%.1f) | %.1f mm |" % (
                angle, name, t0 / vt1, R_BALL * w0 / vt1, n0 / vn1, (t1 - t0) / (R_BALL * 100), (w1 - w0) / 100,
                r0["launch_angle"], fit, 1e3 * r0["strings_slide_peak"] if r0["strings_slide_peak"] == r0["strings_slide_peak"] else 0))


def lindsey(out):
    print("| tension | bed | spin out (measured 1207-1803 rpm) | rebound angle | exit speed | slide |")
    print("|---|---|---|---|---|---|")
    for tension in (231, 276):
        for name, extra in PLANES:
            r = run(["-strings_frame", "held", "-beam_torsion", "0", "-impact_x", "0.1675", "-ball_speed", "25.03",
                     "-impact_angle", "40", "-ball_spin", "400.03", "-strings_tension", str(tension)] + extra, out)
            slide = r["strings_slide_peak"]
            print("| %d N | %s | %.0f rpm | %.1f deg | %.2f m/s | %s |" % (
                tension, name, r["spin_rpm"], r["launch_angle"], r["exit_speed"],
                "%.1f mm" % (1e3 * slide) if slide == slide else "-"))


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as out:
        print("## Cross's string-bed fits: the free racket at rest, 16.5 m/s at the head's centre\n")
        fits(out)
        print("\n## Lindsey's clamped racket: 25.0 m/s at 40 deg, 3820 rpm of backspin in\n")
        lindsey(out)
