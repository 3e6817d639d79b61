#!/usr/bin/env python3
"""A sampled sweep (docs/uncertainty.md) as a PNG: per column, its histogram with the mean and the
5/50/95 % quantiles, its scatter against each sampled input and, with -sweep_sobol, the first and
total Sobol' indices as bars with their 95 % intervals; or the convergence of the mean with N.

    scripts/plot_uq.py FILE.h5 [COLUMN ...] [-o out.png] [--certify B1,B2,... [--cap 0.5] [--hits 6]]
    scripts/plot_uq.py --convergence COLUMN --reference-grid GRID.h5 RANDOM.h5 SOBOL.h5 ... [-o out.png]

COLUMN: /results columns (default: acor). The numbers drawn are the file's own /statistics and
/sobol (nothing recomputed); with Saltelli's design the histogram and scatter use the A and B rows.
--certify (the certification study): the reported value is the mean of --hits independent valid
hits; printed: the single hit's mean and spread, the reported value's spread s/sqrt(hits), and for
each nominal B the probability that a bat whose reported value is centred on B reports above
--cap (normal; with random points also counted over groups of consecutive hits, with Wilson's
95 % interval).
--convergence: |mean of the first n rows - the reference| against n for each file (its
-sweep_sampling in the legend) with the line n^(-1/2); the reference is the mean of COLUMN over
the grid sweep GRID.h5 of the one sampled input's range (Simpson's rule on its uniform grid).
"""
import argparse
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt
PROG = "plot_uq.py"


def fail(msg):
    sys.stderr.write("%s: %s\n" % (PROG, msg))
    sys.exit(1)


def text_list(v):
    return [x.decode() if isinstance(x, bytes) else str(x) for x in v]


def design_rows(f):
    """Rows of the independent points: all, or A and B of Saltelli's blocks."""
    n = f["results/case_index"].shape[0]
    inputs = text_list(f["statistics"].attrs["inputs"])
    if int(files.attr(f, "sweep_sobol", 0) or 0):
        block = len(inputs) + 2
        return np.array([i for i in range(n) if i % block < 2]), inputs
    return np.arange(n), inputs


def wilson(k, n, z=1.959963984540054):
    p = k / n
    den = 1 + z * z / n
    c, h = (p + z * z / (2 * n)) / den, z / den * np.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return max(0.0, c - h), min(1.0, c + h)


