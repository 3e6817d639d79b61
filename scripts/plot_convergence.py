#!/usr/bin/env python3
"""Work-precision and convergence diagrams from beamimpact -task convergence files.

    scripts/plot_convergence.py conv161.h5 -o out/conv161
    scripts/plot_convergence.py spatial.h5 -o out/spatial

For a file with integrator configurations (/configs) it writes
  PREFIX-work-precision.png  ACOR error against wall time (log-log), one curve per
                             configuration; the leapfrog baseline in black; the
                             target error (-convergence_target) as a dotted line;
  PREFIX-convergence.png     ACOR error and contact-time error against the step
                             (adaptive runs: the mean step), with reference slopes.
For a file with a spatial study (/spatial) it writes
  PREFIX-spatial.png         |A(h) - A(0)| against h for the ACOR, contact time and
                             peak force (A(0): the Richardson limit), slope 2 shown.
Failed runs are left out; ACOR errors at or below the file's error floor (the
reference's own accuracy, -convergence_error_floor) are drawn hollow at the floor.
Every observed order p in a legend is a least-squares fit over the points above the error
floor only (computed here from the plotted points, as the program does): the legend says how
many points were at the floor and left out, and a curve with fewer than two points above
it says "at the error floor: no order" instead of a number -- an order fitted to round-off
(e.g. "p = 0.34, expected 4") is never printed as if it were the method's.
"""
import argparse
import os
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt


def configs(f):
    names = [n for n in str(files.attr(f, "configs", "")).split(",") if n]
    out = []
    for n in names:
        g = f["configs"][n]
        d = {k: np.asarray(g[k][:], dtype=float) for k in g.keys()}
        d["name"] = n
        d["method"] = files.attr(g, "method", "ts")
        d["expected_order"] = float(files.attr(g, "expected_order", 0) or 0)
        d["order_lsq"] = float(files.attr(g, "order_acor_lsq", float("nan")))
        out.append(d)
    return out


def plot_floored(ax, x, e, floor, lab, st):
    """One curve; points at or below the floor (the reference's accuracy) drawn hollow at the floor."""
    ok = np.isfinite(x) & np.isfinite(e)
    if ok.sum() == 0:
        return
    x, e = x[ok], e[ok]
    y = np.maximum(e, floor) if floor > 0 else e
    ax.loglog(x, y, label=lab, **st)
    low = e <= floor
    if low.any():
        ax.loglog(x[low], y[low], linestyle="none", marker=st.get("marker", "o"), markersize=st.get("markersize", 5) + 3,
                  markerfacecolor="white", markeredgecolor=st["color"], zorder=st.get("zorder", 2) + 1)


def curve_style(i, d):
    if d["method"] == "leapfrog":
        return dict(color="black", marker="s", linewidth=2.4, markersize=6, zorder=5)
    markers = "o^vD<>pPhX*"
    cmap = plt.get_cmap("tab10")
    return dict(color=cmap(i % 10), marker=markers[i % len(markers)], linewidth=1.4, markersize=5)


def fit_order(h, e, floor):
    """Least-squares slope of log e against log h over the points above the floor (as
    ConvergenceObservedOrder does); returns (p or nan, points used, points at or below the floor)."""
    h, e = np.asarray(h, float), np.asarray(e, float)
    ok = np.isfinite(h) & (h > 0) & np.isfinite(e)
    above = ok & (e > floor)
    used, low = int(above.sum()), int((ok & ~above).sum())
    if used < 2 or np.ptp(np.log(h[above])) == 0:
        return float("nan"), used, low, float("nan")
    near = float(e[above].min() / floor) if floor > 0 else float("inf")
    return float(np.polyfit(np.log(h[above]), np.log(e[above]), 1)[0]), used, low, near


def order_text(p, used, low, near, expected=0.0):
    """'p = 3.96' with what it rests on; never a bare number fitted to round-off."""
    exp = ", expected %g" % expected if expected > 0 else ""
    if not np.isfinite(p):
        if low:
            return "at the error floor: no order (%d of %d points at or below it%s)" % (low, used + low, exp)
        return "no order (fewer than 2 points%s)" % exp
    t = "p = %.2f%s" % (p, exp)
    if low:
        t += "; from the %d points above the error floor, %d at it left out" % (used, low)
    if near < 10:
        t += "; its lowest point only %.2gx the floor" % near
    return t


def label(d, floor):
    ok = d["failed"] == 0
    p, used, low, near = fit_order(d["step"][ok], d["acor_error"][ok], floor)
    return "%s (%s)" % (d["name"], order_text(p, used, low, near, d["expected_order"]))


