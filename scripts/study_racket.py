#!/usr/bin/env python3
"""The tables of scripts/study_racket.sh: the strung racket (options/bats/racket-pure-drive.opts,
options/balls/tennis-ball-fast.opts) beside the published anchors, and beside the rigid-frame
model those papers use (Goodwill & Haake 2001, Kawazoe 2002 Eq. 11: the ball-on-bed restitution
of the head-clamped racket, e_c, and the racket's effective mass at the impact point).

    /usr/bin/python3 scripts/study_racket.py sites|tension|modes OUT_DIR

Sources and what was and was not found: scripts/references/README.md, docs/racket-anchors.md.
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from beamimpact import files, tables  # noqa: E402

import numpy as np  # noqa: E402

PROG = "study_racket.py"
XC = 0.5075          # the head's centre from the butt (racket-pure-drive.opts)
L = 0.685
HEAD_AREA = math.pi * 0.335 / 2 * 0.245 / 2
LAMBDA = 1.51e-3
M_BALL = 0.057


def load(out, name, cols):
    path = os.path.join(out, name + ".h5")
    f = files.open_file(PROG, path)
    r = f["results"]
    n = r["acor"].shape[0]
    if np.any(files.status(r, n) != 0):
        sys.exit("%s: %s has failed points" % (PROG, path))
    got = {c: (r[c][()] if c in r else np.full(n, np.nan)) for c in cols}
    if "vibration_fraction" in got and "bed_fraction" in r:  # the racket's vibration, frame and strings (the bending alone since issue 34)
        got["vibration_fraction"] = got["vibration_fraction"] + r["bed_fraction"][()] + (r["twist_fraction"][()] if "twist_fraction" in r else 0.0)
    return got


def racket_inertia(out, name):
    """Mass, centre of mass, I about it and about the long axis, from the run's log."""
    with open(os.path.join(out, name + ".log")) as f:
        for line in f:
            m = re.search(r"mass ([\d.eE+-]+) kg, centre of mass ([\d.eE+-]+) m from x = 0, moment of inertia ([\d.eE+-]+) kg m\^2 about it, "
                          r"[\d.eE+-]+ kg m\^2 about x = 0, ([\d.eE+-]+) kg m\^2 about its axis", line)
            if m:
                return tuple(float(g) for g in m.groups())
    sys.exit("%s: no inertia line in %s.log" % (PROG, name))


def table(title, head, body, fmts):
    tables.print_table(title, head, body, fmts, min_width=7)


def rigid_acor(e_c, inv_me):
    """Kawazoe 2002 Eq. 11 (and Goodwill & Haake's rigid frame): e = (e_c - m_b/M_e)/(1 + m_b/M_e)."""
    R = M_BALL * inv_me
    return (e_c - R) / (1 + R)


def clamped_cor(out):
    """e_c(tension, speed) of the head-clamped racket, linear in speed between the sweep's points."""
    c = load(out, "clamped", ("strings_tension", "ball_speed", "acor"))
    out_ = {}
    for T in np.unique(c["strings_tension"]):
        k = c["strings_tension"] == T
        o = np.argsort(c["ball_speed"][k])
        out_[float(T)] = (c["ball_speed"][k][o], c["acor"][k][o])
    return lambda T, v: float(np.interp(v, *out_[float(T)]))


