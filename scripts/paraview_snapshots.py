#!/usr/bin/env python3
"""A scene's snapshots in ParaView: the XDMF description beamimpact writes beside a -task impact
file with -snapshot_times (FILE.xmf beside FILE.h5) opened as a time series and drawn at a few of
its times, side by side, into one PNG.

    scripts/paraview_snapshots.py FILE.xmf -o out.png [--field beam|bed|wall] [--times t1,t2,...]
                                  [--scale S] [--size 1500x520]

--field: the beam's deflection y(x) (a line, drawn displaced by y, the times one above the other),
the racket's string bed (w - y - z phi on the head, its surface displaced by w) or the barrel
wall's harmonics W_n(x) (a strip per n, displaced by W_n); default the bed, else the wall, else the
beam, as the file has them. --times: the snapshot times to draw (default three: a third, two thirds
and all of the way through the file's times), each at the nearest time the file holds. The
displacements are magnified --scale times (default: the largest over the times drawn shown as a
quarter of the grid's size; the beam's, a twentieth), coloured by their value in mm on one scale
for all the panels.

The picture in the README's Output section (docs/img/paraview-racket-bed.png), from the
repository root (about 2 s to compute, 5 s to draw):

    mkdir -p out
    build/release/beamimpact -options_file options/scenes/racket-strings.opts \\
        -snapshot_times 0.001,0.003,0.005 -output out/racket-strings.h5
    scripts/paraview_snapshots.py out/racket-strings.xmf -o docs/img/paraview-racket-bed.png

Needs ParaView (Debian: apt-get install paraview; nothing else of beamimpact does): run by a Python
without ParaView's modules, the script runs itself again under pvpython, and when there is no
display (DISPLAY unset: a server, CI) in a virtual one with xvfb-run (Debian: apt-get install
xvfb), as Debian's ParaView renders through X even with --force-offscreen-rendering. Without them
it says what is missing and draws nothing. The file is read with ParaView's Xdmf3 reader
(Xdmf3ReaderT), as File > Open does by default.
"""
import argparse
import os
import shutil
import sys
import xml.etree.ElementTree as ET

PROG = "paraview_snapshots.py"

try:
    from paraview import simple as pv
except ImportError:
    pv = None


def fail(msg):
    sys.stderr.write("%s: %s\n" % (PROG, msg))
    sys.exit(1)


def collections(xmf):
    """The temporal collections of the description, in its order: [(name, attribute, [times])]."""
    try:
        root = ET.parse(xmf).getroot()
    except (OSError, ET.ParseError) as e:
        fail("%s is not an XDMF file this script can read (%s)" % (xmf, e))
    out = []
    for c in root.iter("Grid"):
        if c.get("CollectionType") == "Temporal":
            grids = c.findall("Grid")
            attr = grids[0].find("Attribute").get("Name") if grids else ""
            out.append((c.get("Name"), attr, [float(g.find("Time").get("Value")) for g in grids]))
    if not out:
        fail("%s holds no time series (no temporal collection): beamimpact writes one beside a -task impact file "
             "with -snapshot_times" % xmf)
    return out


def pick_times(asked, have):
    if asked:
        want = [float(t) for t in asked.split(",")]
    else:
        n = len(have)
        want = [have[max(0, round(n * k / 3) - 1)] for k in (1, 2, 3)] if n >= 3 else have
    return [min(have, key=lambda h: abs(h - t)) for t in want]


def field_range(kept, attr, times):
    """The values' range of attr over the times and the bounds of the grid kept."""
    lo, hi, bounds = float("inf"), -float("inf"), None
    for t in times:
        kept.UpdatePipeline(t)
        r = kept.PointData[attr].GetRange()
        lo, hi = min(lo, r[0]), max(hi, r[1])
        bounds = kept.GetDataInformation().GetBounds()
    return lo, hi, bounds


