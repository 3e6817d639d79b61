#!/usr/bin/env python3
"""Maps of a racket's string face: a sweep over the impact point along the frame and across it, as a PNG.

    /usr/bin/python3 scripts/plot_racket_map.py FILE.h5 [-o out.png] [--modes MODES.h5] [--hand X]

FILE.h5 is a -task sweep over impact_x and impact_z of a racket with a string bed
(-strings_frame beam; options/scenes/racket-face-map.opts). Four maps over the face: the ACOR
(the rebound, "power"), the contact time (the dwell), the string bed's largest deflection from
its frame, and the energy the frame keeps in its vibration and roll (vibration_fraction +
twist_fraction + roll_fraction: its bending, its twisting and its rigid roll, of the energy brought
in; a file from before twist_fraction: vibration_fraction, which then held the twist and the
strings too, + roll_fraction), each with the head's outline. Marked, and printed, are the sweet spots of the
racket literature (Brody, Cross and Lindsey, The Physics and Technology of Tennis):
  * the largest ACOR (a star);
  * the centre of percussion for a hand at x = --hand (default: 3 cm from the handle's end): the
    point whose impulse leaves the hand at rest, b = I_cm / (M d) from the centre of mass toward
    the tip, d the hand's distance from it (from the file's rigid-body attributes; a dashed line);
  * the node of the frame's fundamental on the head (a dotted line), from --modes, the file of
    -task modes of the same racket (its /modes/nodes_1), when given; else the point of least
    frame vibration along the axis (the row nearest z = 0) stands in for it.
Points without a result (status != 0: off the face, status 8, or failed) are left blank.
"""
import argparse
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_racket_map.py"
PANELS = ("acor", "contact_time", "bed_deflection_peak", "frame_fraction")


def grid(r, xs, zs, values, ok):
    """Values on the (z, x) grid; NaN at failed or missing points."""
    g = np.full((len(zs), len(xs)), np.nan)
    x, z = r["impact_x"][()], r["impact_z"][()]
    for k in range(len(values)):
        if ok[k]:
            g[np.searchsorted(zs, z[k]), np.searchsorted(xs, x[k])] = values[k]
    return g


