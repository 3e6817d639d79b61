#!/usr/bin/env python3
"""Plots of beamimpact -task sweep files (and -task impact files), as a PNG.

    scripts/plot_sweep.py FILE.h5 [FILE2.h5 ...] [COLUMN] [-o out.png] [--map | --curves] [--logy]

COLUMN is any numeric /results column (default: acor_corrected; bbs, the batted-ball speed, for a
swinging bat, whose acor is not the ACOR of a bat at rest: asked for explicitly it is refused). What is drawn follows the
file's axes (the attribute sweep_axes, in the order of the sweep):

* one axis: COLUMN against it, one curve per file. For the ACOR against the impact
  point (the paper's figures) each file gives one colour: acor_corrected solid with
  markers, the raw acor dotted (omitted when equal: hysteretic ball) and the rigid-body
  ACOR of Eq. (11) dashed; legends come from the files' attributes (length, supports,
  thickness, ball law, f).
* two axes (one file): one curve per value of the axis with at most 6 values, against
  the other; or, when both have more (or with --map), a 2-D map of COLUMN with contour
  lines over the two axes.
* text (categorical) axes (one file; -sweep "ts_type=rk;cn,impact_x=0.4:0.9:6"): one curve
  of COLUMN against the numeric axis per value of the text axis (per combination of values
  with two text axes), the legend naming the values in the sweep's order; with two numeric
  axes one map per value; with no numeric axis the values of the text axis with the most
  values are the horizontal axis. --logy: a log scale for COLUMN (wall_time per integrator); --relative-to
  VALUE: COLUMN minus its value at the same point for that value of the text axis (each
  integrator's ACOR against -ts_type modal's).

Failed points (status != 0) are marked with their status code: an 'x' at the foot of the
curve's axes, or the code written on the map (the codes are listed in docs/sweep.md).
The file may be one still being written (its rows so far are drawn).
"""
import argparse
import itertools
import os
import sys

from beamimpact import checks, files, labels, style

import numpy as np
from matplotlib.lines import Line2D

plt = style.plt

PROG = "plot_sweep.py"
MAX_CURVES = 6


def held(f, values=None):
    """Whether the beam is held (a support other than free, a clamped region, a pivot); values:
    {option: value} of text axes at this curve (beam_left = clamped), which win over the file's
    attributes (those of the sweep's first point)."""
    values = values or {}
    left, right = values.get("beam_left", files.attr(f, "beam_left")), values.get("beam_right", files.attr(f, "beam_right"))
    x0 = files.attr(f, "beam_clamp_x0", -1)
    opts = files.attr(f, "options", "") or ""
    return (left not in (None, "free")) or (right not in (None, "free")) or (x0 is not None and x0 >= 0) or "-beam_pivot" in opts


def geometric(v):
    v = np.unique(v)
    return len(v) > 2 and np.all(v > 0) and np.allclose(np.diff(np.log(v)), np.log(v[1] / v[0]), rtol=1e-6)


def load(path):
    f = files.open_file(PROG, path)
    if "results" not in f:
        sys.exit("%s: %s has no /results (is it a beamimpact sweep or impact file?)" % (PROG, path))
    return f


def mark_failed(ax, xs, codes, colour="k"):
    """An 'x' at the foot of the axes at each failed point, with its status code."""
    if len(xs) == 0:
        return
    trans = ax.get_xaxis_transform()
    ax.plot(xs, np.full(len(xs), 0.02), "x", color=colour, transform=trans, clip_on=False, markersize=6)
    for x, c in zip(xs, codes):
        ax.text(x, 0.05, str(c), transform=trans, ha="center", va="bottom", fontsize=7, color=colour)


def plot_one_axis(args, opened, column):
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = style.colours()
    acor_mode = column in ("acor", "acor_corrected")
    any_raw = any_rigid = any_failed = any_held = any_multi = False
    xlabel = None
    for k, (path, f) in enumerate(opened):
        r = f["results"]
        name = files.sweep_axes(f)[0].name
        xlabel = xlabel or labels.axis_label(r, name)
        x = r[name][()]
        order = np.argsort(x, kind="stable")
        x = x[order]
        y = r[column][()][order]
        st = files.status(r, len(order))[order]
        c = colours[k % len(colours)]
        label = args.label[k] if args.label else labels.sweep_label(f, path)
        rigid = r["rigid_acor"][()][order] if acor_mode and "rigid_acor" in r else None
        if rigid is not None and held(f):
            rigid = None  # Eq. (11) is the free rigid body: no curve for a held or pivoted beam
            any_held = True
        if acor_mode and not args.no_rigid and rigid is not None:
            label += "; rigid f = %g" % files.attr(f, "rigid_loss_fraction", 0.0)
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
    ax.set_ylabel("ACOR" if acor_mode else labels.axis_label(opened[0][1]["results"], column))
    ax.set_title(args.title or ("Apparent coefficient of restitution" if acor_mode else column))
    ax.grid(True, alpha=0.3)
    if args.logy:
        ax.set_yscale("log")
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
    style.save(fig, args.output, dpi=args.dpi, layout=False, tight_box=True, extra_artists=[files_legend])


