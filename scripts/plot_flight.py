#!/usr/bin/env python3
"""The batted ball's trajectory from beamimpact -task flight files, as a PNG.

    scripts/plot_flight.py FILE.h5 [FILE.h5 ...] [-o out.png] [--labels A,B,...] [--top]

Draws each file's trajectory (/series) in a side view: height z against the horizontal
distance from the launch point, every file one curve with its apex and landing marked and a
legend line from its attributes and /results (launch speed, angle, spin; distance, hang time).
With --top, or when a ball moves sideways (sidespin, or a launch direction off the y axis),
a second panel shows the view from above (x across, y down the field). Everything drawn is
read from the files (docs/flight.md, "Output"); nothing is recomputed. Default output: the
first file's name with .png. For example, from the repository root:

    build/release/beamimpact -options_file options/scenes/flight-nathan.opts
    build/release/beamimpact -options_file options/scenes/flight-nathan.opts -flight_spin 0 -output flight-nathan-nospin.h5
    scripts/plot_flight.py flight-nathan.h5 flight-nathan-nospin.h5 -o flight-nathan.png
"""
import argparse
import os
import sys

from beamimpact import files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_flight.py"


def fail(msg):
    sys.stderr.write("%s: %s\n" % (PROG, msg))
    sys.exit(1)


def read(path):
    """The trajectory and the numbers of the legend of one -task flight file, with the units
    of its datasets."""
    f = files.open_file(PROG, path)
    with f:
        if files.attr(f, "task") != "flight" or "series" not in f or "results" not in f:
            fail("%s is not a -task flight file (its task: %s)" % (path, files.attr(f, "task")))
        s, r = f["series"], f["results"]
        d = {k: files.numbers(s, k) for k in ("time", "x", "y", "z")}
        for k in ("distance", "hang_time", "apex", "apex_time"):
            d[k] = float(files.numbers(r, k)[0])
        for k in ("flight_speed", "flight_angle", "flight_spin", "flight_sidespin", "air_density"):
            d[k] = files.attr(f, k)
        d["unit"] = {k: labels.unit_text(files.unit(s[k])) for k in ("x", "y", "z")}
        d["unit"].update({k: labels.unit_text(files.unit(r[k])) for k in ("distance", "hang_time")})
    d["horizontal"] = np.hypot(d["x"] - d["x"][0], d["y"] - d["y"][0])
    return d


def label(d):
    spin = "%.0f rad/s backspin" % d["flight_spin"]
    if d["flight_sidespin"]:
        spin += ", %.0f sidespin" % d["flight_sidespin"]
    u = d["unit"]
    return "%.4g m/s at %.4g°, %s, air %.4g kg/m³: %.2f %s in %.2f %s" % (d["flight_speed"], d["flight_angle"], spin, d["air_density"], d["distance"], u["distance"],
                                                                         d["hang_time"], u["hang_time"])


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="+", help="-task flight HDF5 files")
    ap.add_argument("-o", "--output", help="PNG to write (default: the first file with .png)")
    ap.add_argument("--labels", help="legend labels, comma-separated, one per file (default: from each file)")
    ap.add_argument("--top", action="store_true", help="add the view from above even without sideways motion")
    a = ap.parse_args()
    labels = a.labels.split(",") if a.labels else None
    if labels and len(labels) != len(a.files):
        fail("--labels gives %d labels for %d files" % (len(labels), len(a.files)))
    data = [read(p) for p in a.files]
    top = a.top or any(np.max(np.abs(d["x"])) > 1e-3 for d in data)
    colours = style.colours()
    fig, axes = plt.subplots(2 if top else 1, 1, figsize=(8, 7.5 if top else 4.5), squeeze=False)
    side = axes[0][0]
    for k, d in enumerate(data):
        c = colours[k % len(colours)]
        side.plot(d["horizontal"], d["z"], color=c, label=labels[k] if labels else label(d))
        i = int(np.argmax(d["z"]))
        side.plot(d["horizontal"][i], d["z"][i], "^", color=c, ms=5)
        side.plot(d["horizontal"][-1], d["z"][-1], "o", color=c, ms=5, clip_on=False)
        if top:
            axes[1][0].plot(d["x"], d["y"], color=c)
            axes[1][0].plot(d["x"][-1], d["y"][-1], "o", color=c, ms=5)
    u = data[0]["unit"]
    side.set_xlabel("horizontal distance from the launch point (%s)" % u["x"])
    side.set_ylabel("height z (%s)" % u["z"])
    side.set_xlim(left=0)
    side.set_ylim(0, 1.45 * max(np.max(d["z"]) for d in data))  # room for the legend above the curves
    side.grid(alpha=0.3)
    side.legend(fontsize=7, title="▲ apex, ● landing", title_fontsize=7, loc="upper left")
    side.set_title("Flight of the batted ball (Nathan's trajectory model)", fontsize=10)
    if top:
        ax = axes[1][0]
        ax.set_xlabel("x across (%s)" % u["x"])
        ax.set_ylabel("y down the field (%s)" % u["y"])
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
        ax.set_title("from above", fontsize=9)
    out = a.output or os.path.splitext(a.files[0])[0] + ".png"
    style.save(fig, out, dpi=120)
    print("wrote %s (%d trajectories)" % (out, len(data)))


if __name__ == "__main__":
    main()
