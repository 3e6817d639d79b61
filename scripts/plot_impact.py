#!/usr/bin/env python3
"""Plots of one beamimpact -task impact file (or a -task modes file), as PNGs.

    scripts/plot_impact.py FILE.h5 [-o PREFIX] [--force] [--energy] [--snapshots] [--mode-energies] [--modes] [--full]

Draws what the file holds and nothing it does not (every curve is read, none computed):
  PREFIX-force.png      the contact force against time (/series/force: run with -monitor_ball),
                        with the located events of /events marked: contact start, maximum
                        compression, reload, separation; zoomed to the contacts (--full: the
                        whole run);
  PREFIX-energy.png     the energies against time (-monitor_energy): ball kinetic, stored and
                        dissipated, beam kinetic and strain, dissipated by the beam's damping
                        (a damped beam), the grip's (with -grip), and their total; below, the
                        energy error (E(t) - E(0)) / E(0) of the recorded total;
  PREFIX-snapshots.png  the beam's displacement y(x) at the snapshot times (-snapshot_times),
                        the impact point marked (at most --curves of them, evenly chosen);
  PREFIX-mode-energies.png  where the impact's energy went, mode by mode (/modes_energy: written when
                        the free flight after the separation is modal, the default): bars of the
                        fraction of the energy brought in, E_in, in the ball's rebound and loss,
                        the damping, each rigid mode (translation, rotation, roll) and each
                        flexible mode at the end, labelled by its part (bending, roll, wall,
                        strings: /modes_energy/part) and coloured by it (the first --mode-bars of
                        them, the rest as one bar), from /results and /modes_energy; it prints
                        each part's sum beside the /results column it adds up to;
  PREFIX-modes.png      for a -task modes file: the flexible mode shapes (scaled to unit
                        peak) with their frequencies in the legend, and the nodes of the first
                        two modes the file records (/modes/nodes_1, nodes_2).
PREFIX defaults to FILE without .h5. Each legend or title carries the configuration from the
file's attributes (N, L, supports, the ball's mass and speed, the impact point, ts_type).

Without --force/--energy/--snapshots/--mode-energies/--modes every plot the file allows is drawn and the others
are named with the option that makes them. Asking for one the file lacks is an error (exit
status 1) naming the option to add, e.g. `--energy` on a file run without -monitor_energy.
For example, from the repository root:

    mkdir -p out
    build/release/beamimpact -options_file options/scenes/animation.opts -output out/animation.h5
    scripts/plot_impact.py out/animation.h5 -o out/animation
    build/release/beamimpact -options_file options/scenes/modes.opts -output out/modes.h5
    scripts/plot_impact.py out/modes.h5          # writes out/modes-modes.png
"""
import argparse
import os
import sys
import textwrap

from beamimpact import checks, files, labels, style

import numpy as np

plt = style.plt

PROG = "plot_impact.py"
EVENTS = {0: ("contact start", "^", "C2"), 1: ("maximum compression", "o", "C3"), 2: ("reload", "s", "C4"), 3: ("separation", "v", "C0")}
ENERGIES = [("ball_kinetic", "ball kinetic"), ("ball_stored", "ball stored"), ("ball_dissipated", "ball dissipated"),
            ("beam_kinetic", "beam kinetic"), ("beam_strain", "beam strain"), ("beam_dissipated", "beam damping (dissipated)"),
            ("grip_stored", "grip stored"), ("hand_work", "work of the hands")]


def legend(ax, f, impact=True, extra="", **kw):
    """The legend, titled with the configuration read from the file (wrapped)."""
    lines = textwrap.wrap(labels.config_label(f, impact), 70) + (textwrap.wrap(extra, 70) if extra else [])
    ax.legend(title="\n".join(lines), title_fontsize=7, fontsize=7, **kw)


def save(fig, out):
    """Lays out, writes and closes the figure; returns its path."""
    return style.save(fig, out, dpi=120)


