#!/usr/bin/env python3
"""A bat (or any beam) with its mode shapes, from a beamimpact -task modes file.

    scripts/plot_bat.py r161-modes.h5 -o r161-modes.png [--modes 3]
    scripts/plot_bat.py r161-modes.h5 --sweep r161-swing.h5 --pivot 0.152 -o r161-sweet-spots.png

Top: the section along the beam -- the outline +-D/2 of a round profile (and the bore d of a
hollow one), else the mass per length mu(x) -- with the centre of mass marked. Bottom: the
deflection shapes of the first flexible modes (each scaled to unit peak) with their
frequencies, and the nodes of the first two (where a tap excites nothing: /modes/nodes_1,
nodes_2). The title gives the theory, the mass and the moments of inertia the file records.

With --sweep (a -task sweep file of the same bat, e.g. a swinging bat; a sweep of another beam --
another profile's contents, length, mass, centre of mass or inertia -- is refused) a third panel draws the
batted-ball speed (or --column) against the impact point, the peak force on the hands when the
sweep had them (-grip; right axis), and marks the three sweet spots: the
maximum of the curve (refined by a parabola through the best three points), the barrel node of
the fundamental (the largest of nodes_1), and the centre of percussion about the pivot or the
hands x_p (--pivot, m from x = 0): x_cop = x_p + I_p / (M (x_cm - x_p)), I_p = I_cm + M (x_cm - x_p)^2,
from the mass, centre of mass and inertia the modes file records. They are printed too.
"""
import argparse
import os
import sys

from beamimpact import checks, files, style

import numpy as np

plt = style.plt