def sites(out):
    M, xcm, Icm, Ix = racket_inertia(out, "modes-free")
    ec = clamped_cor(out)
    print("racket: mass %.4f kg, centre of mass %.4f m from the butt, I_cm %.5f kg m^2, about its axis %.6f kg m^2" % (M, xcm, Icm, Ix))

    # Glynn et al.'s grid
    g = load(out, "glynn", ("strings_tension", "impact_x", "impact_z", "ball_speed", "acor", "contact_time"))
    xs, zs, vs = np.unique(g["impact_x"]), np.unique(g["impact_z"]), np.unique(g["ball_speed"])
    for T in np.unique(g["strings_tension"]):
        body, errs = [], []
        for v in vs:
            row = [v]
            for z in zs:
                for x in xs:
                    k = (g["strings_tension"] == T) & (g["impact_x"] == x) & (g["impact_z"] == z) & (g["ball_speed"] == v)
                    a = float(g["acor"][k][0])
                    rig = rigid_acor(ec(T, v), 1 / M + (x - xcm) ** 2 / Icm + z ** 2 / Ix)
                    row.append(a * v)
                    errs.append(rig / a - 1)
            body.append(row)
        head = ["v_in"] + ["%+.0f,%.0f" % ((x - XC) * 100, z * 100) for z in zs for x in xs]
        table("Glynn et al. 2011 grid, free racket, %g N: rebound speed (m/s) at the sites (dx from the head's centre, z across; cm)" % T,
              head, body, ["%.1f"] + ["%.2f"] * (len(head) - 1))
        errs = np.array(errs)
        print("  rigid frame (Kawazoe Eq. 11 with this tension's clamped e_c) over the program, all %d points: mean %+.1f %%, from %+.1f to %+.1f %%, RMS %.1f %%"
              % (len(errs), 100 * errs.mean(), 100 * errs.min(), 100 * errs.max(), 100 * math.sqrt(np.mean(errs ** 2))))
    T0, T1 = np.unique(g["strings_tension"])[[0, -1]]
    d = []
    for x in xs:
        for z in zs:
            for v in vs:
                a = [float(g["acor"][(g["strings_tension"] == T) & (g["impact_x"] == x) & (g["impact_z"] == z) & (g["ball_speed"] == v)][0]) for T in (T0, T1)]
                d.append(a[1] / a[0] - 1)
    print("  %g N over %g N: rebound speed %+.1f %% to %+.1f %% over the grid" % (T1, T0, 100 * min(d), 100 * max(d)))
    print("""Published (Glynn, King & Mitchell 2011, abstract): their lumped model (two rigid segments, 9 masses and
24 springs for the bed, a point-mass visco-elastic ball) matched measured rebound speeds at 9 sites,
6 speeds, 2 frames x 2 tensions with < 3 % RMS error "over the 16-27 m/s range observed". Their
sites, tensions, racket parameters and measured speeds were not found: the grid above is ours,
for comparison when they are.""")

    # Across the face at 16.5 m/s
    a = load(out, "across", ("impact_z", "acor", "roll_fraction", "contact_time"))
    o = np.argsort(a["impact_z"])
    body = []
    for k in o:
        z = a["impact_z"][k]
        pub = "about 0.4" if z < 0.01 else ("0.1-0.2 (0.3 with 27 g at 3 and 9 o'clock)" if z >= 0.06 else "")
        body.append([z * 1000, a["acor"][k], 16.5 * a["acor"][k], a["roll_fraction"][k], rigid_acor(ec(270, 16.5), 1 / M + (XC - xcm) ** 2 / Icm + z ** 2 / Ix), pub])
    print()
    table("Across the face at the head's centre, 16.5 m/s, free racket, 250 N (Cross & Lindsey: hand-held 291 g racket, 16.5 m/s)",
          ["z mm", "ACOR", "v_out", "roll frac", "rigid Eq.11", "published ACOR"], body, ["%.0f", "%.3f", "%.2f", "%.3f", "%.3f", "%s"])
    print("""Published (Cross & Lindsey, "Racquet Control - Part 1", TWU, hand-held 291 g racket, 16.5 +- 1 m/s,
impacts from 80 mm on one side of the axis to 60 mm on the other): ACOR "typically about 0.4 in the
middle of the strings and about 0.1 or 0.2 near the frame, regardless of the speed of the incoming
ball"; with 26.8 g of bolts at 3 and 9 o'clock about 0.3 near the frame. (rigid Eq.11: e_c of the
clamped bed at 270 N, the nearest sweep to 250 N.)""")

    # Goodwill & Haake: the head clamped
    c = load(out, "clamped", ("strings_tension", "ball_speed", "acor", "contact_time", "bed_deflection_peak", "max_compression", "peak_force"))
    o = np.lexsort((c["ball_speed"], c["strings_tension"]))
    wall = lambda v: float(np.interp(v, [7.06, 30.0], [0.745, 0.66]))  # noqa: E731  (tennis-ball-fast-cor.txt)
    body = [[c["strings_tension"][k], c["ball_speed"][k], c["acor"][k], wall(c["ball_speed"][k]), 1e3 * c["contact_time"][k], 1e3 * c["bed_deflection_peak"][k],
             1e3 * c["max_compression"][k], c["peak_force"][k]] for k in o]
    print()
    table("Head clamped (-strings_frame held), struck at the string centre: the ball-on-bed restitution e_c",
          ["T N", "v_in", "e_c", "e wall", "dwell ms", "bed mm", "ball mm", "F N"], body, ["%.0f", "%.1f", "%.3f", "%.3f", "%.2f", "%.1f", "%.1f", "%.0f"])
    ecs = c["acor"]
    print("  e_c from %.3f to %.3f over 210-270 N and 15-30 m/s (a spread of %.1f %%); the wall's e falls %.1f %% over 15-30 m/s"
          % (ecs.min(), ecs.max(), 100 * (ecs.max() / ecs.min() - 1), 100 * (1 - wall(30) / wall(15))))
    print("""Published: Kawazoe 2002 (ACMD'02, Fig. 6): with the head clamped, the ball-strings restitution is
"almost independent of ball velocity and strings tension" while the wall's falls with speed
(Fig. 5; values not read from the figures). Goodwill & Haake 2001 (abstract): head-clamped, central
impacts, "good agreement" of modelled and measured rebound speed and largest bed deflection; their
numbers were not found. Haake, Carre & Goodwill 2003: on a clamped racket the COR falls with speed
and lower tension gives "a smaller range".""")

    # Goodwill & Haake: pinned at the tip
    p = load(out, "tip-pinned", ("impact_x", "acor", "vibration_fraction", "contact_time"))
    o = np.argsort(p["impact_x"])
    Ip = Icm + M * (L - xcm) ** 2
    body = []
    for k in o:
        x = p["impact_x"][k]
        rig = rigid_acor(ec(270, 25.0), (L - x) ** 2 / Ip)
        body.append([(x - XC) * 100, p["acor"][k], 25 * p["acor"][k], 1e3 * p["contact_time"][k], rig, 100 * (rig / p["acor"][k] - 1)])
    print()
    table("Pinned at the tip (-beam_right pinned), on the axis, 25 m/s, 250 N; rigid frame: Eq. 11 about the pin with e_c (270 N)",
          ["dx cm", "ACOR", "v_out", "dwell ms", "rigid", "rigid/prog %"], body, ["%+.0f", "%.3f", "%.2f", "%.2f", "%.3f", "%+.1f"])
    print("""Published (Goodwill & Haake 2001, abstract): the racket freely suspended at the tip on a pin, 3 sites
on the long axis: ball rebound speed in good agreement at the string centre; their rigid-frame
model over-predicted the racket's rebound velocity, "generally by less than 5 per cent", which they
put down to the frame's vibration. Their speeds, sites and numbers were not found.""")


