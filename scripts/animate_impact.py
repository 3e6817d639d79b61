#!/usr/bin/env python3
"""An animation of the beam and the ball through one impact, from a beamimpact -task impact file.

    scripts/animate_impact.py FILE.h5 -o out.gif [--frames N] [--fps 20] [--no-ball]

One frame per snapshot time of the file (/snapshots: the beam's displacement y(x) at every node
at exactly those times, -snapshot_times), or --frames N of them evenly chosen. The ball is drawn
at the impact point at its position y_b (/series/ball_y, -monitor_ball; read at each frame's
time by linear interpolation between the recorded steps): its front at y_b, so while in contact
it overlaps the beam by the compression c = y_b - y(x_imp). The displacements are magnified
(the vertical axis is in mm, the beam in m) and the ball is drawn round on the screen, not to
scale. Each frame shows the time and, with /series/force, the contact force. A racket with a
string bed (-strings_frame beam or held) adds a panel below: the bed's deflection from its frame
(/snapshots/bed, w - y - z phi, mm) on the head at the same times, one colour scale for all.

The file that animates, from the repository root (101 snapshots, 0 to 10 ms, ~0.1 s to compute):

    mkdir -p out
    build/release/beamimpact -options_file options/scenes/animation.opts -output out/animation.h5
    scripts/animate_impact.py out/animation.h5 -o out/animation.gif

Any -task impact run with -monitor_ball and many -snapshot_times t1,t2,... animates the same way.
The GIF is written by matplotlib's PillowWriter (Debian: python3-pil, which comes with
python3-matplotlib). `-o out.mp4` needs ffmpeg on PATH (Debian: apt-get install ffmpeg); without
it the script says so and writes nothing.
"""
import argparse
import os
import shutil
import sys

from beamimpact import checks, files, labels, style

import numpy as np
from matplotlib import animation
from matplotlib.patches import Ellipse

plt = style.plt

