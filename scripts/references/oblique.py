#!/usr/bin/env python3
"""Oblique impact of a ball on a cylinder (bat) in the plane across the bat: launch angle and
spin against the offset, with Coulomb friction and tangential compliance. An independent
reference for the oblique impacts of issue 24 (MODEL.md section 10).

    /usr/bin/python3 scripts/references/oblique.py

(1) The rigid-body impulse model (Cross & Nathan 2006; Kensrud, Nathan & Smith 2017; Stronge,
'Impact Mechanics'). Ball: mass m, radius r, I_b = alpha m r^2, velocity v, spin w (about the
bat's axis, counter-clockwise positive). Bat cross-section: radius R, mass M (the effective mass
at the impact point, 1/M = 1/M_bat + b^2/I_cm for an impact b from the centre of mass; M = inf
for a fixed cylinder), moment of inertia I_a about its own axis (inf: no roll). Normal n from
the bat's axis to the ball's centre, tangent t = z x n. The relative velocity of the contact
points is g = (v - r w t) - (V + R W t). With 1/m_n = 1/m + 1/M and
1/m_t = 1/m + r^2/I_b + 1/M + R^2/I_a, the impulse on the ball P = P_n n + P_t t is

    P_n = -(1 + e) m_n g_n                           (normal restitution e, the BBCOR)
    P_t = -(1 + e_T) m_t g_t, but |P_t| <= mu P_n     (tangential restitution e_T, Coulomb mu)

and v' = v + P/m, w' = w - r P_t/I_b, V' = V - P/M, W' = W - R P_t/I_a. Limits (fixed
cylinder, ball without spin, speed v, sin(theta) = D/(r + R)):
  frictionless:  w' = 0, u_t' = u_t, u_n' = -e u_n   (mirror reflection about n when e = 1)
  rolling (e_T = 0, ample friction): u_t' = u_t/(1 + alpha), w' = u_t'/r
  tangential compliance: w' = (1 + e_T) v sin(theta) / ((1 + alpha) r), (1 + e_T) x rolling
  gross slip (tan theta > mu (1 + e)(1 + alpha)/((1 + e_T) alpha)): w' = mu (1 + e) v cos(theta)/(alpha r)

(2) A time-domain check: the ball against a fixed cylinder through a normal spring k_n (elastic,
or the program's hysteretic m = 1 law) and a tangential spring k_t with Coulomb friction
(elastic-perfectly-plastic: the spring force is capped at mu F_n, the lumped model of Cross,
Am. J. Phys. 70, 1093 (2002), after Maw, Barber & Fawcett). With ample friction the tangential
spring rings harmonically at w_t = sqrt(k_t/m_t) for the contact time T, so
e_T = -cos(w_t T) (for the elastic normal spring T = pi sqrt(m/k_n)): the ODE's spin must equal
the impulse model's with that e_T; with finite mu the two bracket the micro-slip.

(3) The experiments, with their parameters, and the model's launch angle and spin over the
offset: Nathan et al. 2012 (ball fired at a fixed 3-inch wood cylinder, up to 120 mph) and
Kensrud, Nathan & Smith 2017 (a swinging bat, 63-88 mph, on a ball at rest). Their measured
points are in figures not available here: README.md says what was found.
"""
import os
import sys

from _common import need, table  # noqa: E402

need(__file__, "numpy", "scipy")
from dataclasses import dataclass  # noqa: E402

import numpy as np  # noqa: E402

MPH = 0.44704     # m/s
INCH = 0.0254     # m
RPM = 30.0 / np.pi  # rpm per rad/s


@dataclass
class Ball:
    m: float = 0.145                      # kg
    r: float = 9.125 * INCH / (2 * np.pi)  # m (circumference 9.125 in)
    alpha: float = 0.4                    # I_b = alpha m r^2

    @property
    def I(self):
        return self.alpha * self.m * self.r ** 2


@dataclass
class Cylinder:
    R: float                 # m
    M: float = np.inf        # kg, effective mass in the cross-section plane
    I_axis: float = np.inf   # kg m^2, about its own axis


def impact(ball, cyl, v, w, V, W, n, e, eT, mu=np.inf):
    """Impulse model of (1): returns v', w', V', W', P_n, P_t, slid (the Coulomb cap was hit)."""
    n = np.asarray(n, float)
    t = np.array([-n[1], n[0]])
    g = (v - ball.r * w * t) - (V + cyl.R * W * t)
    gn, gt = g @ n, g @ t
    inv_mn = 1.0 / ball.m + 1.0 / cyl.M
    inv_mt = 1.0 / ball.m + ball.r ** 2 / ball.I + 1.0 / cyl.M + cyl.R ** 2 / cyl.I_axis
    Pn = -(1.0 + e) * gn / inv_mn
    Pt = -(1.0 + eT) * gt / inv_mt
    slid = abs(Pt) > mu * Pn
    if slid:
        Pt = -np.sign(gt) * mu * Pn
    P = Pn * n + Pt * t
    v1 = v + P / ball.m
    w1 = w - ball.r * Pt / ball.I
    V1 = V - P / cyl.M
    W1 = W - cyl.R * Pt / cyl.I_axis
    return v1, w1, V1, W1, Pn, Pt, slid