def place_camera(view, a, beam, n, step, bounds, lift):
    """A parallel projection that fills 75% of the image with the n panels (step apart), centred a
    little left of the middle (the colour bar is at the right), looking at the height lift (m) of the
    displaced surface; the panels' centres on the screen."""
    w = bounds[1] - bounds[0]
    cx, cy = 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3])
    aspect = a.size[1] / a.size[0]
    if beam:  # one line above the other, seen from +z
        span = max(w / 0.75 * aspect, ((n - 1) * step + 0.2 * w) / 0.75)  # the view's height in m
        focal = [cx + 0.07 * span / aspect, cy - 0.5 * (n - 1) * step, 0]
        view.CameraPosition, view.CameraViewUp = [focal[0], focal[1], 1], [0, 1, 0]
        centres = [(0.43, 0.5 + (0.5 * (n - 1) - k) * step / span) for k in range(n)]
    else:  # side by side, seen from the front (-y) and above
        span = ((n - 1) * step + w) / 0.75 * aspect
        focal = [cx + 0.5 * (n - 1) * step + 0.07 * span / aspect, cy, lift]
        view.CameraPosition, view.CameraViewUp = [focal[0], focal[1] - 1.0, lift + 0.5], [0, 0, 1]
        centres = [(0.43 + (k - 0.5 * (n - 1)) * step * aspect / span, 0.5) for k in range(n)]
    view.CameraFocalPoint = focal
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.5 * span
    return centres


def draw(a, xmf, index, count, field, attr, times):
    """One view: the field (collection index of count) at each time (ForceTime), displaced, side by side
    (the beam: one above the other)."""
    reader = pv.Xdmf3ReaderT(FileName=[xmf])  # one collection: its grid; more: a block each
    block = pv.ExtractBlock(Input=reader, Selectors=["/Root/Block%d" % index]) if count > 1 else reader
    mm = pv.Calculator(Input=block, ResultArrayName=attr + "_mm", Function="%s*1000" % attr)
    # where the bed or the wall is not (NaN off the head, at a solid section) drops out: NaN passes no threshold
    kept = mm if field == "beam" else pv.Threshold(Input=mm, Scalars=["POINTS", attr], LowerThreshold=-1e30,
                                                    UpperThreshold=1e30)
    lo, hi, bounds = field_range(kept, attr, times)
    if field == "wall":  # the harmonics n = 2, 3, ... across a quarter of the wall's length
        kept = pv.Transform(Input=kept)
        kept.Transform.Scale = [1, 0.25 * (bounds[1] - bounds[0]) / max(bounds[3] - bounds[2], 1e-30), 1]
        lo, hi, bounds = field_range(kept, attr, times)
    largest = max(abs(lo), abs(hi))
    if largest == 0:
        fail("%s: the %s is at rest at the times drawn (%s): choose later --times" % (xmf, field, times))
    w, h = bounds[1] - bounds[0], bounds[3] - bounds[2]
    beam, n = field == "beam", len(times)
    scale = a.scale or (0.05 if beam else 0.25) * max(w, h) / largest
    if abs(lo) < 1e-3 * largest:  # a field of one sign: its scale from 0
        lo = 0.0
    if abs(hi) < 1e-3 * largest:
        hi = 0.0
    step = 0.12 * w if beam else 1.15 * w
    view = pv.CreateRenderView()
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    if "UseColorPaletteForBackground" in view.ListProperties():
        view.UseColorPaletteForBackground = 0
    lut = pv.GetColorTransferFunction(attr + "_mm")
    lut.ApplyPreset("Cool to Warm", True)
    centres = place_camera(view, a, beam, n, step, bounds, 0.4 * scale * hi)
    for k, t in enumerate(times):
        at = pv.ForceTime(Input=kept, ForcedTime=t, IgnorePipelineTime=1)
        warped = pv.WarpByScalar(Input=at, Scalars=["POINTS", attr], ScaleFactor=scale, UseNormal=1,
                                 Normal=[0, 1, 0] if beam else [0, 0, 1])
        moved = pv.Transform(Input=warped)
        moved.Transform.Translate = [0, -k * step, 0] if beam else [k * step, 0, 0]
        d = pv.Show(moved, view)
        pv.ColorBy(d, ("POINTS", attr + "_mm"))
        d.LineWidth = 3
        label = pv.Show(pv.Text(Text="t = %.3g ms" % (t * 1e3)), view)
        label.Color, label.FontSize, label.WindowLocation = [0, 0, 0], 11, "Any Location"
        label.Position = [0.01, centres[k][1] + 0.02] if beam else [centres[k][0] - 0.05, 0.85]
    lut.AutomaticRescaleRangeMode = "Never"  # one scale for every panel: the range over the times drawn
    lut.RescaleTransferFunction(lo * 1e3, hi * 1e3)
    d.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = {"y": "y (mm)", "w": "w (mm)", "W": "W_n (mm)"}.get(attr, attr), ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = bar.LabelFontSize = 10
    bar.WindowLocation, bar.Position, bar.ScalarBarLength = "Any Location", [0.84, 0.12], 0.72
    bar.RangeLabelFormat = "%-#.2g"
    pv.SaveScreenshot(a.output, view, ImageResolution=a.size, TransparentBackground=0)
    print("%s: the %s of %s at t = %s ms, displaced x %.3g, into %s" % (
        PROG, field, os.path.basename(xmf), ", ".join("%.3g" % (t * 1e3) for t in times), scale, a.output))


