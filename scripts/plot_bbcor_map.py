#!/usr/bin/env python3
"""The BBCOR map of a hollow bat over its barrel wall's thickness and hoop frequency, as a PNG.

    /usr/bin/python3 scripts/plot_bbcor_map.py FILE.h5 [-o out.png]

FILE.h5 is a -task sweep of the certification rig with the barrel wall as a shell over
barrel_wall_thickness and a second axis that moves the hoop frequency (shell_youngs_modulus in
options/scenes/bbcor-map.opts), with or without impact_x: at each (thickness, second axis) the
largest BBCOR over the impact points is kept, as the rig keeps the barrel's best. The map is drawn
over (wall thickness, hoop_frequency, the wall's lowest n = 2 frequency of each point): filled
contours of BBCOR on the scattered points (a Delaunay triangulation), the points themselves, the
best marked with a star. Printed: the best point, and for each thickness the best BBCOR with its
hoop frequency and contact time (and their product, f_hoop x contact time). Failed points (status
!= 0) are left out.
"""
import argparse
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_bbcor_map.py"
NEEDED = ("bbcor", "hoop_frequency", "contact_time", "barrel_wall_thickness")


def best_over_x(r, ok, keys):
    """The row of the largest BBCOR for each distinct value of the keys (the impact point folded)."""
    best = {}
    b = r["bbcor"][()]
    for k in range(len(b)):
        if not ok[k] or not np.isfinite(b[k]):
            continue
        key = tuple(float(r[c][k]) for c in keys)
        if key not in best or b[k] > b[best[key]]:
            best[key] = k
    return sorted(best.values())


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--output", default=None, help="PNG to write (default: FILE without .h5, -map.png)")
    args = ap.parse_args()
    f = files.open_file(PROG, args.file)
    r = f["results"] if "results" in f else sys.exit("%s: %s has no /results" % (PROG, args.file))
    names = [a.name for a in files.sweep_axes(f)]
    if "barrel_wall_thickness" not in names:
        sys.exit("%s: %s is not a sweep over barrel_wall_thickness (its axes: %s)" % (PROG, args.file, ", ".join(names)))
    for c in NEEDED:
        if c not in r:
            sys.exit("%s: %s has no /results/%s (a pivoted bat with -beam_shell?)" % (PROG, args.file, c))
    keys = [a for a in names if a != "impact_x"]
    n = r["bbcor"].shape[0]
    ok = files.status(r, n) == 0
    rows = best_over_x(r, ok, keys)
    if len(rows) < 3:
        sys.exit("%s: %s has %d usable points (at least 3 are needed for a map)" % (PROG, args.file, len(rows)))
    t = r["barrel_wall_thickness"][()][rows] * 1e3
    fh = r["hoop_frequency"][()][rows]
    b = r["bbcor"][()][rows]
    tc = r["contact_time"][()][rows]
    x = r["impact_x"][()][rows] if "impact_x" in r else np.full(len(rows), np.nan)
    if not np.all(np.isfinite(fh)):
        sys.exit("%s: %s has no hoop frequency at some points (run with -beam_shell or -barrel_hoop_frequency)" % (PROG, args.file))
    i = int(np.argmax(b))
    other = [c for c in keys if c != "barrel_wall_thickness"]
    where = ", ".join("%s %.4g %s" % (c, r[c][rows[i]], labels.unit_text(files.unit(r[c]))) for c in other)
    print("best BBCOR %.4f at wall %.2f mm%s, impact_x %.3f m: hoop frequency %.0f Hz, contact time %.3f ms, f_hoop x contact time %.2f"
          % (b[i], t[i], (", " + where) if where else "", x[i], fh[i], tc[i] * 1e3, fh[i] * tc[i]))
    for tt in np.unique(t):
        k = np.where(t == tt)[0]
        j = k[np.argmax(b[k])]
        print("  wall %.2f mm: hoop frequency %.0f-%.0f Hz, BBCOR %.4f-%.4f; best %.4f at %.0f Hz (contact %.3f ms, f x t %.2f)"
              % (tt, fh[k].min(), fh[k].max(), b[k].min(), b[k].max(), b[j], fh[j], tc[j] * 1e3, fh[j] * tc[j]))
    fig, ax = plt.subplots(figsize=(8, 6))
    m = ax.tricontourf(t, fh, b, levels=14, cmap="viridis")
    cs = ax.tricontour(t, fh, b, levels=7, colors="k", linewidths=0.6)
    ax.clabel(cs, fontsize=7, fmt="%.3f")
    ax.plot(t, fh, "k.", markersize=4)
    ax.plot(t[i], fh[i], "*", color="r", markersize=16, markeredgecolor="w")
    fig.colorbar(m, ax=ax, label="BBCOR (the largest over the impact points)")
    ax.set_xlabel("barrel wall thickness (mm)")
    ax.set_ylabel(labels.axis_label(r, "hoop_frequency"))
    ax.set_title("%s; star: BBCOR %.3f at %.2f mm, %.0f Hz (1/contact time %.0f Hz)" % (args.file, b[i], t[i], fh[i], 1 / tc[i]), fontsize=9)
    out = args.output or files.default_prefix(args.file) + "-map.png"
    print("wrote %s" % style.save(fig, out))


if __name__ == "__main__":
    main()
