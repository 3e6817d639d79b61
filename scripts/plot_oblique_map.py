#!/usr/bin/env python3
"""Maps of an oblique-impact sweep over the impact point and the undercut, as a PNG.

    /usr/bin/python3 scripts/plot_oblique_map.py FILE.h5 [-o out.png] [--best COLUMN]

FILE.h5 is a -task sweep over impact_x and impact_offset with -flight (options/scenes/
oblique-map.opts). Four maps over the two axes: exit_speed, launch_angle, spin_rpm and distance
(the batted ball's carry), with contour lines. On each, the best point (the largest --best
column, distance by default) is marked with a star, and the best undercut at each impact point
(the offset of the largest --best along each column of the map) is drawn as a white line. The
best point and the best undercut at each impact point are also printed. Failed points (status
!= 0) are left blank.
"""
import argparse
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_oblique_map.py"
PANELS = ("exit_speed", "launch_angle", "spin_rpm", "distance")


def grid(r, xs, ds, column, ok):
    """The column on the (offset, x) grid; NaN at failed or missing points."""
    z = np.full((len(ds), len(xs)), np.nan)
    x, d, v = r["impact_x"][()], r["impact_offset"][()], r[column][()]
    for k in range(len(v)):
        if ok[k]:
            z[np.searchsorted(ds, d[k]), np.searchsorted(xs, x[k])] = v[k]
    return z


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--output", default=None, help="PNG to write (default: FILE without .h5, -map.png)")
    ap.add_argument("--best", default="distance", help="the column whose largest value is marked (default distance)")
    args = ap.parse_args()
    f, r = files.open_map(PROG, args.file, ("impact_x", "impact_offset"))
    for c in PANELS + (args.best,):
        if c not in r:
            sys.exit("%s: %s has no /results/%s (was the sweep run with -flight?)" % (PROG, args.file, c))
    ok = files.status(r, r["impact_x"].shape[0]) == 0
    xs, ds = np.unique(r["impact_x"][()]), np.unique(r["impact_offset"][()])
    best = grid(r, xs, ds, args.best, ok)
    if np.all(np.isnan(best)):
        sys.exit("%s: no point of %s succeeded" % (PROG, args.file))
    i, j = np.unravel_index(np.nanargmax(best), best.shape)
    cols = [k for k in range(len(xs)) if not np.all(np.isnan(best[:, k]))]
    line = [ds[np.nanargmax(best[:, k])] for k in cols]
    print("best %s: %.4g %s at impact_x %.3f m, impact_offset %.4f m" % (args.best, best[i, j], labels.unit_text(files.unit(r[args.best])), xs[j], ds[i]))
    for k, dbest in zip(cols, line):
        print("  impact_x %.3f m: best impact_offset %.4f m (%s %.4g)" % (xs[k], dbest, args.best, np.nanmax(best[:, k])))
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    for ax, c in zip(axes.flat, PANELS):
        z = grid(r, xs, ds, c, ok)
        m = ax.pcolormesh(xs, ds * 100, z, shading="nearest", cmap="viridis")
        if np.sum(~np.isnan(z)) > 4 and len(xs) > 1 and len(ds) > 1:
            cs = ax.contour(xs, ds * 100, z, colors="k", linewidths=0.6, levels=8)
            ax.clabel(cs, fontsize=7, fmt="%.3g")
        ax.plot([xs[k] for k in cols], np.array(line) * 100, "w-", linewidth=1.4)
        ax.plot(xs[j], ds[i] * 100, "*", color="r", markersize=14, markeredgecolor="w")
        fig.colorbar(m, ax=ax, label=labels.axis_label(r, c))
        ax.set_title(c)
    for ax in axes[1]:
        ax.set_xlabel(labels.axis_label(r, "impact_x"))
    for ax in axes[:, 0]:
        ax.set_ylabel("undercut: impact_offset (cm)")
    fig.suptitle("%s; star: the largest %s (%.4g at x = %.2f m, D = %.1f cm); white: the best undercut at each point" % (args.file, args.best, best[i, j], xs[j], ds[i] * 100), fontsize=9)
    out = args.output or files.default_prefix(args.file) + "-map.png"
    print("wrote %s" % style.save(fig, out))


if __name__ == "__main__":
    main()