def grid_of(f, axes, column, rows=None):
    """The planned values of two numeric axes and COLUMN, status on the grid (NaN / -1 where not
    done); rows: a mask of the /results rows to place (one value of the text axes)."""
    r = f["results"]
    u0, u1 = axes[0].values, axes[1].values
    z = np.full((len(u0), len(u1)), np.nan)
    s = np.full((len(u0), len(u1)), -1, dtype=int)
    rows = np.ones(len(r[column]), dtype=bool) if rows is None else rows
    i = np.searchsorted(u0, r[axes[0].name][()][rows])
    j = np.searchsorted(u1, r[axes[1].name][()][rows])
    z[i, j] = r[column][()][rows]
    s[i, j] = files.status(r, len(rows))[rows]
    return u0, u1, z, s


def plot_curves(args, path, f, column, axes, vary):
    """One curve of COLUMN against axes[vary] per value of the other axis."""
    r = f["results"]
    other = axes[1 - vary]
    u0, u1, z, s = grid_of(f, axes, column)
    xs, cs = (u0, u1) if vary == 0 else (u1, u0)
    if vary == 0:  # rows of z, s: one per value of the other axis
        z, s = z.T, s.T
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = style.colours()
    any_failed = False
    for k, cv in enumerate(cs):
        c = colours[k % len(colours)]
        ok = s[k] == 0
        ax.plot(xs[ok], z[k][ok], "-o", color=c, markersize=2.5, linewidth=1.4, label=labels.value_label(other.name, cv, other.unit))
        bad = s[k] > 0
        mark_failed(ax, xs[bad], s[k][bad], c)
        any_failed |= bool(np.any(bad))
    if geometric(xs):
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(labels.axis_label(r, axes[vary].name))
    ax.set_ylabel(labels.axis_label(r, column))
    ax.set_title(args.title or "%s: %s" % (column, labels.sweep_label(f, path)), fontsize=10)
    ax.grid(True, alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    if any_failed:
        handles.append(Line2D([], [], color="k", linestyle="", marker="x", label="failed point (its status code)"))
    ax.legend(handles=handles, fontsize=8)
    style.save(fig, args.output, dpi=args.dpi, layout=False, tight_box=True)


def draw_map(fig, ax, f, column, axes, rows=None):
    """COLUMN over two numeric axes on ax: colours, contour lines, failed points with their code."""
    r = f["results"]
    u0, u1, z, s = grid_of(f, axes, column, rows)
    X, Y = np.meshgrid(u0, u1, indexing="ij")
    finite = np.isfinite(z)
    if finite.any():
        m = ax.pcolormesh(X, Y, np.ma.masked_invalid(z), shading="nearest", cmap="viridis")
        fig.colorbar(m, ax=ax, label=labels.axis_label(r, column))
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
    ax.set_xlabel(labels.axis_label(r, axes[0].name))
    ax.set_ylabel(labels.axis_label(r, axes[1].name))


def plot_map(args, path, f, column, axes):
    """COLUMN over the two axes: colours, contour lines, failed points with their code."""
    fig, ax = plt.subplots(figsize=(8, 5.5))
    draw_map(fig, ax, f, column, axes)
    ax.set_title(args.title or "%s: %s" % (column, labels.sweep_label(f, path)), fontsize=10)
    style.save(fig, args.output, dpi=args.dpi, layout=False, tight_box=True)


def text_rows(r, text_axes, combo):
    """The /results rows whose text axes have the values combo."""
    rows = np.ones(len(r["case_index"]) if "case_index" in r else len(r[text_axes[0].name]), dtype=bool)
    for a, v in zip(text_axes, combo):
        rows &= np.array(files.text(r, a.name), dtype=object) == v
    return rows


def combo_label(text_axes, combo):
    """The legend entry of one combination of text values: 'cn', or 'ts_type = cn, beam_theory = euler'."""
    if len(text_axes) == 1:
        return combo[0]
    return ", ".join(labels.value_label(a.name, v) for a, v in zip(text_axes, combo))


def plot_text_maps(args, path, f, column, numeric, text_axes):
    """Two numeric axes and text axes: one map of COLUMN per combination of the text values."""
    combos = list(itertools.product(*[a.values for a in text_axes]))
    fig, axs = plt.subplots(1, len(combos), figsize=(6.5 * len(combos), 5.2), squeeze=False)
    r = f["results"]
    for ax, combo in zip(axs[0], combos):
        rows = text_rows(r, text_axes, combo)
        draw_map(fig, ax, f, column, numeric, rows)
        ax.set_title(", ".join(labels.value_label(a.name, v) for a, v in zip(text_axes, combo)), fontsize=10)
        print("%s: %s: %s: %d point(s), %d failed (x)" % (PROG, path, combo_label(text_axes, combo), int(rows.sum()),
                                                           int(np.sum(files.status(r, len(rows))[rows] != 0))))
    fig.suptitle(args.title or "%s: %s" % (column, labels.sweep_label(f, path)), fontsize=10)
    style.save(fig, args.output, dpi=args.dpi, layout=True, tight_box=True)


def plot_text_curves(args, path, f, column, numeric, text_axes):
    """One curve of COLUMN per value of the text axis (per combination of values), against the
    numeric axis, or against the values of the text axis with the most values when there is none."""
    r = f["results"]
    acor_mode = column in ("acor", "acor_corrected")
    # per row: whether the text axes' values there hold the beam (beam_left = clamped: no Eq. (11))
    row_values = zip(*[files.text(r, a.name) for a in text_axes])
    held_all = np.array([held(f, {a.name: v for a, v in zip(text_axes, vals)}) for vals in row_values], dtype=bool)
    if numeric:
        x_all, xlabel, ticks = files.numbers(r, numeric[0].name), labels.axis_label(r, numeric[0].name), None
    else:  # the values of the text axis with the most along the horizontal axis, in the sweep's order
        first = max(text_axes, key=lambda a: len(a.values))
        text_axes = [a for a in text_axes if a is not first]
        position = {v: k for k, v in enumerate(first.values)}
        x_all = np.array([position.get(v, np.nan) for v in files.text(r, first.name)], dtype=float)
        xlabel, ticks = first.name, first.values
    y_all, st_all = files.numbers(r, column), files.status(r, len(r[column]))
    multi_all = files.counts(r, "contacts", 0) >= 2 if "contacts" in r else np.zeros(len(y_all), dtype=bool)
    rigid_all = files.numbers(r, "rigid_acor") if acor_mode and "rigid_acor" in r and not args.no_rigid and not args.relative_to else None
    ylabel = "ACOR" if acor_mode else labels.axis_label(r, column)
    if args.relative_to:  # COLUMN minus its value at the same point with the text value given (check_relative_to)
        ref = text_rows(r, text_axes, (args.relative_to,)) & (st_all == 0)
        at = dict(zip(x_all[ref], y_all[ref]))
        y_all = y_all - np.array([at.get(x, np.nan) for x in x_all])
        ylabel = "%s - %s(%s = %s)" % (column, column, text_axes[0].name, args.relative_to)
        if args.logy:
            y_all, ylabel = np.abs(y_all), "|%s|" % ylabel
    fig, ax = plt.subplots(figsize=(8, 5))
    colours = style.colours()
    any_failed = any_multi = any_rigid = False
    rigid_drawn = []  # the Eq. (11) curves drawn (one per distinct curve: it does not depend on the integrator)
    for k, combo in enumerate(itertools.product(*[a.values for a in text_axes])):
        rows = text_rows(r, text_axes, combo) if text_axes else np.ones(len(y_all), dtype=bool)
        order = np.argsort(x_all[rows], kind="stable")
        x, y, st, multi = x_all[rows][order], y_all[rows][order], st_all[rows][order], multi_all[rows][order]
        ok = st == 0
        c = colours[k % len(colours)]
        name = combo_label(text_axes, combo) if text_axes else labels.sweep_label(f, path)
        if args.relative_to and args.logy and combo == (args.relative_to,):
            print("%s: %s: %s: the reference (--relative-to), 0 on a log scale: not drawn" % (PROG, path, name))
            continue
        ax.plot(x[ok], y[ok], "-", color=c, marker="o", markersize=3, linewidth=1.4, label=name)
        rigid = np.where(held_all[rows][order], np.nan, rigid_all[rows][order])[ok] if rigid_all is not None else None
        if rigid is not None and np.isfinite(rigid).any() \
                and not any(np.array_equal(x[ok], u) and np.array_equal(rigid, v, equal_nan=True) for u, v in rigid_drawn):
            ax.plot(x[ok], rigid, "--", color=c, linewidth=1.0, alpha=0.8)
            rigid_drawn.append((x[ok], rigid))
            any_rigid = True
        if np.any(multi & ok):  # the ball struck more than once: ringed
            ax.plot(x[multi & ok], y[multi & ok], "o", color=c, markersize=7, markerfacecolor="none", markeredgewidth=1.0)
            any_multi = True
        mark_failed(ax, x[~ok], st[~ok], c)
        any_failed |= bool(np.any(~ok))
        print("%s: %s: %s: %d point(s), %d with two or more contacts (ringed), %d failed (x)"
              % (PROG, path, name, len(x), int(np.sum(multi & ok)), int(np.sum(~ok))))
    if ticks is not None:
        ax.set_xticks(range(len(ticks)))
        ax.set_xticklabels(ticks)
    elif geometric(x_all[np.isfinite(x_all)]):
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(args.title or "%s: %s" % (column, labels.sweep_label(f, path)), fontsize=10)
    ax.grid(True, alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    if any_rigid:
        handles.append(Line2D([], [], color="k", linestyle="--", label="rigid body, Eq. (11)"))
    if any_multi:
        handles.append(Line2D([], [], color="k", linestyle="", marker="o", markersize=7, markerfacecolor="none", label="two or more contacts"))
    if any_failed:
        handles.append(Line2D([], [], color="k", linestyle="", marker="x", label="failed point (its status code)"))
    ax.legend(handles=handles, fontsize=8, title=", ".join(a.name for a in text_axes) or None, title_fontsize=8)
    style.save(fig, args.output, dpi=args.dpi, layout=False, tight_box=True)


def check_relative_to(value, opened, axes):
    """--relative-to VALUE draws COLUMN minus its value at the same point for VALUE of a text axis:
    curves of one sweep with one text axis holding VALUE and one numeric axis. Anything else (more
    files, no such text axis or value, a map over two numeric axes, no numeric axis) exits naming
    the value and what the file has, before anything is drawn."""
    head = "%s: --relative-to %s is not allowed: " % (PROG, value)
    need = ("it draws COLUMN minus its value at %s of a text axis, as curves along one numeric axis "
            "(one sweep such as -sweep \"ts_type=rk;modal,impact_x=0.4:0.9:6\")" % value)
    if len(opened) != 1:
        sys.exit(head + need + "; it takes one file, not %d" % len(opened))
    path = opened[0][0]
    text = [a for a in axes[0] if a.text]
    numeric = [a for a in axes[0] if not a.text]
    if len(text) != 1:
        sys.exit(head + need + "; %s has %s" % (path, "text axes %s" % ", ".join(a.name for a in text) if text else "no text axis"))
    if value not in text[0].values:
        sys.exit(head + "the text axis %s of %s has the values %s" % (text[0].name, path, ", ".join(text[0].values)))
    if len(numeric) != 1:
        sys.exit(head + need + "; %s has %s" % (path, "%d numeric axes (%s): a map of each value, not curves" % (len(numeric), ", ".join(a.name for a in numeric))
                                              if numeric else "no numeric axis"))


def plot_text(args, path, f, column, axes):
    """A file with text (categorical) axes."""
    numeric = [a for a in axes if not a.text]
    text_axes = [a for a in axes if a.text]
    if len(numeric) > 2:
        sys.exit("%s: %s has %d numeric axes (%s) besides its text axes: draws at most two" % (PROG, path, len(numeric), ",".join(a.name for a in numeric)))
    if len(numeric) == 2:
        plot_text_maps(args, path, f, column, numeric, text_axes)
    else:
        plot_text_curves(args, path, f, column, numeric, text_axes)


def main():
    p = argparse.ArgumentParser(description="Plot a column of beamimpact -task sweep files against their axes: curves (one axis, one curve per value of the other axis, or one curve per value of a text axis such as ts_type) or a 2-D map with contours; failed points marked with their status code.")
    p.add_argument("inputs", nargs="+", metavar="FILE.h5 [COLUMN]", help="sweep output files, then optionally the /results column to draw (default: acor_corrected)")
    p.add_argument("-o", "--output", default=None, help="PNG to write (default: acor.png for the ACOR along one axis, else sweep.png)")
    p.add_argument("--map", action="store_true", help="two axes: draw a 2-D map with contours (the default when both axes have more than %d values)" % MAX_CURVES)
    p.add_argument("--curves", action="store_true", help="two axes: draw one curve per value of the axis with fewer values")
    p.add_argument("--label", action="append", default=[], help="one axis: legend label for each file, in order (default: from the file's attributes)")
    p.add_argument("--title", default=None, help="figure title")
    p.add_argument("--logy", action="store_true", help="a log scale for COLUMN (e.g. wall_time; with --relative-to: the absolute difference)")
    p.add_argument("--relative-to", metavar="VALUE", default=None, help="text axis: draw COLUMN minus its value at the same point with this value of the text axis (e.g. modal: each integrator's difference to -ts_type modal, whose beam flow is exact)")
    p.add_argument("--no-raw", action="store_true", help="ACOR: omit the raw (uncorrected) ACOR")
    p.add_argument("--no-rigid", action="store_true", help="ACOR: omit the rigid-body curves")
    p.add_argument("--dpi", type=checks.count(1, "dots per inch"), default=150)
    args = p.parse_args()
    paths, column, given = list(args.inputs), "acor_corrected", False
    if len(paths) > 1 and not paths[-1].endswith(".h5") and not os.path.exists(paths[-1]):
        column, given = paths.pop(), True
    if args.label and len(args.label) != len(paths):
        p.error("give one --label per file (%d files, %d labels)" % (len(paths), len(args.label)))
    if args.map and args.curves:
        p.error("give --map or --curves, not both")
    opened = [(path, load(path)) for path in paths]
    if args.output:
        style.check_image_output(args.output)  # not onto an input, an image: before any drawing
    swings = [path for path, f in opened if checks.swinging(f)]
    if swings and column in ("acor", "acor_corrected"):  # no ACOR of a bat at rest, no Eq. (11)
        if given:
            sys.exit("%s: %s: the bat swings (-bat_speed/-bat_angular_velocity): /results/%s is not the ACOR of a bat at rest "
                     "and Eq. (11) does not apply; draw bbs (the batted-ball speed) or collision_efficiency" % (PROG, ", ".join(swings), column))
        if len(swings) != len(opened):
            sys.exit("%s: %s swing(s) the bat and the others do not: draw them apart" % (PROG, ", ".join(swings)))
        column = "bbs"
        print("%s: the bat swings in %s: drawing bbs (the batted-ball speed), not the ACOR of a bat at rest" % (PROG, ", ".join(swings)))
    for path, f in opened:
        if column not in f["results"]:
            sys.exit("%s: %s has no /results/%s; its columns: %s" % (PROG, path, column, ", ".join(sorted(f["results"]))))
        if files.is_text(f["results"][column]):
            sys.exit("%s: %s: /results/%s is text, not numbers: draw a numeric column against it (acor, contact_time, wall_time, ...)" % (PROG, path, column))
    axes = [files.sweep_axes(f) for _, f in opened]
    naxes = {len(a) for a in axes}
    if args.relative_to is not None:
        check_relative_to(args.relative_to, opened, axes)
    if any(a.text for ax in axes for a in ax):
        if len(opened) != 1:
            sys.exit("%s: a sweep with text axes is drawn alone (one curve per value): give one file" % PROG)
        args.output = args.output or "sweep.png"
        plot_text(args, opened[0][0], opened[0][1], column, axes[0])
    elif naxes == {1}:
        args.output = args.output or ("acor.png" if column in ("acor", "acor_corrected") else "sweep.png")
        plot_one_axis(args, opened, column)
    elif naxes == {2} and len(opened) == 1:
        args.output = args.output or "sweep.png"
        path, f = opened[0]
        both = axes[0]
        counts = [len(a.values) for a in both]
        if args.map or (not args.curves and min(counts) > MAX_CURVES):
            plot_map(args, path, f, column, both)
        else:
            few = 1 if counts[1] <= counts[0] else 0  # the axis giving the curves
            if counts[few] > 2 * MAX_CURVES:
                sys.exit("%s: --curves would draw %d curves (%s has %d values): use --map" % (PROG, counts[few], both[few].name, counts[few]))
            plot_curves(args, path, f, column, both, 1 - few)
    else:
        sys.exit("%s: draws one file with two axes or files with one axis each; got %s" % (PROG, ", ".join("%s: %d axes (%s)" % (pa, len(ax), ",".join(a.name for a in ax)) for (pa, _), ax in zip(opened, axes))))
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
