#!/usr/bin/env python3
"""ACOR against impact point from beamimpact sweep files, as a PNG.

    scripts/plot_acor.py free.h5 clamped.h5 -o acor.png

Each file (-task sweep output, complete or still running) gives one colour:
the corrected ACOR (acor_corrected: x loss factor for the linear spring) as a
solid line with markers, the raw ACOR dotted (omitted when equal: hysteretic
ball), and the rigid-body ACOR of Eq. (11) dashed. Legends come from the
files' attributes (length, supports, thickness, ball law, f).
"""
import os
import sys



sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from debian_python import require  # noqa: E402

require(__file__, "numpy", "h5py", "matplotlib")
import numpy as np  # noqa: E402
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


import argparse  # noqa: E402


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
    if a:
        parts.append("a = %g mm" % (a * 1e3))
    law = attr(f, "ball_law")
    if law:
        parts.append(law + " ball")
    done, total = attr(f, "sweep_cases_done"), attr(f, "sweep_cases_total")
    if done is not None and total is not None and done < total:
        parts.append("partial %d/%d" % (done, total))
    return ", ".join(parts) if parts else os.path.basename(path)


def main():
    p = argparse.ArgumentParser(description="Plot ACOR (raw, corrected) and the rigid-body ACOR against impact point from beamimpact -task sweep HDF5 files.")
    p.add_argument("files", nargs="+", help="sweep output files (.h5)")
    p.add_argument("-o", "--output", default="acor.png", help="PNG to write (default: acor.png)")
    p.add_argument("--label", action="append", default=[], help="legend label for each file, in order (default: from the file's attributes)")
    p.add_argument("--title", default="Apparent coefficient of restitution", help="figure title")
    p.add_argument("--no-raw", action="store_true", help="omit the raw (uncorrected) ACOR")
    p.add_argument("--no-rigid", action="store_true", help="omit the rigid-body curves")
    p.add_argument("--dpi", type=int, default=150)
    args = p.parse_args()
    if args.label and len(args.label) != len(args.files):
        p.error("give one --label per file (%d files, %d labels)" % (len(args.files), len(args.label)))

    fig, ax = plt.subplots(figsize=(8, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    any_raw = any_rigid = False
    for k, path in enumerate(args.files):
        try:
            f = h5py.File(path, "r")
        except OSError as err:
            sys.exit("plot_acor.py: cannot read %s: %s" % (path, err))
        with f:
            if "results" not in f or "acor" not in f["results"]:
                sys.exit("plot_acor.py: %s has no /results/acor (is it a beamimpact sweep or impact file?)" % path)
            r = f["results"]
            x = r["x"][()]
            order = np.argsort(x, kind="stable")
            x = x[order]
            acor = r["acor"][()][order]
            corr = r["acor_corrected"][()][order]
            rigid = r["rigid_acor"][()][order] if "rigid_acor" in r else None
            c = colours[k % len(colours)]
            label = args.label[k] if args.label else label_of(f, path)
            if not args.no_rigid and rigid is not None:
                label += "; rigid f = %g" % attr(f, "rigid_loss_fraction", 0.0)
            if len(x) == 0:
                print("plot_acor.py: %s has no rows yet" % path, file=sys.stderr)
            ax.plot(x, corr, "-", color=c, marker="o", markersize=2.5, linewidth=1.4, label=label)
            if not args.no_raw and not np.array_equal(acor, corr):
                ax.plot(x, acor, ":", color=c, linewidth=1.2)
                any_raw = True
            if not args.no_rigid and rigid is not None:
                ax.plot(x, rigid, "--", color=c, linewidth=1.0, alpha=0.8)
                any_rigid = True

    ax.set_xlabel("impact point x (m)")
    ax.set_ylabel("ACOR")
    ax.set_title(args.title)
    ax.grid(True, alpha=0.3)
    files_legend = ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize=8, frameon=False)
    ax.add_artist(files_legend)
    from matplotlib.lines import Line2D

    styles = [Line2D([], [], color="k", linestyle="-", marker="o", markersize=2.5, label="ACOR corrected (x loss factor)")]
    if any_raw:
        styles.append(Line2D([], [], color="k", linestyle=":", label="ACOR raw"))
    if any_rigid:
        styles.append(Line2D([], [], color="k", linestyle="--", label="rigid body, Eq. (11)"))
    ax.legend(handles=styles, loc="upper right", fontsize=8)
    fig.savefig(args.output, dpi=args.dpi, bbox_inches="tight", bbox_extra_artists=[files_legend])
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
