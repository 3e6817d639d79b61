#!/usr/bin/env python3
"""The round trip of -task fit (docs/fit.md, "What a fit's numbers are worth"): data made by the
program at known parameters, fitted back, without noise and with Gaussian noise of known sigma
over many draws.

    /usr/bin/python3 scripts/study_fit.py [--draws 60] [--jobs 2] [--exe build/release/beamimpact] [--out out/fit-study]

The scene: the paper's free beam (N = 21, -ts_type modal) struck by a linear ball; rows impact_x =
0.2, 0.4, 0.6, 0.8, 1.0 m x ball_speed = 1, 2 m/s, each measuring acor and contact_time; the
parameters ball_k (true 2.2e4 N/m, bounds 1e4:5e4) and beam_youngs_modulus (true 6.3e10 Pa, bounds
5e10:9e10). Printed:
  * without noise: the fitted values' relative errors (the goal: below 1e-6);
  * with noise (sigma 1 % of each column's mean, given as the _sigma columns, so s^2 = 1): over the
    draws, the share of fits whose true value lies within one reported standard error (the goal:
    68 +- 10 %), and the reported standard error against the scatter (standard deviation) of the
    fitted values (the goal: within 20 %), with the binomial and sampling uncertainty of both.
"""
import argparse
import concurrent.futures
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from beamimpact import tables  # noqa: E402

import h5py  # noqa: E402
import numpy as np  # noqa: E402

SCENE = ["-beam_nodes", "21", "-ts_type", "modal", "-ball_law", "linear"]
TRUE = {"ball_k": 2.2e4, "beam_youngs_modulus": 6.3e10}
PARAMS = "ball_k=1e4:5e4,beam_youngs_modulus=5e10:9e10"
NAMES = ["ball_k", "beam_youngs_modulus"]


def run(exe, args, log):
    with open(log, "w") as f:
        r = subprocess.run([exe] + args, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode != 0:
        sys.exit("study_fit.py: %s failed (see %s)" % (" ".join(args[:6]), log))


def make_data(exe, out):
    """The program's acor and contact_time at the true parameters, one row per case."""
    h5 = os.path.join(out, "truth.h5")
    run(exe, SCENE + ["-task", "sweep", "-sweep", "impact_x=0.2:1.0:5,ball_speed=1;2", "-ball_k", "%.17g" % TRUE["ball_k"],
                      "-beam_youngs_modulus", "%.17g" % TRUE["beam_youngs_modulus"], "-sweep_quiet", "-output", h5, "-output_overwrite"], h5 + ".log")
    r = h5py.File(h5, "r")["results"]
    return {c: r[c][()] for c in ("impact_x", "ball_speed", "acor", "contact_time")}


def write_csv(path, d, acor, ct, sigma=None):
    with open(path, "w") as f:
        f.write("# made by scripts/study_fit.py: the program at ball_k %g N/m, E %g Pa%s\n" % (TRUE["ball_k"], TRUE["beam_youngs_modulus"],
                                                                                             "" if sigma is None else " plus Gaussian noise"))
        f.write("impact_x,ball_speed,acor,contact_time%s\n" % ("" if sigma is None else ",acor_sigma,contact_time_sigma"))
        for i in range(len(acor)):
            row = "%.17g,%.17g,%.17g,%.17g" % (d["impact_x"][i], d["ball_speed"][i], acor[i], ct[i])
            f.write(row + ("" if sigma is None else ",%.17g,%.17g" % sigma) + "\n")


def fit(exe, out, name):
    h5 = os.path.join(out, name + ".h5")
    for p in (h5, h5[:-3] + ".opts"):
        if os.path.exists(p):
            os.remove(p)
    run(exe, SCENE + ["-task", "fit", "-fit_data", os.path.join(out, name + ".csv"), "-fit_parameters", PARAMS, "-fit_quiet", "-output", h5], h5 + ".log")
    g = h5py.File(h5, "r")["fit"]
    return g["value"][()], g["standard_error"][()], float(h5py.File(h5, "r").attrs["fit_chi2"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--draws", type=int, default=60)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=36)
    ap.add_argument("--exe", default=os.path.join(HERE, "..", "build", "release", "beamimpact"))
    ap.add_argument("--out", default=os.path.join("out", "fit-study"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    d = make_data(a.exe, a.out)
    truth = np.array([TRUE[n] for n in NAMES])

    write_csv(os.path.join(a.out, "clean.csv"), d, d["acor"], d["contact_time"])
    p, se, chi2 = fit(a.exe, a.out, "clean")
    tables.print_table("Without noise: %d rows x 2 columns, fitted from the middle of the bounds (chi^2 %.3g)" % (len(d["acor"]), chi2),
                       ["parameter", "true", "fitted", "relative error"], [(n, t, v, (v - t) / t) for n, t, v in zip(NAMES, truth, p)], ["%s", "%.6g", "%.10g", "%.2e"])

    sigma = (0.01 * np.mean(d["acor"]), 0.01 * np.mean(d["contact_time"]))
    rng = np.random.default_rng(a.seed)
    for k in range(a.draws):
        acor = d["acor"] + sigma[0] * rng.standard_normal(len(d["acor"]))
        ct = d["contact_time"] + sigma[1] * rng.standard_normal(len(d["acor"]))
        write_csv(os.path.join(a.out, "draw%03d.csv" % k), d, acor, ct, sigma)
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        res = list(pool.map(lambda k: fit(a.exe, a.out, "draw%03d" % k), range(a.draws)))
    P = np.array([r[0] for r in res])
    S = np.array([r[1] for r in res])
    chi2 = np.array([r[2] for r in res])
    n = a.draws
    cover = np.mean(np.abs(P - truth) <= S, axis=0)
    scatter = np.std(P, axis=0, ddof=1)
    mean_se = np.mean(S, axis=0)
    dof = 2 * len(d["acor"]) - 2
    body = []
    for j, name in enumerate(NAMES):
        body.append((name, 100 * cover[j], 100 * math.sqrt(0.68 * 0.32 / n), mean_se[j], scatter[j], mean_se[j] / scatter[j], 1 / math.sqrt(2 * (n - 1)),
                     (np.mean(P[:, j]) - truth[j]) / scatter[j] * math.sqrt(n)))
    tables.print_table("With noise: %d draws, sigma = 1 %% of each column's mean (acor %.4g, contact_time %.4g s), given as _sigma columns (s^2 = 1)" % (n, sigma[0], sigma[1]),
                       ["parameter", "covered %", "+-", "mean se", "scatter", "se/scatter", "+-", "bias/(sd/sqrt n)"], body,
                       ["%s", "%.1f", "%.1f", "%.4g", "%.4g", "%.3f", "%.3f", "%+.2f"])
    print("\nchi^2 over the draws: mean %.2f (expected m - n = %d), standard deviation %.2f (expected %.2f)" % (np.mean(chi2), dof, np.std(chi2, ddof=1), math.sqrt(2 * dof)))
    print("goals: covered 68 +- 10 %%; se/scatter within 0.8-1.2; the +- columns: the binomial standard error of the share and the relative standard error of a standard deviation from %d draws" % n)


if __name__ == "__main__":
    main()
