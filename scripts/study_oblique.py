#!/usr/bin/env python3
"""The tables of scripts/study_oblique.sh: the program's sweeps over the offset beside the
rigid-body impulse model of scripts/references/oblique.py (the experiments' parameters, the
program's own normal restitution) and the published statements.

    /usr/bin/python3 scripts/study_oblique.py nathan2012|kensrud2017 OUT_DIR
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "references"))

from beamimpact import files, tables  # noqa: E402

import numpy as np  # noqa: E402
import oblique as ref  # noqa: E402  (scripts/references/oblique.py)

PROG = "study_oblique.py"


def rows(path):
    """impact_offset, acor, bbs, launch_angle, spin_rpm, bat_vibration_tangential of a sweep, by offset."""
    f = files.open_file(PROG, path)
    r = f["results"]
    if np.any(files.status(r, r["impact_offset"].shape[0]) != 0):
        sys.exit("%s: %s has failed points" % (PROG, path))
    order = np.argsort(r["impact_offset"][()])
    get = lambda c: r[c][()][order] if c in r else np.full(len(order), np.nan)  # noqa: E731
    return {c: get(c) for c in ("impact_offset", "acor", "bbs", "launch_angle", "spin_rpm", "exit_speed", "bat_vibration_tangential")}


def fmt_table(title, head, body, fmts):
    tables.print_table(title, head, body, fmts, min_width=8)


def nathan2012(out):
    ball = ref.Ball()
    R = 1.5 * ref.INCH
    v = 100 * ref.MPH
    for eT in (0.2, 0.4):
        flex, rig = rows(os.path.join(out, "nathan-eT%g.h5" % eT)), rows(os.path.join(out, "nathan-eT%g-rigid.h5" % eT))
        body = []
        for k, D in enumerate(flex["impact_offset"]):
            e = flex["acor"][k]  # the fixed cylinder: the normal run's rebound over the normal speed
            th, _, ang, spin, slid = ref.fixed_cylinder(ball, R, v, D, e, eT, mu=0.5)
            _, _, ang0, roll, _ = ref.fixed_cylinder(ball, R, v, D, e, 0.0)
            body.append([D / ref.INCH, th, e, flex["launch_angle"][k], flex["spin_rpm"][k], rig["spin_rpm"][k], ang, spin, roll,
                         flex["spin_rpm"][k] / roll if roll > 0 else np.nan, flex["bat_vibration_tangential"][k]])
        fmt_table("Nathan et al. 2012 set-up: baseball at 100 mph, no spin, on a fixed 3-in wood cylinder (clamped, 30 cm); mu 0.5, e_T %g" % eT,
                  ["D in", "theta deg", "e (acor)", "angle deg", "spin rpm", "spin rigid-plane", "model angle", "model spin", "rolling spin", "spin/rolling", "vib. J"], body,
                  ["%.2f", "%.2f", "%.3f", "%.2f", "%.0f", "%.0f", "%.2f", "%.0f", "%.0f", "%.3f", "%.2e"])
    print("""
