#!/usr/bin/env python3
"""The synthetic data of the shipped fit options/fits/oblique-nathan2012.opts (docs/fit.md): the
program's spin and launch angle of a baseball on a fixed 3-inch wood cylinder (Nathan et al.'s
set-up, 100 mph) at the friction and tangential restitution the issue quotes from their paper
(mu 0.15, e_T = e_x 0.30), plus Gaussian noise of stated sigma. SYNTHETIC: their measured points
were not found (scripts/references/README.md); this file is labelled so in its header.

    /usr/bin/python3 scripts/make_fit_data.py [--exe build/release/beamimpact] [--seed 2012] [-o options/fits/oblique-nathan2012.csv]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
MU, ET = 0.15, 0.30
SIGMA_SPIN, SIGMA_ANGLE = 100.0, 0.5  # rpm, deg
SCENE = ["-options_file", "options/fits/oblique-scene.opts"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "release", "beamimpact"))
    ap.add_argument("--seed", type=int, default=2012)
    ap.add_argument("-o", "--output", default=os.path.join(ROOT, "options", "fits", "oblique-nathan2012.csv"))
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        h5 = os.path.join(tmp, "oblique.h5")
        cmd = [os.path.abspath(a.exe)] + SCENE + ["-ball_friction", str(MU), "-ball_tangential_cor", str(ET), "-task", "sweep", "-sweep", "impact_offset=0.00635:0.0508:8",
                                                  "-sweep_quiet", "-output", h5]
        r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("make_fit_data.py: the sweep failed:\n" + r.stdout + r.stderr)
        res = h5py.File(h5, "r")["results"]
        offset, spin, angle = res["impact_offset"][()], res["spin_rpm"][()], res["launch_angle"][()]
    rng = np.random.default_rng(a.seed)
    spin_n = spin + SIGMA_SPIN * rng.standard_normal(len(spin))
    angle_n = angle + SIGMA_ANGLE * rng.standard_normal(len(angle))
    with open(a.output, "w") as f:
        f.write("# SYNTHETIC DATA, not measurements: the program's own spin and launch angle of a baseball on a fixed 3-inch\n"
                "# wood cylinder (options/fits/oblique-scene.opts: Nathan, Cantakos, Kesman, Mathew & Lukash, Procedia Eng. 34,\n"
                "# 182 (2012): a baseball fired at 100 mph onto a 3-inch wood cylinder fixed to a wall), at mu = %.2f and\n"
                "# e_T = %.2f, the values issue 36 quotes from that paper (e_x ~ 0.30, mu ~ 0.15 from 47 impacts; their measured\n"
                "# points were not found: scripts/references/README.md), plus Gaussian noise of sigma %.0f rpm (spin) and\n"
                "# %.1f deg (launch angle), seed %d. Made by: /usr/bin/python3 scripts/make_fit_data.py --seed %d\n"
                % (MU, ET, SIGMA_SPIN, SIGMA_ANGLE, a.seed, a.seed))
        f.write("impact_offset,spin_rpm,spin_rpm_sigma,launch_angle,launch_angle_sigma\n")
        for i in range(len(offset)):
            f.write("%.6g,%.1f,%g,%.2f,%g\n" % (offset[i], spin_n[i], SIGMA_SPIN, angle_n[i], SIGMA_ANGLE))
    print("wrote %s: %d rows (mu %g, e_T %g, noise %g rpm, %g deg, seed %d)" % (a.output, len(offset), MU, ET, SIGMA_SPIN, SIGMA_ANGLE, a.seed))


if __name__ == "__main__":
    main()