def work_precision(f, prefix):
    floor = float(files.attr(f, "convergence_error_floor", 0))
    target = float(files.attr(f, "convergence_target", 1e-6))
    fig, ax = plt.subplots(figsize=(8, 6))
    for i, d in enumerate(configs(f)):
        ok = d["failed"] == 0
        plot_floored(ax, d["wall_time"][ok], d["acor_error"][ok], floor, label(d, floor), curve_style(i, d))
    ax.axhline(target, color="grey", linestyle=":", linewidth=1)
    ax.text(ax.get_xlim()[0], target, " target %g" % target, va="bottom", ha="left", color="grey", fontsize=8)
    if floor > 0:
        ax.axhline(floor, color="grey", linestyle="-.", linewidth=0.8)
        ax.text(ax.get_xlim()[0], floor, " error floor %g (reference accuracy): hollow = at or below" % floor, va="bottom", ha="left", color="grey", fontsize=7)
    s = f["summary"].attrs if "summary" in f else {}
    note = ""
    if "baseline_over_best" in s:
        note = "\nat the target: best PETSc %s %.2e s, leapfrog %.2e s, baseline/best = %.2f" % (
            files.attr(f["summary"], "best_config"), files.attr(f["summary"], "best_time"), files.attr(f["summary"], "baseline_time"), files.attr(f["summary"], "baseline_over_best"))
    ax.set_xlabel("wall time, time stepping only (s, minimum of repeats)")
    ax.set_ylabel("ACOR error |acor - acor_ref|")
    ax.set_title("Work-precision: %s\nreference: %s%s" % (labels.scene_title(f), files.attr(f, "convergence_reference", "?"), note), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    return style.save(fig, prefix + "-work-precision.png", dpi=130)


def convergence(f, prefix):
    floor = float(files.attr(f, "convergence_error_floor", 0))
    cfgs = configs(f)
    fig, axes = plt.subplots(1, 2, figsize=(13, 6))
    for ax, err, name in ((axes[0], "acor_error", "ACOR error (absolute)"), (axes[1], "contact_time_error", "contact-time error (relative)")):
        hs, es = [], []
        fl = floor if err == "acor_error" else 0.0
        for i, d in enumerate(cfgs):
            ok = (d["failed"] == 0) & np.isfinite(d["step"]) & np.isfinite(d[err])
            if ok.sum() == 0:
                continue
            plot_floored(ax, d["step"][ok], d[err][ok], fl, label(d, floor) if err == "acor_error" else d["name"], curve_style(i, d))
            hs.extend(d["step"][ok])
            es.extend(np.maximum(d[err][ok], max(fl, 1e-16)))
        if hs:
            # Reference slopes through a common anchor at the upper left.
            h0, h1 = min(hs), max(hs)
            e0, emin = max(es), max(min(es) / 3, 1e-16)
            hh = np.geomspace(h0, h1, 20)
            for p in (1, 2, 3, 4, 5):
                ee = e0 * (hh / h1) ** p
                ax.loglog(hh, ee, color="grey", linestyle="--", linewidth=0.8)
                # label where the line leaves the plot (left end or bottom edge)
                k = np.argmax(ee >= emin) if ee[0] < emin else 0
                ax.text(hh[k], max(ee[k], emin), " %d" % p, color="grey", fontsize=8, va="bottom", clip_on=True)
            ax.set_ylim(emin, e0 * 3)
        if fl > 0:
            ax.axhline(fl, color="grey", linestyle="-.", linewidth=0.8)
            ax.text(ax.get_xlim()[0], fl, " error floor %g: hollow = at or below, left out of p" % fl, va="bottom", ha="left", color="grey", fontsize=7)
        ax.set_xlabel("step (s): fixed step, or mean step of adaptive runs")
        ax.set_ylabel(name)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Convergence through the contact events: %s (dashed: slopes 1-5)" % labels.scene_title(f), fontsize=10)
    return style.save(fig, prefix + "-convergence.png", dpi=130)


def spatial(f, prefix):
    g = f["spatial"]
    h = g["h"][:]
    # errors at or below the file's floor (round-off) are drawn hollow and left out of the fits
    floor = float(files.attr(f, "convergence_error_floor", 0) or 0)
    colours = iter(["C0", "C1", "C2"])
    fig, ax = plt.subplots(figsize=(7, 5.5))
    for q, lim, lab in (("acor", "acor_limit", "ACOR (absolute)"), ("contact_time", "contact_time_limit", "contact time (relative)"), ("peak_force", "peak_force_limit", "peak force (relative)")):
        a = g[q][:]
        a0 = float(files.attr(g, lim))
        e = np.abs(a - a0) / (1.0 if q == "acor" else abs(a0))
        ok = np.isfinite(e) & ((e > 0) | (floor > 0))  # an exact 0 has no place on a log axis
        ok[-1] = False  # the last level defines the limit
        if ok.sum():
            p, used, low, near = fit_order(h[ok], e[ok], floor)
            st = dict(color=next(colours), marker="o")
            plot_floored(ax, h[ok], e[ok], floor if floor > 0 else 1e-300, "%s, %s" % (lab, order_text(p, used, low, near)), st)
    ok = np.ones(len(h), bool)
    ok[-1] = False
    if ok.sum():
        ax.loglog(h[ok], (h[ok] / h[0]) ** 2 * 1e-2, color="grey", linestyle="--", label="slope 2")
    nodes = g["nodes"][:].astype(int)
    ax.set_xlabel("grid spacing h (m)")
    ax.set_ylabel("|A(h) - A(0)|, A(0) Richardson limit")
    ax.set_title("Spatial convergence, N = %s\nlimit: ACOR %.8f, contact time %.6e s" % (",".join(map(str, nodes)), float(files.attr(g, "acor_limit")), float(files.attr(g, "contact_time_limit"))), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return style.save(fig, prefix + "-spatial.png", dpi=130)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="HDF5 file written by beamimpact -task convergence")
    ap.add_argument("-o", "--output", help="output prefix (default: the file name without .h5)")
    a = ap.parse_args()
    prefix = a.output or os.path.splitext(a.file)[0]
    f = files.open_file("plot_convergence.py", a.file)
    written = []
    with f:
        if files.attr(f, "task") != "convergence":
            sys.stderr.write("plot_convergence.py: %s was not written by -task convergence\n" % a.file)
            return 1
        if "configs" in f:
            written += [work_precision(f, prefix), convergence(f, prefix)]
        if "spatial" in f:
            written.append(spatial(f, prefix))
    for p in written:
        print("wrote %s" % p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
