#!/usr/bin/env python3
"""The history of a beamimpact -task design file, as a PNG.

    scripts/plot_design.py FILE.h5 [-o out.png] [--variables A,B]
    scripts/plot_design.py FILE.h5 --base DESIGN.opts [--grid A,B] [--grid-points 5] [--grid-span 0.2]

Left: the objective of every design evaluated (/design/objective) in the order evaluated, TAO's
iterates (/design/role 0) joined and marked, infeasible designs (/design/feasible 0) hollow; each
constraint's quantity below it with its bound. Right: the designs in two variables (the first two
of /design/variables, or --variables A,B), coloured by the objective, the path of the iterates from
the start to the optimum (/design/optimum). Everything drawn is read from the file
(docs/design-studies.md, "Output"). Default output: the file's name with .png.

With --base (the options file the design ran from) a second figure, FILE-optimum.png: left, the
optimum's section against the start's (a round profile's outline +-D/2 and bore d, else the mass per
length), from -task modes of the base with the variables set (/beam/profile_*, /beam/mu); right, the
objective over two variables (--grid, default the first two) on a grid of --grid-points squared
designs around the optimum (+-grid-span of each variable's range, within its bounds), the other
variables at the optimum, from a -task sweep per study the script runs (the studies of
/options_used/design_studies, their impact points as sweep axes, reduced as the objective says),
with the boundary of each study constraint (its quantity at its bound) drawn; the bat's own numbers
(drop, mass, ...) are not drawn. The runs go to FILE-grid-STUDY.h5 (kept: a rerun resumes them).
--exe: the program (default build/release/beamimpact, else build/dev/beamimpact). For example:

    build/release/beamimpact -options_file options/designs/bbcor-bat.opts
    scripts/plot_design.py bbcor-bat.h5 --base options/designs/bbcor-bat.opts
"""
import argparse
import os
import re
import subprocess
import sys

from beamimpact import style  # re-executes with a Python that has numpy, h5py and matplotlib

import h5py
import numpy as np

plt = style.plt


def text(v):
    return [x.decode() if isinstance(x, bytes) else str(x) for x in v]


REDUCE = {"max": np.max, "min": np.min, "mean": np.mean}


def quantity(q):
    """'max(bbs@game)' -> (np.max, 'bbs', 'game'); 'acor@hit' -> (None, 'acor', 'hit'); a bat number: None."""
    m = re.fullmatch(r"\s*(?:(max|min|mean)\()?\s*(\w+)@(\w+)\s*\)?\s*", q)
    return (REDUCE[m.group(1)] if m.group(1) else None, m.group(2), m.group(3)) if m else None


def studies(text):
    """'rig{a=1, x=0:1:3} game{...}' -> {'rig': ([('a', '1')], ['x=0:1:3']), ...}: settings and sweep axes."""
    out = {}
    for name, body in re.findall(r"(\w+)\{([^}]*)\}", text):
        settings, axes = [], []
        for item in filter(None, (x.strip() for x in body.split(","))):
            k, v = item.split("=", 1)
            (axes if (":" in v or ";" in v) else settings).append((k.strip(), v.strip()) if ":" not in v and ";" not in v else "%s=%s" % (k.strip(), v.strip()))
        out[name] = (settings, axes)
    return out


def program(exe):
    here = os.path.dirname(os.path.abspath(__file__))
    for c in ([exe] if exe else [os.path.join(here, "..", "build", b, "beamimpact") for b in ("release", "dev")]):
        if os.access(c, os.X_OK):
            return c
    sys.exit("plot_design.py: no beamimpact program (give --exe)")


def run(cmd, log):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit("plot_design.py: %s failed:\n%s" % (" ".join(cmd), r.stdout[-3000:]))
    print("  %s" % log)


def section(exe, base, names, values, out):
    cmd = [exe, "-options_file", base, "-task", "modes", "-output", out]
    for n, v in zip(names, values):
        cmd += ["-" + n, "%.17g" % v]
    run(cmd, "section: " + out)
    with h5py.File(out, "r") as f:
        b = f["beam"]
        if "profile_x" in b:
            return b["profile_x"][()], b["profile_D"][()], b["profile_d"][()], None
        return b["x"][()], None, None, b["mu"][()]