def fixed_cylinder(ball, R, speed, D, e, eT, mu=np.inf, w0=0.0):
    """Ball moving in -x at `speed`, its line of flight D above the axis of a fixed cylinder at
    the origin. Returns (theta deg, outgoing speed, angle of v' above +x in deg, spin rpm)."""
    th = np.arcsin(D / (ball.r + R))
    n = np.array([np.cos(th), np.sin(th)])
    v1, w1, _, _, _, _, slid = impact(ball, Cylinder(R), np.array([-speed, 0.0]), w0,
                                      np.zeros(2), 0.0, n, e, eT, mu)
    return np.degrees(th), np.linalg.norm(v1), np.degrees(np.arctan2(v1[1], v1[0])), w1 * RPM, slid


def swinging_bat(ball, cyl, bat_speed, D, e, eT, mu=np.inf, ball_speed=0.0, w0=0.0):
    """Bat moving in +x at `bat_speed` (at the impact point), ball moving in -x at `ball_speed`,
    the ball's centre D above the bat's axis. Returns (launch angle deg, exit speed, spin rpm)."""
    th = np.arcsin(D / (ball.r + cyl.R))
    n = np.array([np.cos(th), np.sin(th)])
    v1, w1, _, _, _, _, slid = impact(ball, cyl, np.array([-ball_speed, 0.0]), w0,
                                      np.array([bat_speed, 0.0]), 0.0, n, e, eT, mu)
    return np.degrees(np.arctan2(v1[1], v1[0])), np.linalg.norm(v1), w1 * RPM, slid


def lumped_ode(ball, R, speed, D, k_n, k_t, mu, n_unload=1.0, dt=None):
    """Time-domain contact of (2) against a fixed cylinder: normal spring k_n (loading), the
    program's m = 1 hysteretic unloading k2 c^n_unload, tangential spring k_t with the Coulomb
    cap |k_t xi| <= mu F_n (return mapping after each RK4 step). Returns (spin rpm, u_t', e_T
    effective, contact time)."""
    th = np.arcsin(D / (ball.r + R))
    n = np.array([np.cos(th), np.sin(th)])
    t = np.array([-n[1], n[0]])
    m, r, I = ball.m, ball.r, ball.I
    un, ut = np.array([-speed, 0.0]) @ n, np.array([-speed, 0.0]) @ t
    if dt is None:
        dt = 2e-4 * np.pi * np.sqrt(m / max(k_n, k_t))
    # state: compression c, normal velocity of approach cd = -u_n, ut, w, tangential spring xi
    c, cd, w, xi, time = 0.0, -un, 0.0, 0.0, 0.0
    loading, cmax = True, 0.0

    def Fn(cc, load, cm):
        if cc <= 0.0:
            return 0.0
        return k_n * cc if load else k_n * cm ** (1.0 - n_unload) * cc ** n_unload

    def rhs(y, load, cm):
        cc, ccd, uu, ww, xx = y
        F = Fn(cc, load, cm)
        Ft = -k_t * xx                     # on the ball, along t
        g_t = uu - r * ww                  # slip velocity of the ball's contact point
        return np.array([ccd, -F / m, Ft / m, -r * Ft / I, g_t])
    y = np.array([c, cd, ut, w, xi])

    def rk4(y, h):
        k1 = rhs(y, loading, cmax)
        k2 = rhs(y + h / 2 * k1, loading, cmax)
        k3 = rhs(y + h / 2 * k2, loading, cmax)
        k4 = rhs(y + h * k3, loading, cmax)
        return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    while True:
        y1 = rk4(y, dt)
        if y1[0] <= 0.0 and time > 0.0:    # separation inside the step: redo the step up to it
            h = dt * y[0] / (y[0] - y1[0])
            for _ in range(3):             # secant refinement of the root of c
                yh = rk4(y, h)
                h = h - yh[0] * h / (yh[0] - y[0]) if yh[0] != y[0] else h
            y, time = rk4(y, h), time + h
            break
        if loading and y1[1] < 0.0:        # maximum compression inside the step
            loading, cmax = False, max(y[0], y1[0])
        if np.isfinite(mu):
            cap = mu * Fn(max(y1[0], 0.0), loading, cmax) / k_t
            y1[4] = np.clip(y1[4], -cap, cap)
        y, time = y1, time + dt
    g_t0 = ut
    g_t1 = y[2] - r * y[3]
    return y[3] * RPM, y[2], -g_t1 / g_t0, time


