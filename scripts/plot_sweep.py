#!/usr/bin/env python3
"""Plots of beamimpact -task sweep files (and -task impact files), as a PNG.

    scripts/plot_sweep.py FILE.h5 [FILE2.h5 ...] [COLUMN] [-o out.png] [--map | --curves]

COLUMN is any /results column (default: acor_corrected). What is drawn follows the
file's axes (the attribute sweep_axes, in the order of the sweep):

* one axis: COLUMN against it, one curve per file. For the ACOR against the impact
  point (the paper's figures) each file gives one colour: acor_corrected solid with
  markers, the raw acor dotted (omitted when equal: hysteretic ball) and the rigid-body
  ACOR of Eq. (11) dashed; legends come from the files' attributes (length, supports,
  thickness, ball law, f).
* two axes (one file): one curve per value of the axis with at most 6 values, against
  the other; or, when both have more (or with --map), a 2-D map of COLUMN with contour
  lines over the two axes.

Failed points (status != 0) are marked with their status code: an 'x' at the foot of the
curve's axes, or the code written on the map (the codes are listed in docs/sweep.md).
The file may be one still being written (its rows so far are drawn).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from debian_python import require  # noqa: E402

require(__file__, "numpy", "h5py", "matplotlib")
import argparse  # noqa: E402

import numpy as np  # noqa: E402
import h5py  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

PROG = "plot_sweep.py"
MAX_CURVES = 6


def attr(f, name, default=None):
    v = f.attrs.get(name, default)
    if isinstance(v, bytes):
        v = v.decode()
    if hasattr(v, "item"):
        v = v.item()
        if isinstance(v, bytes):
            v = v.decode()
    return v


def label_of(f, path):
    """Length, supports, thickness, ball law, from the run attributes."""
    parts = []
    L = attr(f, "beam_length")
    if L is not None:
        parts.append("L = %g m" % L)
    left, right = attr(f, "beam_left"), attr(f, "beam_right")
    if left and right:
        parts.append("%s-%s" % (left, right))
    x0, x1 = attr(f, "beam_clamp_x0", -1), attr(f, "beam_clamp_x1", -1)
    if x0 is not None and x0 >= 0:
        parts.append("clamped %g-%g m" % (x0, x1))
    a = attr(f, "beam_thickness", 0)
    if a and "beam_thickness" not in axes_of(f):
        parts.append("a = %g mm" % (a * 1e3))
    n = attr(f, "beam_nodes")
    if n and "beam_nodes" not in axes_of(f):
        parts.append("N = %d" % n)
    law, mb, vb = attr(f, "ball_law"), attr(f, "ball_mass"), attr(f, "ball_speed")
    if law:
        ball = law + " ball"
        if mb and vb and "ball_speed" not in axes_of(f):
            ball += " %g g at %g m/s" % (mb * 1e3, vb)
        parts.append(ball)
    done, total = attr(f, "sweep_cases_done"), attr(f, "sweep_cases_total")
    if done is not None and total is not None and done < total:
        parts.append("partial %d/%d" % (done, total))
    return ", ".join(parts) if parts else os.path.basename(path)


def held(f):
    """Whether the beam is held (a support other than free, a clamped region, a pivot)."""
    left, right = attr(f, "beam_left"), attr(f, "beam_right")
    x0 = attr(f, "beam_clamp_x0", -1)
    opts = attr(f, "options", "") or ""
    return (left not in (None, "free")) or (right not in (None, "free")) or (x0 is not None and x0 >= 0) or "-beam_pivot" in opts


def axes_of(f):
    """The swept options, in the order of the sweep; ['x'] for a -task impact file or an old sweep."""
    names = [a for a in (attr(f, "sweep_axes") or "").split(",") if a]
    r = f["results"]
    names = [a if a in r else ("x" if a == "impact_x" and "x" in r else a) for a in names]
    return names or ["x"]


def unit_of(r, name):
    u = r[name].attrs.get("unit", b"") if name in r else b""
    u = u.decode() if isinstance(u, bytes) else str(u)
    return "" if u in ("", "1") else u


def axis_label(r, name):
    u = unit_of(r, name)
    nice = {"impact_x": "impact point x", "x": "impact point x"}.get(name, name)
    return "%s (%s)" % (nice, u) if u else nice


def geometric(v):
    v = np.unique(v)
    return len(v) > 2 and np.all(v > 0) and np.allclose(np.diff(np.log(v)), np.log(v[1] / v[0]), rtol=1e-6)


def load(path):
    try:
        f = h5py.File(path, "r")
    except OSError as err:
        sys.exit("%s: cannot read %s: %s" % (PROG, path, err))
    if "results" not in f:
        sys.exit("%s: %s has no /results (is it a beamimpact sweep or impact file?)" % (PROG, path))
    return f


def status_of(r, n):
    return r["status"][()].astype(int) if "status" in r else np.zeros(n, dtype=int)


def mark_failed(ax, xs, codes, colour="k"):
    """An 'x' at the foot of the axes at each failed point, with its status code."""
    if len(xs) == 0:
        return
    trans = ax.get_xaxis_transform()
    ax.plot(xs, np.full(len(xs), 0.02), "x", color=colour, transform=trans, clip_on=False, markersize=6)
    for x, c in zip(xs, codes):
        ax.text(x, 0.05, str(c), transform=trans, ha="center", va="bottom", fontsize=7, color=colour)


def plot_one_axis(args, files, column):
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    acor_mode = column in ("acor", "acor_corrected")
    any_raw = any_rigid = any_failed = any_held = any_multi = False
    xlabel = None
    for k, (path, f) in enumerate(files):
        r = f["results"]
        if column not in r:
            sys.exit("%s: %s has no /results/%s; its columns: %s" % (PROG, path, column, ", ".join(sorted(r))))
        name = axes_of(f)[0]
        xlabel = xlabel or axis_label(r, name)
        x = r[name][()]
        order = np.argsort(x, kind="stable")
        x = x[order]
        y = r[column][()][order]
        st = status_of(r, len(order))[order]
        c = colours[k % len(colours)]
        label = args.label[k] if args.label else label_of(f, path)
        rigid = r["rigid_acor"][()][order] if acor_mode and "rigid_acor" in r else None
        if rigid is not None and held(f):
            rigid = None  # Eq. (11) is the free rigid body: no curve for a held or pivoted beam
            any_held = True
        if acor_mode and not args.no_rigid and rigid is not None:
            label += "; rigid f = %g" % attr(f, "rigid_loss_fraction", 0.0)
        if len(x) == 0:
            print("%s: %s has no rows yet" % (PROG, path), file=sys.stderr)
        ok = st == 0
        ax.plot(x[ok], y[ok], "-", color=c, marker="o", markersize=2.5, linewidth=1.4, label=label)
        if acor_mode and column == "acor_corrected" and not args.no_raw:
            raw = r["acor"][()][order]
            if not np.array_equal(raw[ok], y[ok]):
                ax.plot(x[ok], raw[ok], ":", color=c, linewidth=1.2)
                any_raw = True
        if acor_mode and not args.no_rigid and rigid is not None:
            ax.plot(x[ok], rigid[ok], "--", color=c, linewidth=1.0, alpha=0.8)
            any_rigid = True
        multi = ok & (r["contacts"][()][order] >= 2) if "contacts" in r else np.zeros_like(ok)
        if np.any(multi):  # the ball struck more than once: a different physics, marked
            ax.plot(x[multi], y[multi], "o", color=c, markersize=6, markerfacecolor="none", markeredgewidth=1.0)
            any_multi = True
        mark_failed(ax, x[~ok], st[~ok], c)
        any_failed |= bool(np.any(~ok))
        curve = "not an ACOR plot" if not acor_mode else "left out (--no-rigid)" if args.no_rigid else \
            "not drawn (the beam is held or pivoted)" if held(f) else "drawn" if rigid is not None else "not in the file"
        print("%s: %s: %d point(s), %d with two or more contacts (ringed), %d failed (x); rigid-body Eq. (11) curve: %s"
              % (PROG, path, len(x), int(np.sum(multi)), int(np.sum(~ok)), curve))
    ax.set_xlabel(xlabel)
    ax.set_ylabel("ACOR" if acor_mode else axis_label(files[0][1]["results"], column))
    ax.set_title(args.title or ("Apparent coefficient of restitution" if acor_mode else column))
    ax.grid(True, alpha=0.3)
    files_legend = ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize=8, frameon=False)
    ax.add_artist(files_legend)
    styles = []
    if acor_mode:
        styles.append(Line2D([], [], color="k", linestyle="-", marker="o", markersize=2.5, label="ACOR corrected (x loss factor)" if column == "acor_corrected" else "ACOR"))
        if any_raw:
            styles.append(Line2D([], [], color="k", linestyle=":", label="ACOR raw"))
        if any_rigid:
            styles.append(Line2D([], [], color="k", linestyle="--", label="rigid body, Eq. (11)"))
        if any_held:
            styles.append(Line2D([], [], color="none", label="(no Eq. (11) curve: the beam is held)"))
    if any_multi:
        styles.append(Line2D([], [], color="k", linestyle="", marker="o", markersize=6, markerfacecolor="none", label="two or more contacts"))
    if any_failed:
        styles.append(Line2D([], [], color="k", linestyle="", marker="x", label="failed point (its status code)"))
    if styles:
        ax.legend(handles=styles, loc="upper right", fontsize=8)
    fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight", bbox_extra_artists=[files_legend])


def grid_of(f, names, column):
    """The planned values of both axes and COLUMN, status on the grid (NaN / -1 where not done)."""
    r = f["results"]
    v0, v1 = (f["sweep"][n][()] if "sweep" in f and n in f["sweep"] else r[n][()] for n in names)
    u0, u1 = np.unique(v0), np.unique(v1)
    z = np.full((len(u0), len(u1)), np.nan)
    s = np.full((len(u0), len(u1)), -1, dtype=int)
    i = np.searchsorted(u0, r[names[0]][()])
    j = np.searchsorted(u1, r[names[1]][()])
    z[i, j] = r[column][()]
    s[i, j] = status_of(r, len(i))
    return u0, u1, z, s


def plot_curves(args, path, f, column, names, vary):
    """One curve of COLUMN against names[vary] per value of the other axis."""
    r = f["results"]
    other = names[1 - vary]
    u0, u1, z, s = grid_of(f, names, column)
    xs, cs = (u0, u1) if vary == 0 else (u1, u0)
    if vary == 0:  # rows of z, s: one per value of the other axis
        z, s = z.T, s.T
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    unit = unit_of(r, other)
    any_failed = False
    for k, cv in enumerate(cs):
        c = colours[k % len(colours)]
        ok = s[k] == 0
        ax.plot(xs[ok], z[k][ok], "-o", color=c, markersize=2.5, linewidth=1.4, label="%s = %g%s" % (other, cv, " " + unit if unit else ""))
        bad = s[k] > 0
        mark_failed(ax, xs[bad], s[k][bad], c)
        any_failed |= bool(np.any(bad))
    if geometric(xs):
        ax.set_xscale("log")
    ax.set_xlabel(axis_label(r, names[vary]))
    ax.set_ylabel(axis_label(r, column))
    ax.set_title(args.title or "%s: %s" % (column, label_of(f, path)), fontsize=10)
    ax.grid(True, alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    if any_failed:
        handles.append(Line2D([], [], color="k", linestyle="", marker="x", label="failed point (its status code)"))
    ax.legend(handles=handles, fontsize=8)
    fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight")


def plot_map(args, path, f, column, names):
    """COLUMN over the two axes: colours, contour lines, failed points with their code."""
    r = f["results"]
    u0, u1, z, s = grid_of(f, names, column)
    X, Y = np.meshgrid(u0, u1, indexing="ij")
    fig, ax = plt.subplots(figsize=(8, 5.5))
    finite = np.isfinite(z)
    if finite.any():
        m = ax.pcolormesh(X, Y, np.ma.masked_invalid(z), shading="nearest", cmap="viridis")
        fig.colorbar(m, ax=ax, label=axis_label(r, column))
        if len(u0) > 1 and len(u1) > 1 and finite.sum() >= 4 and np.nanmax(z) > np.nanmin(z):
            cs = ax.contour(X, Y, np.ma.masked_invalid(z), levels=8, colors="k", linewidths=0.7)
            ax.clabel(cs, fontsize=7, fmt="%.3g")
    for i, j in zip(*np.nonzero(s > 0)):
        ax.plot(u0[i], u1[j], "x", color="r", markersize=7)
        ax.annotate(str(s[i, j]), (u0[i], u1[j]), textcoords="offset points", xytext=(4, 3), fontsize=7, color="r")
    if (s > 0).any():
        ax.legend(handles=[Line2D([], [], color="r", linestyle="", marker="x", label="failed point (its status code)")], fontsize=8, loc="upper right")
    for v, setter in ((u0, ax.set_xscale), (u1, ax.set_yscale)):
        if geometric(v):
            setter("log")
    ax.set_xlabel(axis_label(r, names[0]))
    ax.set_ylabel(axis_label(r, names[1]))
    ax.set_title(args.title or "%s: %s" % (column, label_of(f, path)), fontsize=10)
    fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight")


def main():
    p = argparse.ArgumentParser(description="Plot a column of beamimpact -task sweep files against their axes: curves (one axis, or one curve per value of the other axis) or a 2-D map with contours; failed points marked with their status code.")
    p.add_argument("inputs", nargs="+", metavar="FILE.h5 [COLUMN]", help="sweep output files, then optionally the /results column to draw (default: acor_corrected)")
    p.add_argument("-o", "--output", default=None, help="PNG to write (default: acor.png for the ACOR along one axis, else sweep.png)")
    p.add_argument("--map", action="store_true", help="two axes: draw a 2-D map with contours (the default when both axes have more than %d values)" % MAX_CURVES)
    p.add_argument("--curves", action="store_true", help="two axes: draw one curve per value of the axis with fewer values")
    p.add_argument("--label", action="append", default=[], help="one axis: legend label for each file, in order (default: from the file's attributes)")
    p.add_argument("--title", default=None, help="figure title")
    p.add_argument("--no-raw", action="store_true", help="ACOR: omit the raw (uncorrected) ACOR")
    p.add_argument("--no-rigid", action="store_true", help="ACOR: omit the rigid-body curves")
    p.add_argument("--dpi", type=int, default=150)
    args = p.parse_args()
    paths, column = list(args.inputs), "acor_corrected"
    if len(paths) > 1 and not paths[-1].endswith(".h5") and not os.path.exists(paths[-1]):
        column = paths.pop()
    if args.label and len(args.label) != len(paths):
        p.error("give one --label per file (%d files, %d labels)" % (len(paths), len(args.label)))
    if args.map and args.curves:
        p.error("give --map or --curves, not both")
    files = [(path, load(path)) for path in paths]
    for path, f in files:
        if column not in f["results"]:
            sys.exit("%s: %s has no /results/%s; its columns: %s" % (PROG, path, column, ", ".join(sorted(f["results"]))))
    naxes = {len(axes_of(f)) for _, f in files}
    if naxes == {1}:
        args.output = args.output or ("acor.png" if column in ("acor", "acor_corrected") else "sweep.png")
        plot_one_axis(args, files, column)
    elif naxes == {2} and len(files) == 1:
        args.output = args.output or "sweep.png"
        path, f = files[0]
        names = axes_of(f)
        counts = [len(np.unique(f["sweep"][n][()] if "sweep" in f and n in f["sweep"] else f["results"][n][()])) for n in names]
        if args.map or (not args.curves and min(counts) > MAX_CURVES):
            plot_map(args, path, f, column, names)
        else:
            few = 1 if counts[1] <= counts[0] else 0  # the axis giving the curves
            if counts[few] > 2 * MAX_CURVES:
                sys.exit("%s: --curves would draw %d curves (%s has %d values): use --map" % (PROG, counts[few], names[few], counts[few]))
            plot_curves(args, path, f, column, names, 1 - few)
    else:
        sys.exit("%s: draws one file with two axes or files with one axis each; got %s" % (PROG, ", ".join("%s: %d axes (%s)" % (pa, len(axes_of(f)), ",".join(axes_of(f))) for pa, f in files)))
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