def sweet_spots(ax, a, info, nodes_1):
    with files.open_file("plot_bat.py", a.sweep) as f:
        r = f["results"]
        if a.column not in r:
            sys.exit("plot_bat.py: %s has no /results/%s" % (a.sweep, a.column))
        x, y = r["x"][:], r[a.column][:]
        ok = r["status"][:] == 0 if "status" in r else np.isfinite(y)
    x, y = x[ok], y[ok]
    order = np.argsort(x)
    x, y = x[order], y[order]
    k = int(np.argmax(y))
    x_max = x[k]
    if 0 < k < len(x) - 1:  # the parabola's vertex through the best three points
        c = np.polyfit(x[k - 1:k + 2], y[k - 1:k + 2], 2)
        if c[0] < 0:
            x_max = -c[1] / (2 * c[0])
    M, xcm, Icm, xp = info["mass"], info["xcm"], info["icm"], a.pivot
    Ip = Icm + M * (xcm - xp) ** 2
    x_cop = xp + Ip / (M * (xcm - xp))
    x_node = max(nodes_1) if len(nodes_1) else float("nan")
    ax.plot(x, y, "k.-", lw=1, ms=3, label=a.column)
    for xs, name, col in ((x_max, "maximum %s" % a.column, "C3"), (x_node, "node of the fundamental", "C0"), (x_cop, "centre of percussion (x_p = %.3f m)" % xp, "C2")):
        ax.axvline(xs, color=col, ls="--", lw=1, label="%s: %.3f m" % (name, xs))
        print("sweet spot: %s at %.4f m" % (name, xs))
    ax.set_ylabel(a.column + (" (m/s)" if a.column == "bbs" else ""))
    ax.legend(fontsize=8, loc="lower left")
    with files.open_file("plot_bat.py", a.sweep) as f:  # the hands, when the sweep had them
        hands = f["results/grip_force_peak"][:][ok][order] if "grip_force_peak" in f["results"] else None
    if hands is not None and np.any(hands > 0):
        ax2 = ax.twinx()
        ax2.plot(x, hands, color="0.5", lw=1, ls=":", label="peak force on the hands")
        ax2.set_ylabel("peak force on the hands (N)", color="0.4")
        ax2.legend(fontsize=8, loc="lower right")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("file", help="HDF5 file written by -task modes")
    ap.add_argument("-o", "--output", help="PNG to write (default: FILE with .png)")
    ap.add_argument("--modes", type=checks.count(1, "flexible modes to draw"), default=3, help="flexible modes to draw (default 3)")
    ap.add_argument("--sweep", help="a -task sweep file of the same bat: its curve and the sweet spots")
    ap.add_argument("--column", default="bbs", help="the sweep column to draw (default bbs; acor for a bat at rest)")
    ap.add_argument("--pivot", type=float, default=0.152, help="pivot or hands position x_p (m) for the centre of percussion (default 0.152)")
    a = ap.parse_args()
    out = a.output or os.path.splitext(a.file)[0] + ".png"
    with files.open_file("plot_bat.py", a.file) as f:
        if "modes" not in f or "shapes" not in f["modes"] or "beam" not in f:
            sys.exit("plot_bat.py: %s has no /modes/shapes or /beam: write it with -task modes" % a.file)
        x = f["beam/x"][:]
        freq = f["modes/frequency"][:]
        shapes = f["modes/shapes"][:]
        nodes = [f["modes/" + n][:] if n in f["modes"] else np.array([]) for n in ("nodes_1", "nodes_2")]
        prof = {k: f["beam/profile_" + k][:] for k in ("x", "D", "d")} if "profile_x" in f["beam"] else None
        mu = f["beam/mu"][:]
        info = dict(theory=files.attr(f, "beam_theory", "euler"), mass=files.attr(f, "beam_mass", 0.0), xcm=files.attr(f, "beam_center_of_mass", 0.0),
                    icm=files.attr(f, "beam_inertia_cm", 0.0), iend=files.attr(f, "beam_inertia_end", 0.0), src=files.attr(f, "beam_section_file", ""))
    flex = [k for k in range(len(freq)) if freq[k] > 0][: a.modes]
    if a.sweep:  # its curve and sweet spots belong over this bat only
        with files.open_file("plot_bat.py", a.file) as f, files.open_file("plot_bat.py", a.sweep) as g:
            if files.attr(g, "task") != "sweep" or "results" not in g:
                sys.exit("plot_bat.py: %s is not a -task sweep file (it holds -task %s)" % (a.sweep, files.attr(g, "task", "?")))
            why = checks.other_beam(f, g)
        if why:
            sys.exit("plot_bat.py: %s is a sweep of another beam than %s: %s; its curve and sweet spots would be drawn over the "
                     "wrong bat: give --sweep a sweep of this bat" % (a.sweep, a.file, "; ".join(why)))

    panels = 3 if a.sweep else 2
    fig, axes = plt.subplots(panels, 1, figsize=(9, 3 * panels), sharex=True, gridspec_kw=dict(height_ratios=[1, 2, 2][:panels]))
    ax0, ax1 = axes[0], axes[1]
    if prof is not None:
        ax0.fill_between(prof["x"], -prof["D"] / 2, prof["D"] / 2, color="0.75", lw=0)
        if np.any(prof["d"] > 0):
            ax0.fill_between(prof["x"], -prof["d"] / 2, prof["d"] / 2, color="white", lw=0)
        ax0.plot(prof["x"], prof["D"] / 2, "k", lw=0.8)
        ax0.plot(prof["x"], -prof["D"] / 2, "k", lw=0.8)
        ax0.set_ylabel("radius (m)")
        ax0.set_aspect("auto")
    else:
        ax0.plot(x, mu, "k")
        ax0.set_ylabel("mu (kg/m)")
    ax0.axvline(info["xcm"], color="C3", ls="--", lw=1)
    ax0.text(info["xcm"], ax0.get_ylim()[1], " centre of mass %.3f m" % info["xcm"], color="C3", va="top", fontsize=8)
    for i, k in enumerate(flex):
        w = shapes[k] / np.max(np.abs(shapes[k]))
        ax1.plot(x, w, color="C%d" % i, label="mode %d: %.1f Hz" % (i + 1, freq[k]))
        if i < 2:
            ax1.plot(nodes[i], np.zeros_like(nodes[i]), "o", color="C%d" % i, ms=6, mfc="white")
            for xn in nodes[i]:
                ax1.annotate("%.3f" % xn, (xn, 0), textcoords="offset points", xytext=(0, 8 + 10 * i), ha="center", fontsize=7, color="C%d" % i)
    ax1.axhline(0, color="0.5", lw=0.5)
    ax1.set_xlabel("x (m) from the x = 0 end")
    if a.sweep:
        sweet_spots(axes[2], a, info, nodes[0])
        axes[2].set_xlabel("x (m) from the x = 0 end")
    ax1.set_ylabel("deflection (scaled)")
    ax1.legend(fontsize=8, loc="lower left")
    fig.suptitle("%s (%s): %.3f kg, I_cm %.4f kg m^2, I_0 %.4f kg m^2; open circles: nodes"
                 % (os.path.basename(info["src"]) or "beam", info["theory"], info["mass"], info["icm"], info["iend"]), fontsize=9)
    style.save(fig, out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