def report_limits():
    ball = Ball()
    R = 1.5 * INCH
    v = 50.0
    rows = []
    for D_in in (0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5):
        D = D_in * INCH
        th = np.arcsin(D / (ball.r + R))
        ut = v * np.sin(th)
        fr = fixed_cylinder(ball, R, v, D, 1.0, 0.0, mu=0.0)
        ro = fixed_cylinder(ball, R, v, D, 0.5, 0.0)
        comp = fixed_cylinder(ball, R, v, D, 0.5, 0.3)
        rows.append([D_in, np.degrees(th), fr[2], 2 * np.degrees(th), fr[3],
                     ro[3], ut / (1 + ball.alpha) / ball.r * RPM,
                     comp[3], 1.3 * ut / (1 + ball.alpha) / ball.r * RPM])
    table("(1) limits on a fixed cylinder (R = 1.5 in), ball 50 m/s without spin, alpha = 0.4: the "
          "impulse model against the closed forms",
          ["D in", "theta deg", "frictionless e=1: angle", "mirror 2 theta", "spin",
           "rolling spin rpm", "u_t/((1+a) r)", "e_T=0.3 spin", "1.3 x rolling"], rows,
          ["%.2f", "%.3f", "%.6f", "%.6f", "%.1f", "%.3f", "%.3f", "%.3f", "%.3f"])


def report_ode_check():
    ball = Ball()
    R = 1.5 * INCH
    v = 30.0
    k_n = ball.m * np.pi ** 2 / (1.0e-3) ** 2   # 1 ms elastic contact
    rows = []
    m_t = 1.0 / (1.0 / ball.m + ball.r ** 2 / ball.I)
    for ratio in (0.3, 0.5, 0.8):
        k_t = ratio * k_n
        w_t = np.sqrt(k_t / m_t)
        for D_in in (0.5, 1.0, 1.5):
            D = D_in * INCH
            T = np.pi * np.sqrt(ball.m / k_n)
            eT = -np.cos(w_t * T)
            spin, ut1, eT_ode, tc = lumped_ode(ball, R, v, D, k_n, k_t, mu=np.inf)
            imp = fixed_cylinder(ball, R, v, D, 1.0, eT)
            rows.append([ratio, D_in, eT, eT_ode, imp[3], spin, spin - imp[3], tc * 1e3])
    table("(2) time-domain check, ample friction: elastic normal spring (contact 1 ms), tangential "
          "spring k_t; e_T = -cos(w_t T) and the impulse model against the ODE (30 m/s)",
          ["k_t/k_n", "D in", "e_T formula", "e_T ODE", "spin impulse rpm", "spin ODE rpm",
           "diff rpm", "contact ms"], rows,
          ["%.1f", "%.2f", "%+.6f", "%+.6f", "%.3f", "%.3f", "%+.3f", "%.4f"])
    rows = []
    k_t = 0.5 * k_n
    for mu in (0.2, 0.5, np.inf):
        for D_in in (0.5, 1.0, 2.0):
            D = D_in * INCH
            spin, ut1, eT_ode, tc = lumped_ode(ball, R, v, D, k_n, k_t, mu=mu)
            eT = -np.cos(np.sqrt(k_t / m_t) * np.pi * np.sqrt(ball.m / k_n))
            imp = fixed_cylinder(ball, R, v, D, 1.0, eT, mu=mu)
            rows.append(["%g" % mu, D_in, spin, imp[3], "yes" if imp[4] else "no", eT_ode])
    table("    with Coulomb friction (k_t/k_n = 0.5): the ODE (micro-slip, force capped at mu F_n) "
          "and the impulse model with the cap",
          ["mu", "D in", "spin ODE rpm", "spin impulse rpm", "impulse slid", "e_T ODE"], rows,
          ["%s", "%.2f", "%.2f", "%.2f", "%s", "%+.4f"])
    n_h = 2.0 / 0.5 ** 2 - 1.0
    rows = []
    for D_in in (0.5, 1.0):
        D = D_in * INCH
        spin, ut1, eT_ode, tc = lumped_ode(ball, R, v, D, k_n, k_t, mu=np.inf, n_unload=n_h)
        eT = -np.cos(np.sqrt(k_t / m_t) * tc)
        imp = fixed_cylinder(ball, R, v, D, 0.5, eT)
        rows.append([D_in, tc * 1e3, eT, eT_ode, imp[3], spin])
    table("    the program's hysteretic ball (e = 0.5, m = 1, n = 7): e_T = -cos(w_t T_contact)",
          ["D in", "contact ms", "e_T formula", "e_T ODE", "spin impulse rpm", "spin ODE rpm"],
          rows, ["%.2f", "%.4f", "%+.6f", "%+.6f", "%.3f", "%.3f"])


