#!/usr/bin/env python3
"""A bat (or any beam) with its mode shapes, from a beamimpact -task modes file.

    scripts/plot_bat.py r161-modes.h5 -o r161-modes.png [--modes 3]

Top: the section along the beam -- the outline +-D/2 of a round profile (and the bore d of a
hollow one), else the mass per length mu(x) -- with the centre of mass marked. Bottom: the
deflection shapes of the first flexible modes (each scaled to unit peak) with their
frequencies, and the nodes of the first two (where a tap excites nothing: /modes/nodes_1,
nodes_2). The title gives the theory, the mass and the moments of inertia the file records.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from debian_python import require  # noqa: E402

require(__file__, "numpy", "h5py", "matplotlib")
import numpy as np  # noqa: E402
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def attr(f, name, default=None):
    v = f.attrs.get(name, default)
    if isinstance(v, bytes):
        v = v.decode()
    return v.item() if hasattr(v, "item") else v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("file", help="HDF5 file written by -task modes")
    ap.add_argument("-o", "--output", help="PNG to write (default: FILE with .png)")
    ap.add_argument("--modes", type=int, default=3, help="flexible modes to draw (default 3)")
    a = ap.parse_args()
    out = a.output or os.path.splitext(a.file)[0] + ".png"
    with h5py.File(a.file, "r") as f:
        if "modes" not in f or "shapes" not in f["modes"] or "beam" not in f:
            sys.exit("plot_bat.py: %s has no /modes/shapes or /beam: write it with -task modes" % a.file)
        x = f["beam/x"][:]
        freq = f["modes/frequency"][:]
        shapes = f["modes/shapes"][:]
        nodes = [f["modes/" + n][:] if n in f["modes"] else np.array([]) for n in ("nodes_1", "nodes_2")]
        prof = {k: f["beam/profile_" + k][:] for k in ("x", "D", "d")} if "profile_x" in f["beam"] else None
        mu = f["beam/mu"][:]
        info = dict(theory=attr(f, "beam_theory", "euler"), mass=attr(f, "beam_mass", 0.0), xcm=attr(f, "beam_center_of_mass", 0.0),
                    icm=attr(f, "beam_inertia_cm", 0.0), iend=attr(f, "beam_inertia_end", 0.0), src=attr(f, "beam_section_file", ""))
    flex = [k for k in range(len(freq)) if freq[k] > 0][: a.modes]

    fig, (ax0, ax1) = plt.subplots(2, 1, figsize=(9, 6), sharex=True, gridspec_kw=dict(height_ratios=[1, 2]))
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
    ax1.set_ylabel("deflection (scaled)")
    ax1.legend(fontsize=8, loc="lower left")
    fig.suptitle("%s (%s): %.3f kg, I_cm %.4f kg m^2, I_0 %.4f kg m^2; open circles: nodes"
                 % (os.path.basename(info["src"]) or "beam", info["theory"], info["mass"], info["icm"], info["iend"]), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