def tension(out):
    cols = ("ball_speed", "strings_tension", "acor", "contact_time", "bed_deflection_peak", "max_compression", "vibration_fraction", "ball_loss_fraction", "peak_force")
    t, s = load(out, "tension", cols), load(out, "tension-stiff", cols)
    for v in np.unique(t["ball_speed"]):
        body = []
        k = np.where(t["ball_speed"] == v)[0]
        k = k[np.argsort(t["strings_tension"][k])]
        ks = np.where(s["ball_speed"] == v)[0]
        ks = ks[np.argsort(s["strings_tension"][ks])]
        for i, j in zip(k, ks):
            body.append([t["strings_tension"][i], t["acor"][i], v * t["acor"][i], 1e3 * t["contact_time"][i], 1e3 * t["bed_deflection_peak"][i], 1e3 * t["max_compression"][i],
                         t["ball_loss_fraction"][i], t["vibration_fraction"][i], s["acor"][j], 100 * (s["acor"][j] / t["acor"][i] - 1), s["vibration_fraction"][j]])
        table("Tension, free racket struck at the head's centre, %g m/s (stiff: the frame's EI doubled)" % v,
              ["T N", "ACOR", "v_out", "dwell ms", "bed mm", "ball mm", "ball loss", "vib frac", "ACOR stiff", "stiff %", "vib stiff"], body,
              ["%.0f", "%.4f", "%.2f", "%.2f", "%.1f", "%.1f", "%.3f", "%.4f", "%.4f", "%+.1f", "%.4f"])
        T = t["strings_tension"][k]
        a220, a270 = np.interp(220, T, t["acor"][k]), np.interp(270, T, t["acor"][k])
        d220, d270 = np.interp(220, T, t["contact_time"][k]), np.interp(270, T, t["contact_time"][k])
        print("  220 -> 270 N: ACOR %.4f -> %.4f (%+.1f %%), dwell %.2f -> %.2f ms (%+.1f %%)" % (a220, a270, 100 * (a270 / a220 - 1), 1e3 * d220, 1e3 * d270, 100 * (d270 / d220 - 1)))
    print("""Published (Cross 2000, abstract): for 220-270 N and a ball at right angles to the strings, "changes in
racket power and control are essentially negligible", the gain at low tension coming partly from
less energy lost in the ball and partly from less vibration; "a significant increase in racket
power can be achieved by increasing the stiffness of the racket frame". Lindsey (TWU, "stringbeds"):
"string tension and material have only a small effect on ball speed". USRSA: dwell time "typically
.004-.005 seconds", longer for softer strings. Cross's own numbers (his figures) were not found.""")
    b = load(out, "bower", ("ball_speed", "strings_tension", "acor"))
    v_play = 108.1 / 3.6  # m/s: Bower & Cross's mean rebound speed at 180 N
    body = []
    for v in np.unique(b["ball_speed"]):
        lo = float(b["acor"][(b["ball_speed"] == v) & (b["strings_tension"] == 180)][0])
        hi = float(b["acor"][(b["ball_speed"] == v) & (b["strings_tension"] == 280)][0])
        # the same swing: v_out = e_A v_rel + V (lab frame), so 180 -> 280 N changes it by dE_A v_rel
        body.append([v, lo, hi, hi - lo, 100 * (hi - lo) * v / v_play])
    table("180 -> 280 N in play (Bower & Cross 2005): free racket at the head's centre, relative speed v_rel",
          ["v_rel m/s", "ACOR 180", "ACOR 280", "dACOR", "dv_out %"], body, ["%.0f", "%.4f", "%.4f", "%+.4f", "%+.1f"])
    print("""  dv_out: the change of the ball's speed off a racket swung the same, dACOR v_rel, over their 108.1 km/h
  (v_out = e_A v_rel + V in the ground's frame: V, the racket's speed at the impact, cancels).
Published (Bower & Cross 2005, abstract; J. Sports Sci. 23, 765): players stroking balls from a ball
machine cross-court with three rackets at 180 and 280 N: 108.1 +- 9.9 km/h at 180 N, 105.3 +- 9.6 km/h
at 280 N (-2.6 %, P < 0.05). Their ball and swing speeds and impact sites were not found: the
relative speed is ours (their rebound ~30 m/s off a groundstroke), and the sites of play spread
over the face where the program strikes the centre.""")


