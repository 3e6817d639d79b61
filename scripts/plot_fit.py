#!/usr/bin/env python3
"""A fit of beamimpact -task fit, as a PNG: measured against fitted, the residuals, and the
confidence ellipses of the fitted parameters.

    scripts/plot_fit.py FIT.h5 [-o out.png] [--x OPTION]

Top row: each measured column against a setting of the rows (--x, default the data's option
column with the most distinct values; the row number when there is none): the measured values
with error bars (their sigma, times s = sqrt(chi^2/(m - n)) when the sigma are relative weights:
the scatter the fit's standard errors assume) and the program's values at the optimum. Middle:
the weighted residuals (fitted - measured)/sigma of every value, each column its colour. Bottom:
for each pair of parameters the ellipse chi^2 = chi^2_min + 1 of their covariance (its shadow on
each axis is the standard error; a pair with a parameter the data do not determine is said, not
drawn), centred on the optimum, with the start marked. Everything is read from the file's /fit
(docs/fit.md, "Output"); nothing is recomputed. Default output: FIT with .png.

    build/release/beamimpact -options_file options/fits/baseball-wall.opts
    scripts/plot_fit.py baseball-wall-fit.h5
"""
import argparse
import itertools
import os
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_fit.py"


def fail(msg):
    sys.stderr.write("%s: %s\n" % (PROG, msg))
    sys.exit(1)


def read(path):
    """The fit's tables: parameters, covariance, residuals per value and each row's settings."""
    f = files.open_file(PROG, path)
    with f:
        if files.attr(f, "task") != "fit" or "fit" not in f:
            fail("%s is not a -task fit file (its task: %s)" % (path, files.attr(f, "task")))
        g = f["fit"]
        d = {"names": files.text(g, "names"), "unit": files.text(g, "unit"), "value": files.numbers(g, "value"), "se": files.numbers(g, "standard_error"),
             "start": files.numbers(g, "start"), "cov": g["covariance"][()], "chi2": files.attr(f, "fit_chi2"), "dof": files.attr(f, "fit_dof"),
             "relative": files.attr(f, "fit_sigma") == "relative", "data": files.attr(f, "fit_data"), "task": files.attr(f, "fit_task")}
        r = g["residuals"]
        d["res"] = {k: files.numbers(r, k) for k in ("row", "measured", "sigma", "fitted", "weighted_residual")}
        d["res"]["column"] = files.text(r, "column")
        d["res"]["unit"] = files.text(r, "unit")
        d["rows"] = {k: (files.numbers(g["rows"], k), labels.unit_text(files.unit(g["rows"][k]))) for k in (g["rows"].keys() if "rows" in g else [])}
    return d


def x_axis(d, name):
    """The setting the measured values are drawn against: (values per residual, label)."""
    rows = d["rows"]
    if name is not None and name not in rows:
        fail("--x %s is not a numeric column of the data (they are: %s)" % (name, ", ".join(rows) or "none"))
    if name is None:
        best = [(len(np.unique(v[np.isfinite(v)])), k) for k, (v, u) in rows.items()]
        name = max(best)[1] if best and max(best)[0] > 1 else None
    row = d["res"]["row"].astype(int) - 1
    if name is None:
        return row + 1.0, "row of the data"
    v, u = rows[name]
    return v[row], name + (" (%s)" % u if u else "")


