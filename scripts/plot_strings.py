#!/usr/bin/env python3
"""The string bed's pictures: its mode shapes, or its deflection at snapshot times, on the head.

    scripts/plot_strings.py FILE.h5 -o out.png [--modes 6] [--snapshots 6]

FILE.h5 is one of
  * a -strings_frame held -task modes file: the bed's own modes (/modes/shape_k on /modes/x, z);
  * a -strings_frame beam -task modes file (a strung racket): the bed's share of each of the
    racket's modes (/modes/bed_shape_k on /modes/bed_x, bed_z), titled with the mode's part
    (bending, roll, strings) and its share of the mode's kinetic energy;
  * a -task impact file of a racket with -snapshot_times: the bed's deflection from its frame
    (w - y - z phi: the strings' own, the frame's motion taken out) at those times (/snapshots/bed
    on /snapshots/bed_x, bed_z), --snapshots of them evenly chosen, on one colour scale, the
    ball's disc marked.
One panel per mode or time (the first 6 modes unless --modes says otherwise): the deflection on
the head's grid (x along the frame's axis, z across the face, from the head's centre), coloured
from -max to +max (a mode: its own max; snapshots: the largest over the times drawn), with the
nodal lines (w = 0) of a mode and the outline (ellipse or rectangle, from the file's head_shape,
head_length and head_width). The figure's title gives the head, the tensions and the grid.
"""
import argparse
import os
import sys

from beamimpact import checks, files, style

import numpy as np

plt = style.plt
PROG = "plot_strings.py"
PARTS = {0: "bending", 1: "roll", 2: "wall", 3: "strings"}


def outline(ax, shape, length, width):
    a, b = 0.5 * length, 0.5 * width
    if shape == "rectangle":
        ax.plot([-a, a, a, -a, -a], [-b, -b, b, b, -b], "k-", lw=1)
    else:
        t = np.linspace(0, 2 * np.pi, 241)
        ax.plot(a * np.cos(t), b * np.sin(t), "k-", lw=1)


def read(f, a):
    """(kind, x, z, panels [(w, title)], shared colour scale or None, marker (x, z, r) or None)."""
    if "snapshots" in f and "bed" in f["snapshots"]:
        g = f["snapshots"]
        x, z, t, bed = files.numbers(g, "bed_x"), files.numbers(g, "bed_z"), files.numbers(g, "time"), g["bed"][()]
        pick = np.unique(np.round(np.linspace(0, len(t) - 1, min(a.snapshots, len(t)))).astype(int))
        panels = [(bed[k].reshape(len(z), len(x)), "t = %.3f ms" % (t[k] * 1e3)) for k in pick]
        scale = max(float(np.nanmax(np.abs(w))) for w, _ in panels) or 1.0
        xi, zi, r = files.attr(f, "impact_x"), files.attr(f, "impact_z", 0.0), files.attr(f, "strings_patch_radius", 0.0)
        return "snapshots", x, z, [(w * 1e3, s) for w, s in panels], scale * 1e3, (xi - files.attr(f, "head_center"), zi or 0.0, r or 0.0)
    if "modes" in f and "bed_shape_1" in f["modes"]:
        g = f["modes"]
        x, z, freq = files.numbers(g, "bed_x"), files.numbers(g, "bed_z"), files.numbers(g, "frequency")
        part = files.numbers(g, "part") if "part" in g else None
        share = files.numbers(g, "part_share") if "part_share" in g else None
        flexible = [k for k in range(len(freq)) if freq[k] > 0][: a.modes]
        panels = []
        for k in flexible:
            what = "" if part is None else ", %s %.0f%%" % (PARTS.get(int(part[k]), "?"), 100 * share[k])
            panels.append((files.numbers(g, "bed_shape_%d" % (k + 1)), "mode %d: %.1f Hz%s" % (k + 1, freq[k], what)))
        return "racket modes", x, z, panels, None, None
    if "modes" in f and "shape_1" in f["modes"] and files.attr(f, "strings_frame") == "held":
        g = f["modes"]
        x, z, freq = files.numbers(g, "x"), files.numbers(g, "z"), files.numbers(g, "frequency")
        n = min(a.modes, len(freq))
        return "bed modes", x, z, [(files.numbers(g, "shape_%d" % (k + 1)), "mode %d: %.1f Hz" % (k + 1, freq[k])) for k in range(n)], None, None
    sys.exit("%s: %s has no string bed's picture: write it with -strings_frame held -task modes, -strings_frame beam -task modes, "
             "or a racket's -task impact with -snapshot_times t1,t2,..." % (PROG, a.file))


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("file", help="HDF5 file: a string bed's or a strung racket's -task modes, or a racket's -task impact with -snapshot_times")
    ap.add_argument("-o", "--output", help="PNG to write (default: FILE with .png)")
    ap.add_argument("--modes", type=checks.count(1, "modes to draw"), default=6, help="modes to draw (default 6)")
    ap.add_argument("--snapshots", type=checks.count(1, "snapshot times to draw"), default=6, help="snapshot times to draw, evenly chosen (default 6)")
    a = ap.parse_args()
    with files.open_file(PROG, a.file) as f:
        kind, x, z, panels, scale, marker = read(f, a)
        shape, length, width = files.attr(f, "head_shape"), files.attr(f, "head_length"), files.attr(f, "head_width")
        frame = files.attr(f, "strings_frame")
        title = "string bed, %s %.3g x %.3g m %s: N_x %.0f N/m, N_z %.0f N/m, sigma %.4g kg/m^2, grid %d x %d; %s%s" % (
            shape, length, width, "held" if frame == "held" else "on the frame", files.attr(f, "membrane_N_x"), files.attr(f, "membrane_N_z"),
            files.attr(f, "membrane_sigma"), len(x), len(z), kind, " (mm)" if kind == "snapshots" else "")
    if not panels:
        sys.exit("%s: %s has no %s to draw" % (PROG, a.file, kind))
    n = len(panels)
    cols = min(3, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows + 0.4), squeeze=False)
    X, Z = np.meshgrid(x, z)
    for k in range(rows * cols):
        ax = axes[k // cols][k % cols]
        if k >= n:
            ax.axis("off")
            continue
        w, name = panels[k]
        w = np.ma.masked_invalid(np.asarray(w, dtype=float))
        m = scale if scale is not None else (float(np.max(np.abs(w))) or 1.0)
        if shape != "rectangle":  # the nodes outside the outline are not the bed's: blank
            w = np.ma.masked_where((X / (0.5 * length)) ** 2 + (Z / (0.5 * width)) ** 2 >= 1.0, w)
        mesh = ax.pcolormesh(X, Z, w, cmap="RdBu_r", vmin=-m, vmax=m, shading="auto")
        if scale is None and w.max() > 0 and w.min() < 0:
            ax.contour(X, Z, w, levels=[0.0], colors="k", linewidths=0.6, linestyles="--")
        outline(ax, shape, length, width)
        if marker is not None and marker[2] > 0:
            ax.add_patch(plt.Circle((marker[0], marker[1]), marker[2], fill=False, color="k", lw=0.8))
        if scale is not None:
            fig.colorbar(mesh, ax=ax, label="w - y - z phi (mm)", shrink=0.8)
        ax.set_aspect("equal")
        ax.set_xlim(-0.52 * length, 0.52 * length)  # the head (a bed on a frame has a column at every node of the frame)
        ax.set_ylim(-0.52 * width, 0.52 * width)
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("x along the frame (m)")
        ax.set_ylabel("z across (m)")
    fig.suptitle(title, fontsize=9)
    out = a.output or os.path.splitext(a.file)[0] + ".png"
    style.save(fig, out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