Published (Nathan et al. 2012, the abstract; the measured points were not found): the spin is
"considerably larger" than rolling and nearly independent of the incident spin, i.e. e_T > 0 in
the impulse model. The program: spin/rolling is 1 + e_T on the rigid plane (the contact grips
throughout: at mu 0.5 the impulse model slides throughout only beyond tan theta =
mu (1 + e)(1 + alpha)/((1 + e_T) alpha), theta about 65 deg here), 0.3-0.5 % less on the
flexible one. (D = 0 is head-on: the oblique columns do not apply, NaN.) The differences from
the impulse model:
  * e_T is set on the contact's own normal force (the tangential spring's stiffness follows F_n,
    the length l from e_T for a grip throughout), the model takes it as a restitution of the
    whole impulse: equal where it grips throughout, different where it slides part of the time
    (the program slides at the start and may grip again: micro-slip, which the impulse model's
    single cap cannot represent);
  * the cylinder is clamped, not rigid: its modes (flexible plane) take a little of the
    tangential energy (vib. J), so the flexible plane's spin is below the rigid plane's;
  * e is the program's own along the normal (the baseball's e(v) at v cos theta), given to the
    model point by point.""")


def kensrud2017(out):
    ball = ref.Ball()
    prof = os.path.normpath(os.path.join(HERE, "..", "options", "bats", "r161.profile"))
    M, xc, Icm, Iax, xi, Ri = ref.bat_from_profile(prof, 649.0, 0.15)
    Meff = 1.0 / (1.0 / M + (xi - xc) ** 2 / Icm)
    V = 75 * ref.MPH
    flex, rig = rows(os.path.join(out, "kensrud.h5")), rows(os.path.join(out, "kensrud-rigid.h5"))
    # e: the restitution of the impulse model that gives the program's head-on batted-ball speed
    target = flex["bbs"][np.argmin(np.abs(flex["impact_offset"]))]
    lo, hi = 0.0, 1.0
    for _ in range(60):
        e = 0.5 * (lo + hi)
        _, speed, _, _ = ref.swinging_bat(ball, ref.Cylinder(Ri, Meff, Iax), V, 0.0, e, 0.0, ball_speed=0.0)
        lo, hi = (e, hi) if speed < target else (lo, e)
    body = []
    for k, D in enumerate(flex["impact_offset"]):
        ang, speed, spin, _ = ref.swinging_bat(ball, ref.Cylinder(Ri, Meff, Iax), V, D, e, 0.4, mu=0.5, ball_speed=0.0)
        _, _, roll, _ = ref.swinging_bat(ball, ref.Cylinder(Ri, Meff, Iax), V, D, e, 0.0, ball_speed=0.0)
        body.append([D / ref.INCH, flex["exit_speed"][k] / ref.MPH, flex["launch_angle"][k], flex["spin_rpm"][k], rig["spin_rpm"][k], speed / ref.MPH, ang, spin, roll,
                     flex["spin_rpm"][k] / roll if roll > 0 else np.nan, flex["bat_vibration_tangential"][k]])
    fmt_table("Kensrud, Nathan & Smith 2017 set-up: the R161 (Timoshenko, free) at 75 mph at the impact point, 15 cm from the tip, onto a ball at rest; mu 0.5, e_T 0.4; "
              "the model's e = %.4f (the program's head-on bbs), M_eff %.4f kg, I_axis %.3e kg m^2" % (e, Meff, Iax),
              ["D in", "exit mph", "angle deg", "spin rpm", "spin rigid-plane", "model mph", "model angle", "model spin", "rolling spin", "spin/rolling", "vib. J"], body,
              ["%.2f", "%.1f", "%.2f", "%.0f", "%.0f", "%.1f", "%.2f", "%.0f", "%.0f", "%.3f", "%.2e"])
    print("""
Published (Kensrud, Nathan & Smith 2017, the abstract; the measured points were not found):
launch angles 0-30 deg, spins 0-3500 rpm, spin "up to 40 % greater than" rolling. The program
at e_T 0.4 spans the same ranges over 0-1.5 in of offset, at 1.3-1.4 times rolling where the
contact grips; the differences from the impulse model:
  * the bat is flexible in both planes (the normal run's e(v) of the baseball and the bat's
    vibration; along t its modes), the model's bat a rigid body of effective mass M_eff: the
    exit speed agrees by construction of e at D = 0, and within a few tenths of a mph elsewhere;
  * the roll of the bat about its axis (I_axis from the profile) is in both;
  * e_T on the contact's own force against a restitution of the impulse (see nathan2012);
  * the ball at rest, as in their tests (a ball on a tee struck by the swinging bat).""")


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("nathan2012", "kensrud2017"):
        sys.exit("usage: %s nathan2012|kensrud2017 OUT_DIR" % PROG)
    {"nathan2012": nathan2012, "kensrud2017": kensrud2017}[sys.argv[1]](sys.argv[2])


if __name__ == "__main__":
    main()