def grid(exe, base, stem, d, names, pair, points, span):
    """The objective and the study constraints on a grid of pair around the optimum: (A, B, {q: Z})."""
    opt, lo, hi = d["optimum"][()], d["lower"][()], d["upper"][()]
    axes = []
    for p in pair:
        j = names.index(p)
        half = span * (hi[j] - lo[j])
        a, b = max(lo[j], opt[j] - half), min(hi[j], opt[j] + half)
        axes.append(np.linspace(a, b, points))
    used = d.file.attrs  # the run record: design_studies, design_objective, design_constraints
    text = lambda k: used[k].decode() if isinstance(used[k], bytes) else str(used[k])
    plan = studies(text("design_studies"))
    qs = [text("design_objective")] + [c.strip() for c in re.split(r",(?![^(]*\))", text("design_constraints")) if c.strip()] if "design_constraints" in used else [text("design_objective")]
    values = {}
    for q in qs:
        bound = None
        m = re.fullmatch(r"(.*?)(<=|>=)\s*([-+0-9.eE]+)", q)
        if m:
            q, bound = m.group(1).strip(), float(m.group(3))
        parsed = quantity(q)
        if not parsed:
            continue  # a bat number: not drawn
        reduce, column, study = parsed
        settings, saxes = plan[study]
        out = "%s-grid-%s.h5" % (stem, study)
        if not os.path.exists(out) or study not in values.get("_run", set()):
            cmd = [exe, "-options_file", base, "-task", "sweep", "-sweep_quiet", "-output", out, "-sweep",
                   ",".join(["%s=%s" % (p, ";".join("%.10g" % v for v in ax)) for p, ax in zip(pair, axes)] + saxes)]
            for n, v in zip(names, opt):
                if n not in pair:
                    cmd += ["-" + n, "%.17g" % v]
            for k, v in settings:
                cmd += ["-" + k, v]
            run(cmd, "grid of %s: %s" % (study, out))
            values.setdefault("_run", set()).add(study)
        with h5py.File(out, "r") as f:
            r = f["results"]
            x, y, z = r[pair[0]][()], r[pair[1]][()], r[column][()]
        Z = np.array([[(reduce or (lambda v: v[0]))(z[np.isclose(x, a) & np.isclose(y, b)]) for a in axes[0]] for b in axes[1]])
        values[q] = (Z, bound)
    values.pop("_run", None)
    return axes, values


def optimum_figure(a, d, names, objective, out):
    exe = program(a.exe)
    stem = os.path.splitext(a.file)[0]
    fig, (axp, axg) = plt.subplots(1, 2, figsize=(12, 4.8))
    for label, key, colour in (("start", "start", "0.5"), ("optimum", "optimum", "C3")):
        x, D, dd, mu = section(exe, a.base, names, d[key][()], "%s-section-%s.h5" % (stem, key))
        if D is not None:
            axp.plot(x, D / 2, color=colour, label=label)
            axp.plot(x, -D / 2, color=colour)
            if np.any(dd > 0):
                axp.plot(x, dd / 2, "--", color=colour, lw=0.8)
                axp.plot(x, -dd / 2, "--", color=colour, lw=0.8)
            axp.set_ylabel("radius: outline and bore (dashed) (m)")
        else:
            axp.plot(x, mu, color=colour, label=label)
            axp.set_ylabel("mass per length (kg/m)")
    axp.set_xlabel("x (m)")
    axp.legend(fontsize=8)
    axp.set_title("the section: start and optimum")
    pair = a.grid.split(",") if a.grid else names[:2]
    if len(pair) == 2 and all(p in names for p in pair):
        (ga, gb), values = grid(exe, a.base, stem, d, names, pair, a.grid_points, a.grid_span)
        A, B = np.meshgrid(ga, gb)
        Z, _ = values.pop(objective)
        cs = axg.contourf(A, B, Z, 20, cmap="viridis")
        fig.colorbar(cs, ax=axg, label=objective)
        for i, (q, (C, bound)) in enumerate(values.items()):
            if bound is not None and C.min() < bound < C.max():
                cc = axg.contour(A, B, C, [bound], colors="C%d" % (3 + i), linewidths=2)
                axg.clabel(cc, fmt={bound: "%s = %g" % (q, bound)}, fontsize=8)
        opt = d["optimum"][()]
        axg.plot(opt[names.index(pair[0])], opt[names.index(pair[1])], "*", ms=15, color="C3", label="optimum")
        axg.set_xlabel(pair[0])
        axg.tick_params(axis="x", labelrotation=25)
        axg.set_ylabel(pair[1])
        axg.legend(fontsize=8)
        axg.set_title("%s around the optimum (%d x %d designs)" % (objective, a.grid_points, a.grid_points))
    else:
        axg.set_visible(False)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print("wrote %s" % out)


def main():
    ap = argparse.ArgumentParser(prog="plot_design.py", description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--output")
    ap.add_argument("--variables", help="two design variables for the right panel: A,B")
    ap.add_argument("--base", help="the options file the design ran from: draws FILE-optimum.png too")
    ap.add_argument("--grid", help="the two variables of the objective's grid: A,B (default the first two)")
    ap.add_argument("--grid-points", type=int, default=5, help="points along each of the grid's variables")
    ap.add_argument("--grid-span", type=float, default=0.2, help="the grid's half-width, a fraction of each variable's range")
    ap.add_argument("--exe", help="the beamimpact program")
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
    if a.base:
        optimum_figure(a, d, names, objective, os.path.splitext(out)[0] + "-optimum.png")


if __name__ == "__main__":
    main()