PROG = "animate_impact.py"
SCENE = " (e.g. -options_file options/scenes/animation.opts)"


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 2)[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="HDF5 file written by beamimpact -task impact with -snapshot_times (and -monitor_ball)")
    ap.add_argument("-o", "--output", required=True, help="out.gif (or out.mp4 with ffmpeg on PATH)")
    ap.add_argument("--frames", type=int, default=0, help="at most this many frames, evenly chosen from the snapshots (default: all)")
    ap.add_argument("--fps", type=float, default=20, help="frames per second (default 20)")
    ap.add_argument("--dpi", type=checks.count(1, "dots per inch"), default=80, help="resolution (default 80: 640 x 320 pixels)")
    ap.add_argument("--no-ball", action="store_true", help="the beam only (a file without -monitor_ball)")
    a = ap.parse_args()
    ext = os.path.splitext(a.output)[1].lower()
    if ext not in (".gif", ".mp4"):
        sys.stderr.write("%s: -o %s: write a .gif (or an .mp4 with ffmpeg)\n" % (PROG, a.output))
        return 1
    if ext == ".mp4" and not shutil.which("ffmpeg"):
        sys.stderr.write("%s: -o %s: an MP4 needs ffmpeg, and there is no ffmpeg on PATH (Debian: apt-get install ffmpeg); "
                         "write a GIF instead: -o %s\n" % (PROG, a.output, os.path.splitext(a.output)[0] + ".gif"))
        return 1
    with files.open_file(PROG, a.file) as f:
        task = files.attr(f, "task", "")
        if task and task != "impact":
            sys.stderr.write("%s: %s was written by -task %s; an animation needs a -task impact file%s\n" % (PROG, a.file, task, SCENE))
            return 1
        if not files.has(f, "snapshots"):
            files.missing(PROG, a.file, "snapshots", ", many of them%s" % SCENE)
        if not a.no_ball and not files.has(f, "ball"):
            files.missing(PROG, a.file, "ball", SCENE + ", or animate the beam alone with --no-ball")
        x, ts, Y = f["snapshots/x"][()], f["snapshots/time"][()], f["snapshots/y"][()]
        if len(ts) < 2:
            sys.stderr.write("%s: %s has %d snapshot time(s): an animation needs many (-snapshot_times t1,t2,...%s)\n"
                             % (PROG, a.file, len(ts), SCENE))
            return 1
        s = f["series"] if "series" in f else {}
        st = s["time"][()] if "time" in s else None
        yb = np.interp(ts, st, s["ball_y"][()]) if not a.no_ball else None
        force = np.interp(ts, st, s["force"][()]) if (st is not None and "force" in s) else None
        xi = files.impact_point(f)
        L = float(files.attr(f, "beam_length", x[-1]))
        label = labels.config_label(f)
        left, right = files.attr(f, "beam_left", "free"), files.attr(f, "beam_right", "free")
        x0, x1 = files.attr(f, "beam_clamp_x0", -1), files.attr(f, "beam_clamp_x1", -1)
        bed = None
        if "bed" in f["snapshots"]:  # a racket's string bed: its deflection from the frame on the head
            bx, bz = f["snapshots/bed_x"][()], f["snapshots/bed_z"][()]
            bed = f["snapshots/bed"][()].reshape(len(ts), len(bz), len(bx)) * 1e3
            head = (files.attr(f, "head_shape"), files.attr(f, "head_length"), files.attr(f, "head_width"))
    pick = np.arange(len(ts))
    if a.frames and a.frames < len(ts):
        pick = np.unique(np.round(np.linspace(0, len(ts) - 1, a.frames)).astype(int))

    Ymm = Y * 1e3
    lo, hi = float(np.min(Ymm[pick])), float(np.max(Ymm[pick]))
    if yb is not None:
        lo, hi = min(lo, float(np.min(yb[pick] * 1e3))), max(hi, float(np.max(yb[pick] * 1e3)))
    span = max(hi - lo, 1e-6)
    ball_h = 0.2 * span if yb is not None else 0.0  # the ball's height on the screen, in mm of the y axis
    ylim = (lo - ball_h - 0.08 * span, hi + 0.12 * span)
    xlim = (-0.03 * L, 1.03 * L)

    if bed is None:
        fig, ax = plt.subplots(figsize=(8, 4))
    else:
        fig, (ax, bax) = plt.subplots(2, 1, figsize=(8, 7), gridspec_kw={"height_ratios": [1, 1.3]})
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel("x (m) from the x = 0 end")
    ax.set_ylabel("y (mm, magnified)")
    ax.set_title("\n".join([os.path.basename(a.file) + ": beam and ball", label]), fontsize=8)
    ax.axhline(0, color="0.7", lw=0.6, ls=":")
    if x0 is not None and x0 >= 0:
        ax.axvspan(x0, x1, color="0.88", zorder=0)
    for xs, side in ((0.0, left), (L, right)):
        if side and side != "free":
            ax.plot([xs], [0], "ks", ms=7)
    if xi is not None:
        ax.axvline(xi, color="C3", lw=0.6, ls="--")
    (beam,) = ax.plot(x, Ymm[pick[0]], color="0.25", lw=3, solid_capstyle="round")
    mesh = None
    if bed is not None:
        shape, length, width = head
        m = float(np.nanmax(np.abs(bed[pick]))) or 1.0
        mesh = bax.pcolormesh(bx, bz, np.ma.masked_invalid(bed[pick[0]]), cmap="RdBu_r", vmin=-m, vmax=m, shading="auto")
        t = np.linspace(0, 2 * np.pi, 241)
        if shape == "rectangle":
            bax.plot([-length / 2, length / 2, length / 2, -length / 2, -length / 2], [-width / 2, -width / 2, width / 2, width / 2, -width / 2], "k-", lw=1)
        else:
            bax.plot(length / 2 * np.cos(t), width / 2 * np.sin(t), "k-", lw=1)
        bax.set_xlim(-0.52 * length, 0.52 * length)
        bax.set_ylim(-0.52 * width, 0.52 * width)
        bax.set_aspect("equal")
        bax.set_xlabel("x along the frame from the head's centre (m)")
        bax.set_ylabel("z across (m)")
        fig.colorbar(mesh, ax=bax, label="strings: w - y - z phi (mm)")
    text = ax.text(0.01, 0.97, "", transform=ax.transAxes, va="top", fontsize=9, family="monospace")
    ball = None
    if yb is not None and xi is not None:
        fig.tight_layout()
        fig.canvas.draw()
        # round on the screen: the width in m that spans as many pixels as ball_h mm does
        bb = ax.get_window_extent()
        px_per_mm = bb.height / (ylim[1] - ylim[0])
        px_per_m = bb.width / (xlim[1] - xlim[0])
        ball_w = ball_h * px_per_mm / px_per_m
        ball = Ellipse((xi, 0.0), ball_w, ball_h, facecolor="C1", edgecolor="k", lw=1, zorder=4)
        ax.add_patch(ball)
    else:
        fig.tight_layout()

    def frame(j):
        k = pick[j]
        beam.set_ydata(Ymm[k])
        line = "t = %7.3f ms" % (ts[k] * 1e3)
        if ball is not None:
            ball.set_center((xi, yb[k] * 1e3 - ball_h / 2))  # its front at y_b
            c = yb[k] * 1e3 - np.interp(xi, x, Ymm[k])
            line += "   c = %6.3f mm" % max(c, 0.0) if c > -1e-9 else "   apart by %.3f mm" % -c
        if force is not None:
            line += "   F = %6.2f N" % force[k]
        text.set_text(line)
        if mesh is not None:
            mesh.set_array(np.ma.masked_invalid(bed[k]).ravel())
        return (beam, text) + ((ball,) if ball is not None else ()) + ((mesh,) if mesh is not None else ())

    files.check_output(PROG, a.output, ext)  # not onto the file it reads
    anim = animation.FuncAnimation(fig, frame, frames=len(pick), blit=False)
    if ext == ".gif":
        writer = animation.PillowWriter(fps=a.fps)
    else:
        writer = animation.FFMpegWriter(fps=a.fps)
    anim.save(a.output, writer=writer, dpi=a.dpi)
    plt.close(fig)
    print("wrote %s: %d frames (t = %.4g to %.4g ms), %d bytes" % (a.output, len(pick), ts[pick[0]] * 1e3, ts[pick[-1]] * 1e3, os.path.getsize(a.output)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