def certify(f, col, nominals, cap, hits):
    """The reported value is the mean of `hits` independent hits: its spread s / sqrt(hits), the
    chance of reporting above the cap at nominal b 1 - Phi((cap - b) / that) (normal); with random
    points also counted over groups of consecutive hits (Sobol' and LHS points are stratified:
    their consecutive groups are too even to count)."""
    from math import erf, sqrt
    rows, _ = design_rows(f)
    y = files.numbers(f["results"], col)[rows]
    y = y[np.isfinite(y)]
    s6 = y.std(ddof=1) / np.sqrt(hits)
    print("%s: one hit %.4f, std %.4f (%d hits); the reported value (mean of %d hits) spreads by %.4f"
          % (col, y.mean(), y.std(ddof=1), len(y), hits, s6))
    random = str(files.attr(f, "sweep_sampling", "")) == "random"
    groups = y[: len(y) // hits * hits].reshape(-1, hits).mean(axis=1) if random else None
    for b in nominals:
        p = 0.5 * (1 - erf((cap - b) / (s6 * sqrt(2))))
        line = "  nominal %.3f: P(reported > %.3f) = %.3f (normal)" % (b, cap, p)
        if random:
            k = int(np.sum(groups - groups.mean() + b > cap))
            lo, hi = wilson(k, len(groups))
            line += "; counted over %d groups of %d: %.3f, 95%% interval [%.3f, %.3f]" % (len(groups), hits, k / len(groups), lo, hi)
        print(line)


def draw_file(f, cols, out):
    rows, inputs = design_rows(f)
    r = f["results"]
    sob = "sobol" in f
    ncol = 1 + len(inputs) + (1 if sob else 0)
    fig, axes = plt.subplots(len(cols), ncol, figsize=(3.6 * ncol, 3.0 * len(cols)), squeeze=False)
    for i, col in enumerate(cols):
        if col not in r or col not in f["statistics"]:
            fail("%s is not a column with statistics; those of this file: %s" % (col, ", ".join(k for k in f["statistics"] if k in r)))
        y = files.numbers(r, col)[rows]
        st = f["statistics"][col]
        ax = axes[i][0]
        ax.hist(y[np.isfinite(y)], bins=30, color="0.7")
        for q, ls in (("q05", ":"), ("q50", "--"), ("q95", ":")):
            ax.axvline(st[q][0], color="k", ls=ls, lw=1)
        ax.axvline(st["mean"][0], color="C3", lw=1.5, label="mean %.4g +- %.2g" % (st["mean"][0], st["sem"][0]))
        ax.set_xlabel(labels.axis_label(r, col))
        ax.set_ylabel("points")
        ax.legend(fontsize=7)
        for j, inp in enumerate(inputs):
            ax = axes[i][1 + j]
            ax.plot(files.numbers(r, inp)[rows], y, ".", ms=3)
            ax.set_xlabel(labels.axis_label(r, inp))
            ax.set_ylabel(col)
        if sob:
            s = f["sobol"][col]
            ax = axes[i][-1]
            x = np.arange(len(inputs))
            for k, (name, off) in enumerate((("first", -0.2), ("total", 0.2))):
                v, ci = s[name][0], s[name + "_ci"][0]
                ax.bar(x + off, v, 0.4, label=name, color="C%d" % k,
                       yerr=[np.maximum(v - ci[:, 0], 0), np.maximum(ci[:, 1] - v, 0)], capsize=3)
            ax.set_xticks(x)
            ax.set_xticklabels(inputs, rotation=20, fontsize=8)
            ax.set_ylabel("Sobol' index of %s" % col)
            ax.set_ylim(-0.1, 1.15)
            ax.legend(fontsize=7)
    print("wrote", style.save(fig, out))


def grid_mean(path, col):
    g = files.open_file(PROG, path)
    axes = files.sweep_axes(g)
    if len(axes) != 1:
        fail("%s: the reference grid sweep must have one axis" % path)
    y = files.numbers(g["results"], col)
    n = len(y) - 1
    if n % 2:
        fail("%s: Simpson's rule needs an odd number of grid points, not %d" % (path, n + 1))
    return (y[0] + y[-1] + 4 * y[1:-1:2].sum() + 2 * y[2:-1:2].sum()) / (3 * n)


def convergence(paths, col, grid, out):
    ref = grid_mean(grid, col)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    nmax = 1
    for p in paths:
        f = files.open_file(PROG, p)
        rows, _ = design_rows(f)
        y = files.numbers(f["results"], col)[rows]
        n = np.arange(1, len(y) + 1)
        err = np.abs(np.cumsum(y) / n - ref)
        pick = np.unique(np.round(np.geomspace(1, len(y), 60)).astype(int)) - 1
        ax.loglog(n[pick], err[pick], ".-", label="%s (N = %d: error %.2g)" % (files.attr(f, "sweep_sampling", "?"), len(y), err[-1]))
        nmax = max(nmax, len(y))
    nn = np.array([1, nmax])
    ax.loglog(nn, np.std(y) / np.sqrt(nn), "k--", lw=1, label="std / sqrt(N)")
    ax.set_xlabel("N (points)")
    ax.set_ylabel("|mean of %s - grid integral|" % col)
    ax.set_title("reference %.8g (%s)" % (ref, grid), fontsize=8)
    ax.legend(fontsize=7)
    print("wrote", style.save(fig, out))


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 1)[1],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="+", help="FILE.h5 [COLUMN ...], or with --convergence the sampled files")
    ap.add_argument("-o", "--output")
    ap.add_argument("--certify", help="nominal values B1,B2,...: the probability of reporting above --cap")
    ap.add_argument("--cap", type=float, default=0.5)
    ap.add_argument("--hits", type=int, default=6)
    ap.add_argument("--convergence", metavar="COLUMN")
    ap.add_argument("--reference-grid", metavar="GRID.h5")
    a = ap.parse_args()
    if a.convergence:
        if not a.reference_grid:
            fail("--convergence needs --reference-grid GRID.h5")
        convergence(a.files, a.convergence, a.reference_grid, a.output or "uq-convergence.png")
        return 0
    path, cols = a.files[0], a.files[1:] or ["acor"]
    f = files.open_file(PROG, path)
    if "statistics" not in f:
        fail("%s has no /statistics: not a sampled sweep (-sweep NAME=normal:..., -sweep_samples N)" % path)
    if a.certify:
        certify(f, cols[0], [float(v) for v in a.certify.split(",")], a.cap, a.hits)
    draw_file(f, cols, a.output or files.default_prefix(path) + ".png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
