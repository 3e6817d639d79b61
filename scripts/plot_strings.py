#!/usr/bin/env python3
"""The string bed's mode shapes, from a -strings_frame held -task modes file.

    scripts/plot_strings.py strings-modes.h5 -o strings-modes.png [--modes 6]

One panel per mode (the first 6 unless --modes says otherwise): the mass-normalised deflection
/modes/shape_k on the head's grid (/modes/x along the frame's axis, /modes/z across the face,
from the head's centre), coloured from -max to +max with the nodal lines (w = 0) drawn and the
outline (ellipse or rectangle, from the file's head_shape, head_length and head_width), titled
with the mode's frequency. The figure's title gives the head, the tensions and the grid.
"""
import argparse
import os
import sys

from beamimpact import files, style

import numpy as np

plt = style.plt


def outline(ax, shape, length, width):
    a, b = 0.5 * length, 0.5 * width
    if shape == "rectangle":
        ax.plot([-a, a, a, -a, -a], [-b, -b, b, b, -b], "k-", lw=1)
    else:
        t = np.linspace(0, 2 * np.pi, 241)
        ax.plot(a * np.cos(t), b * np.sin(t), "k-", lw=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("file", help="HDF5 file written by -strings_frame held -task modes")
    ap.add_argument("-o", "--output", help="PNG to write (default: FILE with .png)")
    ap.add_argument("--modes", type=int, default=6, help="modes to draw (default 6)")
    a = ap.parse_args()
    with files.open_file("plot_strings.py", a.file) as f:
        if "modes" not in f or "shape_1" not in f["modes"] or files.attr(f, "strings_frame") != "held":
            sys.exit("plot_strings.py: %s has no string bed's modes (/modes/shape_1): write it with -strings_frame held -task modes" % a.file)
        g = f["modes"]
        x, z, freq = files.numbers(g, "x"), files.numbers(g, "z"), files.numbers(g, "frequency")
        n = min(a.modes, len(freq))
        shapes = [files.numbers(g, "shape_%d" % (k + 1)) for k in range(n)]
        shape, length, width = files.attr(f, "head_shape"), files.attr(f, "head_length"), files.attr(f, "head_width")
        title = "string bed, %s %.3g x %.3g m held: N_x %.0f N/m, N_z %.0f N/m, sigma %.4g kg/m^2, grid %d x %d" % (
            shape, length, width, files.attr(f, "membrane_N_x"), files.attr(f, "membrane_N_z"), files.attr(f, "membrane_sigma"), len(x), len(z))
    cols = min(3, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows + 0.4), squeeze=False)
    X, Z = np.meshgrid(x, z)
    for k in range(rows * cols):
        ax = axes[k // cols][k % cols]
        if k >= n:
            ax.axis("off")
            continue
        w = shapes[k]
        m = np.max(np.abs(w)) or 1.0
        if shape != "rectangle":  # the nodes outside the outline are not the bed's (held at 0): blank
            w = np.ma.masked_where((X / (0.5 * length)) ** 2 + (Z / (0.5 * width)) ** 2 >= 1.0, w)
        ax.pcolormesh(X, Z, w, cmap="RdBu_r", vmin=-m, vmax=m, shading="auto")
        if w.max() > 0 and w.min() < 0:
            ax.contour(X, Z, w, levels=[0.0], colors="k", linewidths=0.6, linestyles="--")
        outline(ax, shape, length, width)
        ax.set_aspect("equal")
        ax.set_title("mode %d: %.1f Hz" % (k + 1, freq[k]), fontsize=10)
        ax.set_xlabel("x along the frame (m)")
        ax.set_ylabel("z across (m)")
    fig.suptitle(title, fontsize=9)
    out = a.output or os.path.splitext(a.file)[0] + ".png"
    style.save(fig, out, dpi=110)
    print("wrote %s" % out)


if __name__ == "__main__":
    main()