def bat_from_profile(path, rho, x_impact_from_tip):
    """Mass, centre of mass, I_cm, axial moment of inertia and the barrel radius at the impact
    point of a solid round bat from its profile (x from the knob, outer diameter; linear)."""
    data = np.loadtxt(path)
    x = np.linspace(data[0, 0], data[-1, 0], 20001)
    d = np.interp(x, data[:, 0], data[:, 1])
    mu_x = rho * np.pi * d ** 2 / 4.0
    M = np.trapz(mu_x, x)
    xc = np.trapz(mu_x * x, x) / M
    Icm = np.trapz(mu_x * (x - xc) ** 2, x)
    Iax = np.trapz(rho * np.pi * d ** 4 / 32.0, x)
    xi = x[-1] - x_impact_from_tip
    Ri = 0.5 * np.interp(xi, data[:, 0], data[:, 1])
    return M, xc, Icm, Iax, xi, Ri


def report_experiments():
    ball = Ball()
    # Nathan et al. 2012: baseball fired horizontally onto a 3-inch wood cylinder fixed to a wall
    R = 1.5 * INCH
    rows = []
    for D_in in (0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0):
        D = D_in * INCH
        r0 = fixed_cylinder(ball, R, 100 * MPH, D, 0.5, 0.0)
        r1 = fixed_cylinder(ball, R, 100 * MPH, D, 0.5, 0.2)
        r2 = fixed_cylinder(ball, R, 100 * MPH, D, 0.5, 0.4)
        r3 = fixed_cylinder(ball, R, 100 * MPH, D, 0.5, 0.2, mu=0.5)
        rows.append([D_in, r0[0], r0[2], r0[3], r1[2], r1[3], r2[3], r3[3]])
    table("(3a) Nathan et al. 2012 set-up: ball at 100 mph on a fixed 3-in cylinder, e = 0.5; "
          "outgoing angle above the reversed direction and spin (backspin > 0)",
          ["D in", "theta deg", "angle e_T=0", "spin e_T=0 rpm", "angle e_T=0.2",
           "spin e_T=0.2", "spin e_T=0.4", "spin e_T=0.2 mu=0.5"], rows,
          ["%.2f", "%.2f", "%.2f", "%.0f", "%.2f", "%.0f", "%.0f", "%.0f"])

    # Kensrud, Nathan & Smith 2017: a swinging bat on a ball at rest; a wood bat like the R161
    prof = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                         "options", "bats", "r161.profile"))
    M, xc, Icm, Iax, xi, Ri = bat_from_profile(prof, 649.0, 0.15)
    Meff = 1.0 / (1.0 / M + (xi - xc) ** 2 / Icm)
    print("\n    R161 (ash, rho = 649 kg/m^3, options/bats/r161.profile): M = %.4f kg, x_cm = %.4f m, I_cm = %.5f "
          "kg m^2, I_axis = %.3e kg m^2; impact 0.15 m from the tip: R = %.4f m, M_eff = %.4f kg"
          % (M, xc, Icm, Iax, Ri, Meff))
    rows = []
    for bat_mph in (63.0, 75.0, 88.0):
        for D_in in (0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5):
            D = D_in * INCH
            cyl = Cylinder(Ri, Meff, Iax)
            a0 = swinging_bat(ball, cyl, bat_mph * MPH, D, 0.5, 0.0)
            a4 = swinging_bat(ball, cyl, bat_mph * MPH, D, 0.5, 0.4)
            noroll = swinging_bat(ball, Cylinder(Ri, Meff, np.inf), bat_mph * MPH, D, 0.5, 0.4)
            rows.append([bat_mph, D_in, a0[0], a0[1] / MPH, a0[2], a4[0], a4[2], noroll[2]])
    table("(3b) Kensrud, Nathan & Smith 2017 set-up: bat (R161-like) swung at the impact point "
          "onto a ball at rest, e = 0.5; launch angle, exit speed and spin",
          ["bat mph", "D in", "angle e_T=0", "exit mph", "spin e_T=0 rpm", "angle e_T=0.4",
           "spin e_T=0.4", "spin e_T=0.4, bat not rolling"], rows,
          ["%.0f", "%.2f", "%.2f", "%.1f", "%.0f", "%.2f", "%.0f", "%.0f"])


def main():
    print("oblique.py: a ball on a cylinder, rigid-body impulse model with e, e_T and Coulomb "
          "friction; a lumped tangential-compliance ODE; the experiments' set-ups")
    report_limits()
    report_ode_check()
    report_experiments()


if __name__ == "__main__":
    main()