def force_plot(f, path, out, full):
    s = f["series"]
    t, F = s["time"][()], s["force"][()]
    ev_t = f["events/time"][()] if "events" in f else np.array([])
    ev_k = f["events/kind"][()].astype(int) if "events" in f else np.array([], int)
    ev_F = f["events/force"][()] if "events" in f else np.array([])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(t * 1e3, F, "k", lw=1.2, label="contact force F (/series/force)")
    for k, (name, marker, col) in EVENTS.items():
        sel = ev_k == k
        if sel.any():
            ax.plot(ev_t[sel] * 1e3, ev_F[sel], marker, color=col, ms=8, mfc="white" if k == 3 else col, ls="none",
                    label="%s (%d)" % (name, sel.sum()))
            for te in ev_t[sel]:
                ax.axvline(te * 1e3, color=col, lw=0.6, ls=":")
    if not full and len(ev_t) and np.any(ev_k == 3):
        t_end = ev_t.max()
        ax.set_xlim(0, min(t[-1], 1.15 * t_end) * 1e3)
        zoom = "\nzoomed to the contacts (--full: the whole run, %.3g ms)" % (t[-1] * 1e3)
    else:
        zoom = ""
    r = f["results"]
    extra = []
    for name, fmt in (("peak_force", "peak force %.4g N"), ("contact_time", "contact time %.4g ms"), ("contacts", "%d contact(s)"), ("acor", "acor %.5g")):
        if name in r:
            v = float(r[name][0])
            extra.append(fmt % (v * 1e3 if name == "contact_time" else v))
    ax.set_xlabel("time t (ms)")
    ax.set_ylabel("contact force F (N)")
    ax.grid(True, alpha=0.3)
    legend(ax, f, extra=", ".join(extra), loc="best")
    ax.set_title("Contact force: %s%s" % (os.path.basename(path), zoom), fontsize=9)
    return save(fig, out)


def energy_plot(f, path, out):
    s = f["series"]
    t = s["time"][()] * 1e3
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True, gridspec_kw=dict(height_ratios=[3, 1.4]))
    for i, (name, lab) in enumerate(ENERGIES):
        if name in s:
            ax.plot(t, s[name][()], color="C%d" % i, lw=1.2, label=lab)
    tot = s["total_energy"][()]
    ax.plot(t, tot, "k--", lw=1.4, label="total (/series/total_energy)")
    ax.set_ylabel("energy (J)")
    ax.grid(True, alpha=0.3)
    ax.set_ylim(top=ax.get_ylim()[1] * 1.55)  # room above the curves for the legend
    legend(ax, f, loc="upper center", ncol=3)
    e0 = tot[0]
    err = (tot - e0) / e0 if e0 != 0 else tot - e0
    res = f["results"]
    lab = "(E(t) - E(0)) / E(0)%s" % ("" if e0 != 0 else " (E(0) = 0: absolute, J)")
    if "energy_error" in res:
        lab += "; /results/energy_error %.3g" % float(res["energy_error"][0])
    ax2.plot(t, err, "C3", lw=1.2, label=lab)
    ax2.axhline(0, color="0.5", lw=0.6)
    ax2.set_ylabel("energy error")
    ax2.set_xlabel("time t (ms)")
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=8, loc="best")
    ax2.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
    ax.set_title("Energies: %s; E(0) = %.6g J" % (os.path.basename(path), e0), fontsize=9)
    return save(fig, out)


def support_marks(ax, f, L):
    """The clamped region shaded and the ends' supports named, from the attributes."""
    x0, x1 = files.attr(f, "beam_clamp_x0", -1), files.attr(f, "beam_clamp_x1", -1)
    if x0 is not None and x0 >= 0:
        ax.axvspan(x0, x1, color="0.85", zorder=0, label="clamped %g-%g m" % (x0, x1))
    for x, side in ((0.0, files.attr(f, "beam_left")), (L, files.attr(f, "beam_right"))):
        if side and side != "free":
            ax.plot([x], [0], "ks", ms=7, zorder=5)
            ax.annotate(side, (x, 0), textcoords="offset points", xytext=(0, -14), ha="center", fontsize=7)


def snapshots_plot(f, path, out, curves):
    g = f["snapshots"]
    x, ts, y = g["x"][()], g["time"][()], g["y"][()]
    n = len(ts)
    pick = np.unique(np.round(np.linspace(0, n - 1, min(curves, n))).astype(int)) if n > curves else np.arange(n)
    fig, ax = plt.subplots(figsize=(9, 4.8))
    cmap = plt.get_cmap("viridis")
    for j, k in enumerate(pick):
        ax.plot(x, y[k] * 1e3, color=cmap(j / max(len(pick) - 1, 1)), lw=1.3, label="t = %.4g ms" % (ts[k] * 1e3))
    ax.axhline(0, color="0.6", lw=0.6, ls=":")
    xi = files.impact_point(f)
    if xi is not None:
        ax.axvline(xi, color="C3", ls="--", lw=1, label="impact point x = %g m" % xi)
        ax.plot([xi], [0], marker="v", color="C3", ms=9, ls="none", transform=ax.get_xaxis_transform(), clip_on=False)
    support_marks(ax, f, float(files.attr(f, "beam_length", x[-1])))
    ax.set_xlabel("x (m) from the x = 0 end")
    ax.set_ylabel("displacement y (mm)")
    ax.grid(True, alpha=0.3)
    legend(ax, f, loc="best", ncol=2 if len(pick) > 6 else 1)
    shown = "" if len(pick) == n else " (%d of the %d snapshot times, evenly chosen; --curves)" % (len(pick), n)
    ax.set_title("Beam snapshots y(x): %s%s" % (os.path.basename(path), shown), fontsize=9)
    return save(fig, out)