def ellipse(ax, centre, cov, colour):
    """The chi^2_min + 1 contour of a 2-D Gaussian with covariance cov around centre."""
    w, V = np.linalg.eigh(cov)
    t = np.linspace(0, 2 * np.pi, 200)
    pts = V @ np.vstack([np.sqrt(np.maximum(w[0], 0)) * np.cos(t), np.sqrt(np.maximum(w[1], 0)) * np.sin(t)])
    ax.plot(centre[0] + pts[0], centre[1] + pts[1], color=colour)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("fit")
    ap.add_argument("-o", "--output")
    ap.add_argument("--x", help="the data's option column to draw the measured values against")
    a = ap.parse_args()
    d = read(a.fit)
    out = a.output or os.path.splitext(a.fit)[0] + ".png"
    res, cols = d["res"], list(dict.fromkeys(d["res"]["column"]))
    x, xlabel = x_axis(d, a.x)
    scale = np.sqrt(d["chi2"] / d["dof"]) if d["relative"] and d["dof"] > 0 else 1.0
    n = len(d["names"])
    pairs = list(itertools.combinations(range(n), 2))
    ncol = max(len(cols), len(pairs), 1)
    fig = plt.figure(figsize=(4.2 * ncol, 10.5 if pairs else 7))
    nrow = 3 if pairs else 2
    c = style.colours()
    for k, name in enumerate(cols):
        ax = fig.add_subplot(nrow, ncol, k + 1)
        m = np.array([col == name for col in res["column"]])
        order = np.argsort(x[m], kind="stable")
        ax.errorbar(x[m], res["measured"][m], yerr=scale * res["sigma"][m], fmt="o", ms=4, color=c[k % len(c)], label="measured")
        ax.plot(x[m][order], res["fitted"][m][order], "x--", color="k", lw=0.8, label="fitted")
        unit = labels.unit_text(res["unit"][int(np.nonzero(m)[0][0])])
        ax.set_xlabel(xlabel)
        ax.set_ylabel(name + (" (%s)" % unit if unit else ""))
        ax.legend(fontsize=8)
    ax = fig.add_subplot(nrow, 1, 2)
    for k, name in enumerate(cols):
        m = np.array([col == name for col in res["column"]])
        ax.plot(np.nonzero(m)[0] + 1, res["weighted_residual"][m], "o", color=c[k % len(c)], label=name)
    ax.axhline(0, color="k", lw=0.6)
    if scale != 1.0:
        for s in (-scale, scale):
            ax.axhline(s, color="grey", lw=0.6, ls=":")
    ax.set_xlabel("measured value (in the data's order)")
    ax.set_ylabel("(fitted - measured)/sigma")
    ax.set_title("chi^2 = %.4g for m - n = %d (%s sigma)" % (d["chi2"], d["dof"], "relative" if d["relative"] else "absolute"), fontsize=9)
    ax.legend(fontsize=8)
    for k, (i, j) in enumerate(pairs):
        ax = fig.add_subplot(nrow, ncol, 2 * ncol + k + 1)
        sub = d["cov"][np.ix_([i, j], [i, j])]
        ax.plot(d["value"][i], d["value"][j], "+", color="k", ms=10, label="optimum")
        if np.all(np.isfinite(sub)):
            ellipse(ax, (d["value"][i], d["value"][j]), sub, c[0])
            for q, set_lim in ((i, ax.set_xlim), (j, ax.set_ylim)): # the ellipse's neighbourhood; the start, far away, in the legend
                if d["se"][q] > 0:
                    set_lim(d["value"][q] - 2.5 * d["se"][q], d["value"][q] + 2.5 * d["se"][q])
            ax.plot([], [], "s", mfc="none", color="grey", label="start %.4g, %.4g" % (d["start"][i], d["start"][j]))
        else:
            ax.plot(d["start"][i], d["start"][j], "s", mfc="none", color="grey", label="start")
            ax.text(0.5, 0.5, "not determined\nby these data", transform=ax.transAxes, ha="center", va="center", color="r")
        for q, set_label in ((i, ax.set_xlabel), (j, ax.set_ylabel)):
            u = labels.unit_text(d["unit"][q])
            set_label(d["names"][q] + (" (%s)" % u if u and u != "1" else ""))
        ax.legend(fontsize=7)
    fig.suptitle("%s: -task fit of %s (-fit_task %s)" % (os.path.basename(a.fit), d["data"], d["task"]), fontsize=10)
    style.save(fig, out, dpi=110)
    print("wrote %s: %d measured columns, %d parameters, chi^2 %.4g" % (out, len(cols), n, d["chi2"]))


if __name__ == "__main__":
    main()