def outline(f):
    """The head's outline (x along the frame, z across; m) from the file's attributes."""
    c, a, b = files.attr(f, "head_center"), 0.5 * files.attr(f, "head_length"), 0.5 * files.attr(f, "head_width")
    if files.attr(f, "head_shape") == "rectangle":
        return np.array([c - a, c + a, c + a, c - a, c - a]), np.array([-b, -b, b, b, -b])
    t = np.linspace(0, 2 * np.pi, 200)
    return c + a * np.cos(t), b * np.sin(t)


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("file")
    ap.add_argument("-o", "--output", default=None, help="PNG to write (default: FILE without .h5, -face.png)")
    ap.add_argument("--modes", default=None, help="a -task modes file of the same racket: its fundamental's node on the head")
    ap.add_argument("--hand", type=float, default=None, help="the hand's point x (m) for the centre of percussion (default: 3 cm from the x = L end)")
    args = ap.parse_args()
    f, r = files.open_map(PROG, args.file, ("impact_x", "impact_z"))
    if files.attr(f, "strings_frame") != "beam":
        sys.exit("%s: %s is not a racket with a string bed on its frame (-strings_frame beam)" % (PROG, args.file))
    for c in ("acor", "contact_time", "bed_deflection_peak", "vibration_fraction", "roll_fraction"):
        if c not in r:
            sys.exit("%s: %s has no /results/%s (a free racket struck by a moving ball records it)" % (PROG, args.file, c))
    ok = files.status(r, r["impact_x"].shape[0]) == 0
    if not np.any(ok):
        sys.exit("%s: no point of %s succeeded" % (PROG, args.file))
    xs, zs = np.unique(r["impact_x"][()]), np.unique(r["impact_z"][()])
    values = {c: r[c][()] for c in ("acor", "contact_time", "bed_deflection_peak")}
    twist = r["twist_fraction"][()] if "twist_fraction" in r else 0.0  # (in vibration_fraction before the column)
    values["frame_fraction"] = r["vibration_fraction"][()] + twist + r["roll_fraction"][()]
    maps = {c: grid(r, xs, zs, values[c], ok) for c in PANELS}

    acor = maps["acor"]
    i, j = np.unravel_index(np.nanargmax(acor), acor.shape)
    L, M, xcm, Icm = (files.attr(f, k) for k in ("beam_length", "beam_mass", "beam_center_of_mass", "beam_inertia_cm"))
    hand = args.hand if args.hand is not None else L - 0.03
    d = hand - xcm
    cop = xcm - Icm / (M * d)  # toward the tip (x = 0) from the centre of mass, the hand beyond it
    print("largest ACOR %.4f at impact_x %.3f m, impact_z %.3f m" % (acor[i, j], xs[j], zs[i]))
    print("centre of percussion for the hand at x = %.3f m: x = %.4f m (centre of mass %.4f m, I_cm %.5g kg m^2, M %.4f kg)" % (hand, cop, xcm, Icm, M))
    node, node_how = None, ""
    if args.modes:
        g = files.open_file(PROG, args.modes)
        if "modes" not in g or "nodes_1" not in g["modes"]:
            sys.exit("%s: %s has no /modes/nodes_1 (run -task modes on the same racket)" % (PROG, args.modes))
        c, a = files.attr(f, "head_center"), 0.5 * files.attr(f, "head_length")
        on_head = [x for x in g["modes"]["nodes_1"][()] if c - a <= x <= c + a]
        if on_head:
            node, node_how = on_head[0], "the fundamental's node (%s)" % args.modes
    if node is None:  # the least frame vibration along the axis
        row = int(np.argmin(np.abs(zs)))
        vib = maps["frame_fraction"][row]
        if np.any(~np.isnan(vib)):
            node, node_how = xs[int(np.nanargmin(vib))], "least frame energy along z = %.3f m" % zs[row]
    if node is not None:
        print("node: x = %.4f m (%s)" % (node, node_how))

    ox, oz = outline(f)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5), sharex=True, sharey=True)
    titles = {"acor": "ACOR (rebound)", "contact_time": "contact time (dwell)", "bed_deflection_peak": "strings' largest deflection",
              "frame_fraction": "frame's vibration and roll / E_in"}
    for ax, c in zip(axes.flat, PANELS):
        z = maps[c]
        m = ax.pcolormesh(xs, zs * 100, z, shading="nearest", cmap="viridis")
        if np.sum(~np.isnan(z)) > 4 and len(xs) > 1 and len(zs) > 1:
            cs = ax.contour(xs, zs * 100, z, colors="k", linewidths=0.6, levels=8)
            ax.clabel(cs, fontsize=7, fmt="%.3g")
        ax.plot(ox, oz * 100, "w-", linewidth=1.2)
        ax.axvline(cop, color="r", linestyle="--", linewidth=1.0)
        if node is not None:
            ax.axvline(node, color="orange", linestyle=":", linewidth=1.4)
        ax.plot(xs[j], zs[i] * 100, "*", color="r", markersize=14, markeredgecolor="w")
        label = labels.axis_label(r, c) if c != "frame_fraction" else "vibration_ + twist_ + roll_fraction (1)"
        fig.colorbar(m, ax=ax, label=label)
        ax.set_title(titles[c])
    for ax in axes[1]:
        ax.set_xlabel(labels.axis_label(r, "impact_x"))
    for ax in axes[:, 0]:
        ax.set_ylabel("across the face: impact_z (cm)")
    node_text = "; dotted: %s, x = %.3f m" % (node_how, node) if node is not None else ""
    fig.suptitle("%s\nstar: the largest ACOR (%.4f at x = %.3f m, z = %.1f cm); dashed: the centre of percussion (hand at %.3f m), x = %.3f m%s"
                 % (args.file, acor[i, j], xs[j], zs[i] * 100, hand, cop, node_text), fontsize=8)
    out = args.output or files.default_prefix(args.file) + "-face.png"
    print("wrote %s" % style.save(fig, out))


if __name__ == "__main__":
    main()