def modes_lines(out, name):
    rows = []
    with open(os.path.join(out, name + ".log")) as f:
        for line in f:
            m = re.match(r"\s+(\d+)\s+([\d.]+)\s+([\d.]+)\s+(\w+)\s+(\d+)%", line)
            if m:
                rows.append((int(m.group(1)), float(m.group(2)), m.group(4), int(m.group(5))))
    return rows


def modes(out):
    free = modes_lines(out, "modes-free")
    stiff = modes_lines(out, "modes-free-stiff")
    first = lambda rows, fam: next((r[1] for r in rows if r[2] == fam), float("nan"))  # noqa: E731
    print("\nThe free strung racket (-task modes): the lowest flexible modes")
    for r in free[:8]:
        print("  %2d  %8.1f Hz  %-8s %3d %%" % r)
    held = {}
    for T in (250, 175):
        f = files.open_file(PROG, os.path.join(out, "modes-held-%d.h5" % T))
        held[T] = float(f["modes"]["frequency"][0])
    cross = lambda T: math.sqrt(T / LAMBDA) / (2 * math.sqrt(HEAD_AREA))  # noqa: E731
    body = [["frame: first bending (free)", first(free, "bending"), "100-150 Hz (issue 25, quoting Brody, Cross & Lindsey; not reached)"],
            ["frame: first bending, EI doubled", first(stiff, "bending"), ""],
            ["frame: first roll (free)", first(free, "roll"), "not found (ours: about 400)"],
            ["bed on the free frame: first strings mode", first(free, "strings"), ""],
            ["bed, held frame, 250 N", held[250], "Cross 2006 formula: %.0f Hz" % cross(250)],
            ["bed, held frame, 175 N (30 % lost on stringing)", held[175], "500-700 Hz measured (Cross 2006); formula %.0f Hz" % cross(175)]]
    print()
    w = max(len(b[0]) for b in body)
    print("%s  %9s  %s" % ("".ljust(w), "program", "published"))
    for b in body:
        print("%s  %7.1f Hz  %s" % (b[0].ljust(w), b[1], b[2]))
    print("""Cross 2006's formula f = sqrt(T/(4 m L)), m = lambda L the mass of a string of length L = sqrt(A)
(A = %.0f cm^2, lambda = %.2f g/m): a square membrane of the same area and tension. The tension in a
strung racket is about 30 %% below the pull tension (Cross & Bower 2001), hence the 175 N row.""" % (HEAD_AREA * 1e4, LAMBDA * 1e3))


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("sites", "tension", "modes"):
        sys.exit(__doc__)
    {"sites": sites, "tension": tension, "modes": modes}[sys.argv[1]](sys.argv[2])


if __name__ == "__main__":
    main()
