#!/usr/bin/env python3
"""The history of a beamimpact -task design file, as a PNG.

    scripts/plot_design.py FILE.h5 [-o out.png] [--variables A,B]

Left: the objective of every design evaluated (/design/objective) in the order evaluated, TAO's
iterates (/design/role 0) joined and marked, infeasible designs (/design/feasible 0) hollow; each
constraint's quantity below it with its bound. Right: the designs in two variables (the first two
of /design/variables, or --variables A,B), coloured by the objective, the path of the iterates from
the start to the optimum (/design/optimum). Everything drawn is read from the file
(docs/design-studies.md, "Output"). Default output: the file's name with .png. For example:

    build/release/beamimpact -options_file options/designs/bbcor-bat.opts
    scripts/plot_design.py bbcor-bat.h5
"""
import argparse
import os
import sys

from beamimpact import style  # re-executes with a Python that has numpy, h5py and matplotlib

import h5py
import numpy as np

plt = style.plt


def text(v):
    return [x.decode() if isinstance(x, bytes) else str(x) for x in v]


def main():
    ap = argparse.ArgumentParser(prog="plot_design.py", description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--output")
    ap.add_argument("--variables", help="two design variables for the right panel: A,B")
    a = ap.parse_args()
    try:
        d = h5py.File(a.file, "r")["design"]
    except (OSError, KeyError) as e:
        sys.exit("plot_design.py: %s has no /design group (a -task design file?): %s" % (a.file, e))
    names = text(d["variables"][()])
    cons = text(d["constraints"][()]) if "constraints" in d else []
    obj, role, feas = d["objective"][()], d["role"][()], d["feasible"][()].astype(bool)
    objective = text(d["objective_text"][()])[0]
    k = np.arange(len(obj))
    it = role == 0
    nrow = 1 + len(cons)
    fig = plt.figure(figsize=(12, 3 + 2 * nrow))
    ax = fig.add_subplot(nrow, 2, 1)
    ax.plot(k[feas], obj[feas], ".", color="0.6", label="designs evaluated")
    ax.plot(k[~feas], obj[~feas], "o", mfc="none", color="C3", label="infeasible")
    ax.plot(k[it], obj[it], "-o", color="C0", label="TAO's iterates")
    ax.set_ylabel(objective)
    ax.legend(fontsize=8)
    for i, c in enumerate(cons):
        axc = fig.add_subplot(nrow, 2, 3 + 2 * i, sharex=ax)
        axc.plot(k, d[c][()], ".", color="0.6")
        axc.plot(k[it], d[c][()][it], "-o", color="C0")
        axc.set_ylabel(c)
    fig.axes[-1].set_xlabel("design (in the order evaluated)")
    pair = a.variables.split(",") if a.variables else names[:2]
    axr = fig.add_subplot(1, 2, 2)
    if len(pair) == 2 and all(p in names for p in pair):
        x, y = d[pair[0]][()], d[pair[1]][()]
        sc = axr.scatter(x, y, c=obj, cmap="viridis", s=20)
        axr.plot(x[it], y[it], "-", color="k", lw=1)
        opt = d["optimum"][()]
        axr.plot(opt[names.index(pair[0])], opt[names.index(pair[1])], "*", ms=15, color="C3", label="optimum")
        axr.plot(x[0], y[0], "s", color="k", label="start")
        axr.set_xlabel(pair[0])
        axr.set_ylabel(pair[1])
        axr.legend(fontsize=8)
        fig.colorbar(sc, ax=axr, label=objective)
    else:
        x = d[names[0]][()]
        axr.scatter(x, obj, c=feas, cmap="coolwarm_r", s=20)
        axr.plot(x[it], obj[it], "-o", color="C0")
        axr.set_xlabel(names[0])
        axr.set_ylabel(objective)
    fig.tight_layout()
    out = a.output or os.path.splitext(a.file)[0] + ".png"
    fig.savefig(out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