def modes_plot(f, path, out, count):
    g = f["modes"]
    freq, shapes = g["frequency"][()], g["shapes"][()]
    x = f["beam/x"][()] if "beam" in f and "x" in f["beam"] else np.linspace(0, float(files.attr(f, "beam_length", 1.0)), shapes.shape[1])
    flex = [k for k in range(len(freq)) if freq[k] > 0][:count]
    rigid = int(np.sum(freq <= 0))
    nodes = [g[n][()] if n in g else np.array([]) for n in ("nodes_1", "nodes_2")]
    fig, ax = plt.subplots(figsize=(9, 4.8))
    for i, k in enumerate(flex):
        w = shapes[k] / np.max(np.abs(shapes[k]))
        lab = "mode %d: %.5g Hz" % (i + 1, freq[k])
        if i < 2 and len(nodes[i]):
            lab += ", nodes at %s m" % ", ".join("%.3f" % v for v in nodes[i])
        ax.plot(x, w, color="C%d" % i, lw=1.4, label=lab)
        if i < 2 and len(nodes[i]):
            ax.plot(nodes[i], np.zeros_like(nodes[i]), "o", color="C%d" % i, ms=7, mfc="white", zorder=5)
    ax.axhline(0, color="0.5", lw=0.5)
    support_marks(ax, f, float(files.attr(f, "beam_length", x[-1])))
    ax.set_xlabel("x (m) from the x = 0 end")
    ax.set_ylabel("deflection (scaled to unit peak)")
    ax.grid(True, alpha=0.3)
    legend(ax, f, impact=False, loc="best")
    note = "; %d rigid mode(s) (0 Hz) not drawn" % rigid if rigid else ""
    ax.set_title("Mode shapes: %s%s\nopen circles: the nodes of modes 1 and 2 the file records (/modes/nodes_1, nodes_2)"
                 % (os.path.basename(path), note), fontsize=9)
    return save(fig, out)


# A mode's label in /modes_energy/part (run/energy_parts.hpp) and the /results column its modes add up
# to: a rigid mode's motion, a flexible mode's part (as -task modes names it).
RIGID_COLUMNS = {"translation": "translation_fraction", "rotation": "rotation_fraction", "roll": "roll_fraction"}
PART_COLUMNS = {"bending": "vibration_fraction", "roll": "twist_fraction", "wall": "wall_fraction", "strings": "bed_fraction"}
PART_COLORS = {"bending": "C3", "roll": "C6", "wall": "C8", "strings": "C9"}


def mode_labels(g, rigid):
    """Each mode's label: /modes_energy/part, or (a file from before it) the free beam's rigid pair and 'bending'."""
    if "part" in g:
        return [p.decode() if isinstance(p, bytes) else str(p) for p in g["part"][()]]
    rk = np.flatnonzero(rigid)
    names = ["bending"] * len(rigid)
    for j, k in enumerate(rk):
        names[k] = ("translation", "rotation", "roll")[j] if len(rk) <= 3 else "rigid"
    return names


def part_sums(part, rigid, frac, r):
    """Lines: each label's modes summed, beside the /results column they add up to."""
    lines, done = [], set()
    for p, rg in zip(part, rigid):
        col = (RIGID_COLUMNS if rg else PART_COLUMNS).get(p)
        if (p, bool(rg)) in done:
            continue
        done.add((p, bool(rg)))
        total = float(np.sum(frac[(np.array(part) == p) & (rigid == rg)]))
        ref = float(r[col][0]) if col and col in r else float("nan")
        lines.append("%s%s %.6g (%s %.6g)" % ("rigid " if rg else "", p, total, col or "no column", ref))
    return lines