def hand_over():
    """Run this script again where ParaView can draw: under pvpython when this Python lacks
    ParaView's modules, in a virtual display (xvfb-run) when there is none; or say what is missing."""
    cmd = [sys.executable, os.path.abspath(__file__)] + sys.argv[1:]
    if pv is None:
        cmd[0] = shutil.which("pvpython")
        if not cmd[0]:
            fail("needs ParaView's pvpython, and there is none on PATH (Debian: apt-get install paraview); "
                 "nothing was drawn")
    if not os.environ.get("DISPLAY"):  # Debian's ParaView renders through X: a virtual display
        xvfb = shutil.which("xvfb-run")
        if not xvfb:
            fail("no display (DISPLAY is unset) and no xvfb-run to make one (Debian: apt-get install xvfb); "
                 "nothing was drawn")
        cmd = [xvfb, "-a", "-s", "-screen 0 1920x1080x24"] + cmd
    sys.stdout.flush()
    os.execv(cmd[0], cmd)


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 2)[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="FILE.xmf written by beamimpact beside FILE.h5 (-task impact, -snapshot_times)")
    ap.add_argument("-o", "--output", required=True, help="out.png")
    ap.add_argument("--field", choices=("beam", "bed", "wall"), help="what to draw (default: bed, else wall, else beam)")
    ap.add_argument("--times", default="", help="t1,t2,... in s (default: three through the file's times)")
    ap.add_argument("--scale", type=float, default=0, help="magnification of the displacements (default: automatic)")
    ap.add_argument("--size", default="1500x520", help="image size in pixels, WIDTHxHEIGHT (default 1500x520)")
    a = ap.parse_args()
    try:
        a.size = [int(v) for v in a.size.lower().split("x")]
    except ValueError:
        fail("--size %s: give WIDTHxHEIGHT in pixels, e.g. 1500x520" % a.size)
    if pv is None or not os.environ.get("DISPLAY"):
        hand_over()
    if not a.file.endswith(".xmf"):
        fail("%s: give the .xmf description beamimpact writes beside the .h5 (FILE.xmf for FILE.h5)" % a.file)
    if not os.path.isfile(a.file):
        fail("%s does not exist (beamimpact writes it beside the .h5 of a -task impact run with -snapshot_times)" % a.file)
    have = collections(a.file)
    names = [c[0] for c in have]
    field = a.field or next(f for f in ("bed", "wall", "beam") if f in names)
    if field not in names:
        fail("%s has no %s snapshots (it has: %s)" % (a.file, field, ", ".join(names)))
    index = names.index(field)
    times = pick_times(a.times, have[index][2])
    draw(a, os.path.abspath(a.file), index, len(names), field, have[index][1], times)
    # the image is written: leave without ParaView's teardown, which under Xvfb (Mesa) can die on
    # its X window and turn a finished drawing into a failed command
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


if __name__ == "__main__":
    sys.exit(main())