def mode_energies_plot(f, path, out, bars):
    g, r = f["modes_energy"], f["results"]
    freq, frac, rigid = g["frequency"][()], g["fraction"][()], g["rigid"][()].astype(bool)
    part = mode_labels(g, rigid)

    def col(name):
        return float(r[name][0]) if name in r else float("nan")

    names, vals, colors = [], [], []

    def bar(name, v, c):
        if np.isfinite(v) and (v != 0 or c == "C0"):
            names.append(name), vals.append(v), colors.append(c)

    rebound = col("rebound_fraction") if "rebound_fraction" in r else col("acor_corrected") ** 2  # files from before the column
    bar("ball rebound", rebound, "C0")
    bar("ball loss", col("ball_loss_fraction"), "C1")
    bar("beam damping", col("damping_fraction"), "C5")
    bar("grip (stored)", col("grip_fraction"), "C7")
    bar("to the hands", col("hands_fraction"), "C7")
    for k in np.flatnonzero(rigid):
        bar(part[k], frac[k], "C2")
    flex = np.flatnonzero(~rigid)
    for k in flex[:bars]:
        bar("%s\n%.4g Hz" % (part[k], freq[k]), frac[k], PART_COLORS.get(part[k], "C3"))
    if len(flex) > bars:
        bar("%d more modes" % (len(flex) - bars), float(np.sum(frac[flex[bars:]])), "C4")
    fig, ax = plt.subplots(figsize=(max(8, 0.55 * len(names) + 2), 4.8))
    x = np.arange(len(names))
    ax.bar(x, vals, color=colors)
    for xi, v in zip(x, vals):
        ax.annotate("%.3g" % v, (xi, v), textcoords="offset points", xytext=(0, 2), ha="center", fontsize=7)
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=45, ha="right", fontsize=7)
    ax.set_ylabel("fraction of the energy brought in, E_in")
    ax.grid(True, axis="y", alpha=0.3)
    sums = part_sums(part, rigid, frac, r)
    print("%s: mode energies by part (their /results column): %s" % (PROG, "; ".join(sums)))
    extra = "%d modes kept; by part: %s" % (len(freq), "; ".join(s for s in sums if not s.startswith("rigid")))
    legend(ax, f, extra=extra, handles=[], loc="upper right")
    ax.set_title("Where the impact's energy went, mode by mode, at t = %.4g ms: %s"
                 % (1e3 * float(g.attrs.get("time", float("nan"))), os.path.basename(path)), fontsize=9)
    return save(fig, out)


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 2)[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="HDF5 file written by beamimpact -task impact (or -task modes)")
    ap.add_argument("-o", "--output", metavar="PREFIX", help="output prefix (default: FILE without .h5)")
    ap.add_argument("--force", action="store_true", help="the contact force (needs -monitor_ball)")
    ap.add_argument("--energy", action="store_true", help="the energies (needs -monitor_energy)")
    ap.add_argument("--snapshots", action="store_true", help="the beam snapshots (needs -snapshot_times)")
    ap.add_argument("--mode-energies", action="store_true", help="the energy per mode at the end (a modal free flight, /modes_energy)")
    ap.add_argument("--modes", action="store_true", help="the mode shapes (a -task modes file)")
    ap.add_argument("--full", action="store_true", help="force plot over the whole run, not zoomed to the contacts")
    ap.add_argument("--curves", type=checks.count(1, "snapshot curves"), default=8, help="at most this many snapshot curves (default 8)")
    ap.add_argument("--mode-count", type=checks.count(1, "flexible modes to draw"), default=4, help="flexible modes to draw (default 4)")
    ap.add_argument("--mode-bars", type=int, default=8, help="flexible modes with a bar of their own in the mode energies (default 8)")
    a = ap.parse_args()
    prefix = a.output or files.default_prefix(a.file)
    asked = [w for w in ("force", "energy", "snapshots", "mode_energies", "modes") if getattr(a, w)]
    written = []
    with files.open_file(PROG, a.file) as f:
        task = files.attr(f, "task", "")
        if task in ("sweep", "convergence"):
            sys.stderr.write("%s: %s was written by -task %s: plot it with scripts/%s\n"
                             % (PROG, a.file, task, "plot_sweep.py" if task == "sweep" else "plot_convergence.py"))
            return 1
        possible = ("modes",) if task == "modes" else ("force", "energy", "snapshots", "mode_energies")
        for w in asked:
            if w not in possible:
                sys.stderr.write("%s: %s is a -task %s file: it holds no %s (%s)\n" % (PROG, a.file, task or "?", files.what_name(w), files.MAKES[w]))
                return 1
            if not files.has(f, w):
                files.missing(PROG, a.file, w)
        todo = asked or [w for w in possible if files.has(f, w)]
        if not asked:
            for w in possible:
                if not files.has(f, w):
                    print("%s: no %s plot: the file has no %s (run beamimpact with %s)" % (PROG, w, files.what_name(w), files.MAKES[w]))
        if not todo:
            sys.stderr.write("%s: %s holds nothing to plot: run beamimpact -task impact with -monitor_ball, -monitor_energy "
                             "or -snapshot_times t1,t2,... (e.g. -options_file options/scenes/animation.opts), or -task modes\n" % (PROG, a.file))
            return 1
        for w in todo:
            out = "%s-%s.png" % (prefix, w.replace("_", "-"))
            if w == "force":
                written.append(force_plot(f, a.file, out, a.full))
            elif w == "energy":
                written.append(energy_plot(f, a.file, out))
            elif w == "snapshots":
                written.append(snapshots_plot(f, a.file, out, max(a.curves, 1)))
            elif w == "mode_energies":
                written.append(mode_energies_plot(f, a.file, out, max(a.mode_bars, 1)))
            else:
                written.append(modes_plot(f, a.file, out, max(a.mode_count, 1)))
    for p in written:
        print("wrote", p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
