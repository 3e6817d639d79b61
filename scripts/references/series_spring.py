#!/usr/bin/env python3
"""The ball on a springy wall: restitution of a linear (hysteretic) ball in series with a wall
spring, with and without the wall's mass. An independent reference for the lumped trampoline
of issue 23 (MODEL.md section 9, 'Lumped alternative').

    /usr/bin/python3 scripts/references/series_spring.py

The ball: mass m_b, the program's hysteretic law with m = 1 (MODEL.md section 1): F = k1 c
while the compression grows, F = k2 c^n after its maximum c_max, k2 = k1 c_max^(1-n), so that
on a rigid wall e0^2 = 2/(n+1) at any speed (n = 1: the linear, lossless spring k_b = k1).

(1) Massless wall spring k_h (closed form). Ball and wall carry the same force F at every
instant, so at maximum compression the energy is split as F^2/(2 k_b) in the ball and
F^2/(2 k_h) in the wall. The ball gives back e0^2 of its share (its unloading branch returns
the fraction 2/(n+1) of whatever it stored: that does not depend on c_max), the wall all of its
share. Hence, with r = k_b / k_h,

    e^2 = (e0^2 F^2/k_b + F^2/k_h) / (F^2/k_b + F^2/k_h) = (e0^2 + r) / (1 + r),

exactly, for any speed and any unloading exponent. Printed: the formula, and an independent
integration of the ball with the series force (the unloading force found from
c = c_b + F/k_h, F = k2 c_b^n at every step) that must agree to the integrator's tolerance;
and the contact time pi sqrt(m_b (1/k_b + 1/k_h)) of the elastic case.

(2) Wall of mass m_h on the spring k_h = m_h (2 pi f_h)^2 (the bat lab's 'hoop frequency'
f_h), ball spring k_b between ball and wall. For the elastic ball the two-mass oscillator is
solved in closed form (normal modes) until the compression first returns to zero: the ball
leaves with e < 1 because the wall keeps vibrating. The script checks the closed form against
the ODE and tabulates e against f_h for a baseball (the hoop frequency that maximises e
against the contact time), with the hysteretic ball (ODE). At a reload (the compression
growing again during unloading) the force retraces the unloading curve up to c_max and loads
with k1 c beyond it (no force jump; the program's run/events.cpp jumps to k1 c at once: the two
agree where the tables count 0 reloads). (4) takes the wall's mass and stiffness from the hoop
mode of shell_modes.py (hoop_lumped).
Sources, numbers for the program's tests and caveats: scripts/references/README.md.
"""
import os
import sys

from _common import need, table, percent  # noqa: E402

need(__file__, "numpy", "scipy")
import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.linalg import eigh  # noqa: E402
from scipy.optimize import brentq  # noqa: E402

RTOL, ATOL = 1e-12, 1e-18


def e_series(e0, r):
    """Restitution of a linear hysteretic ball (wall value e0) on a massless wall spring,
    r = k_b / k_h (MODEL.md section 9)."""
    return np.sqrt((e0 ** 2 + r) / (1.0 + r))


def exponent_for(e0):
    """Unloading exponent n of the m = 1 law that gives e0 on a rigid wall: e0^2 = 2/(n+1)."""
    return 2.0 / e0 ** 2 - 1.0


def _segment(rhs, y0, t0, events, tmax, skip=0.0, counted=()):
    """Integrate until the first of `events` (terminal); return (t, y, index of the event,
    how often each of the `counted` (non-terminal) events occurred). The first `skip` seconds
    are stepped without events: a segment that starts on the root of the previous one must not
    find it again by round-off."""
    if skip > 0.0:
        sol = solve_ivp(rhs, (t0, t0 + skip), y0, method="DOP853", rtol=RTOL, atol=ATOL)
        t0, y0 = sol.t[-1], sol.y[:, -1]
    for ev in events:
        ev.terminal = True
    for ev in counted:
        ev.terminal = False
    sol = solve_ivp(rhs, (t0, tmax), y0, method="DOP853", rtol=RTOL, atol=ATOL,
                    events=list(events) + list(counted), dense_output=False)
    counts = [len(sol.t_events[len(events) + j]) for j in range(len(counted))]
    for i in range(len(events)):
        if len(sol.t_events[i]):
            return sol.t_events[i][0], sol.y_events[i][0], i, counts
    raise RuntimeError("no event before t = %g" % tmax)


def massless_wall_ode(m_b, k1, n, k_h, v):
    """Ball (speed v) on the hysteretic contact in series with a massless wall spring:
    restitution and contact time by ODE integration."""
    keff = k1 * k_h / (k1 + k_h)
    tmax = 50.0 * np.pi * np.sqrt(m_b / keff)

    def f_load(t, y):
        return [y[1], -keff * y[0] / m_b]

    def vmax(t, y):
        return y[1]
    vmax.direction = -1
    t1, y1, _, _ = _segment(f_load, [0.0, v], 0.0, [vmax], tmax)
    c_tot = y1[0]
    F_max = keff * c_tot
    cb_max = F_max / k1
    k2 = k1 * cb_max ** (1.0 - n)

    def force(c):  # F = k2 c_b^n with c = c_b + F/k_h, monotone in F on [0, k_h c]
        if c <= 0.0:
            return 0.0
        return brentq(lambda F: F - k2 * max(c - F / k_h, 0.0) ** n, 0.0, k_h * c,
                      xtol=1e-14 * F_max, rtol=1e-15)

    def f_unload(t, y):
        return [y[1], -force(y[0]) / m_b]

    def sep(t, y):
        return y[0]
    sep.direction = -1
    t2, y2, _, _ = _segment(f_unload, y1, t1, [sep], tmax)
    return -y2[1] / v, t2


def two_mass_exact(m_b, k_b, m_h, k_h, v):
    """Elastic ball (spring k_b) on a wall mass m_h held by k_h, wall at rest: the normal-mode
    solution until the compression x_b - x_h first returns to zero. Returns (e, contact time,
    fraction of the energy left in the wall)."""
    M = np.diag([m_b, m_h])
    K = np.array([[k_b, -k_b], [-k_b, k_b + k_h]])
    w2, phi = eigh(K, M)  # mass-normalised: phi^T M phi = I
    w = np.sqrt(w2)
    a = phi.T @ M @ np.array([v, 0.0]) / w  # x(t) = phi @ (a sin w t)

    def x(t):
        return phi @ (a * np.sin(w * t))

    def xd(t):
        return phi @ (a * w * np.cos(w * t))

    def c(t):
        xx = x(t)
        return xx[0] - xx[1]
    # first root of c after t = 0 (c > 0 just after contact): scan finely, then refine
    T = 2.0 * np.pi / w.min()
    ts = np.linspace(0.0, 3.0 * T, 60001)[1:]
    cs = np.array([c(t) for t in ts])
    k = np.argmax(cs <= 0.0)
    tc = brentq(c, ts[k - 1], ts[k], xtol=1e-16, rtol=1e-15)
    vb, vh = xd(tc)
    xh = x(tc)[1]
    wall = 0.5 * m_h * vh ** 2 + 0.5 * k_h * xh ** 2
    return -vb / v, tc, wall / (0.5 * m_b * v ** 2)


def two_mass_ode(m_b, k1, n, m_h, k_h, v, max_phases=400):
    """Ball on the hysteretic contact against the wall mass: (e, contact time, reloads,
    wall energy fraction) by ODE integration with located branch switches.

    Rule at a reload (the compression grows again before separation): the force retraces the
    unloading curve k2 c^n (elastic, no jump) up to c_max and follows the loading branch k1 c
    beyond it. The program's rule (run/events.cpp: ContactEventKind::Reload) switches to k1 c
    at once, a force jump; the two agree wherever 'reloads' is 0."""
    T = 2.0 * np.pi * np.sqrt(min(m_b, m_h) / max(k1, k_h))
    tmax = 1e4 * T

    def rhs_for(F_of_c):
        def rhs(t, y):
            F = F_of_c(y[0] - y[2])
            return [y[1], -F / m_b, y[3], (F - k_h * y[2]) / m_h]
        return rhs

    def cdot_down(t, y):
        return y[1] - y[3]
    cdot_down.direction = -1

    def cdot_up(t, y):
        return y[1] - y[3]
    cdot_up.direction = 1

    def comp(t, y):
        return y[0] - y[2]
    comp.direction = -1
    y = np.array([0.0, v, 0.0, 0.0])
    t = 0.0
    reloads = 0
    for _ in range(max_phases):
        t, y, i, _ = _segment(rhs_for(lambda c: k1 * c), y, t, [cdot_down, comp], tmax,
                              skip=1e-9 * T if t > 0.0 else 0.0)
        if i == 1:
            raise RuntimeError("separated during loading")
        cmax = y[0] - y[2]
        k2 = k1 * cmax ** (1.0 - n)

        def back(t, y, cmax=cmax):
            return y[0] - y[2] - cmax
        back.direction = 1
        t, y, i, cnt = _segment(rhs_for(lambda c, k2=k2, cm=cmax: k2 * min(max(c, 0.0), 2.0 * cm) ** n), y, t,
                                [comp, back], tmax, skip=1e-9 * T, counted=[cdot_up])
        reloads += cnt[0]
        if i == 0:
            wall = 0.5 * m_h * y[3] ** 2 + 0.5 * k_h * y[2] ** 2
            return -y[1] / v, t, reloads, wall / (0.5 * m_b * v ** 2)
    raise RuntimeError("more than %d phases" % max_phases)


def wall_contact_time(m_b, k1, n):
    """Rigid wall: loading quarter period plus the unloading time of F = k2 c^n,
    sqrt((n+1) m/(2 k1)) * int_0^1 ds / sqrt(1 - s^(n+1))."""
    from scipy.special import gamma
    p = n + 1.0
    integral = np.sqrt(np.pi) * gamma(1.0 + 1.0 / p) / gamma(0.5 + 1.0 / p)
    return 0.5 * np.pi * np.sqrt(m_b / k1) + np.sqrt(p * m_b / (2.0 * k1)) * integral


def series_contact_time(m_b, k1, n, k_h, v):
    """Contact time of the massless-wall series (1) by quadrature, independent of the ODE:
    loading is harmonic with k_eff; unloading runs on the ball's compression c_b from c_bmax
    to 0, with c = c_b + F/k_h, F = k2 c_b^n and (1/2) m cdot^2 = W(c_b) = int F dc."""
    from scipy.integrate import quad
    keff = k1 * k_h / (k1 + k_h)
    t_load = 0.5 * np.pi * np.sqrt(m_b / keff)
    Fm = np.sqrt(keff * m_b) * v  # (1/2) m v^2 = Fm^2 / (2 keff)
    cbm = Fm / k1
    k2 = k1 * cbm ** (1.0 - n)

    def dc(cb):  # dc/dc_b
        return 1.0 + n * k2 * cb ** (n - 1.0) / k_h

    def W(cb):
        return (k2 / (n + 1.0) * (cbm ** (n + 1.0) - cb ** (n + 1.0))
                + k2 ** 2 / (2.0 * k_h) * (cbm ** (2.0 * n) - cb ** (2.0 * n)))

    def integrand(s):  # c_b = c_bmax (1 - s^2) removes the 1/sqrt(c_bmax - c_b) end point
        cb = cbm * (1.0 - s * s)
        w = W(cb)
        if w <= 0.0:  # s = 0: the limit of the integrand
            return 2.0 * cbm * dc(cbm) / np.sqrt(2.0 * k2 * cbm ** (n + 1.0) * dc(cbm) / m_b)
        return dc(cb) * 2.0 * cbm * s / np.sqrt(2.0 * w / m_b)
    t_unload, _ = quad(integrand, 0.0, 1.0, epsabs=0.0, epsrel=1e-12, limit=200)
    return t_load + t_unload


def main():
    print("series_spring.py: a ball on a springy wall (the lumped trampoline of MODEL.md "
          "section 9)")
    rows = []
    for r in (0.0, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 10.0):
        rows.append([r] + [e_series(e0, r) for e0 in (0.5, 0.546, 0.7, 0.85)])
    table("(1) closed form e = sqrt((e0^2 + r)/(1 + r)), r = k_b/k_h (massless wall)",
          ["r", "e0=0.5", "e0=0.546", "e0=0.7", "e0=0.85"], rows, ["%.2f"] + ["%.6f"] * 4)

    m_b, v = 0.145, 26.8  # baseball at the ASTM/NCAA test speed (60 mph)
    tau = 1.0e-3          # linear-wall contact time pi sqrt(m/k): k1 from it
    k1 = m_b * np.pi ** 2 / tau ** 2
    rows = []
    for e0 in (1.0, 0.85, 0.5):
        n = exponent_for(e0)
        for r in (1e-6, 0.25, 1.0, 4.0):
            e_ode, t_c = massless_wall_ode(m_b, k1, n, k1 / r, v)
            tq = series_contact_time(m_b, k1, n, k1 / r, v)
            rows.append([e0, "%g" % r, e_series(e0, r), e_ode, percent(e_ode, e_series(e0, r)),
                         tq * 1e3, t_c * 1e3, percent(t_c, tq)])
        rows.append([e0, "wall", e0, float("nan"), float("nan"),
                     wall_contact_time(m_b, k1, n) * 1e3, float("nan"), float("nan")])
    table("ODE check of (1): baseball m_b = 0.145 kg, v = 26.8 m/s, k1 = %.6g N/m "
          "(pi sqrt(m/k1) = 1 ms); contact time by quadrature ('wall': rigid wall, closed form "
          "pi/2 sqrt(m/k1) + sqrt((n+1) m/(2 k1)) sqrt(pi) G(1+1/(n+1))/G(1/2+1/(n+1)))" % k1,
          ["e0", "r", "formula e", "ODE e", "diff %", "tc quad ms", "tc ODE ms", "diff %"], rows,
          ["%.2f", "%s", "%.10f", "%.10f", "%+.1e", "%.6f", "%.6f", "%+.1e"])

    rows = []
    for mu, Om in ((0.1, 2.0), (0.1, 4.0), (0.2, 2.0), (0.2, 4.0), (0.5, 3.0), (1.0, 2.0),
                    (1.0, 4.0)):
        m_h = mu * m_b
        k_h = m_h * (Om * np.sqrt(k1 / m_b)) ** 2
        e_ex, t_ex, wall = two_mass_exact(m_b, k1, m_h, k_h, v)
        e_od, t_od, nre, _ = two_mass_ode(m_b, k1, 1.0, m_h, k_h, v)
        rows.append([mu, Om, e_ex, e_od, e_ex - e_od, t_ex * 1e3, t_od * 1e3, wall, nre])
    table("(2) wall mass m_h = mu m_b on k_h = m_h (Omega w_b)^2, w_b = sqrt(k1/m_b): elastic "
          "ball, normal modes against the ODE",
          ["mu", "Omega", "e exact", "e ODE", "diff", "tc exact ms", "tc ODE ms",
           "wall energy", "reloads"], rows,
          ["%.2f", "%.2f", "%.10f", "%.10f", "%+.1e", "%.6f", "%.6f", "%.6f", "%d"])

    n = exponent_for(0.5)
    rows = []
    for e0 in (0.85, 0.5):
        n0 = exponent_for(e0)
        for r in (0.25, 1.0, 4.0):
            e_small, _, nre, _ = two_mass_ode(m_b, k1, n0, 1e-3 * m_b, k1 / r, v)
            rows.append([e0, "m_h = 1e-3 m_b, r = %g" % r, e_series(e0, r), e_small,
                         percent(e_small, e_series(e0, r)), nre])
        e_rig, _, nre, _ = two_mass_ode(m_b, k1, n0, m_b, 1e8 * k1, v)
        rows.append([e0, "m_h = m_b, k_h = 1e8 k1", e_series(e0, 1e-8), e_rig,
                     percent(e_rig, e_series(e0, 1e-8)), nre])
    table("(2b) the hysteretic two-mass ODE in its limits: a light wall is the massless series (1), "
          "a stiff one the rigid wall", ["e0", "wall", "formula (1)", "ODE", "diff %", "reloads"],
          rows, ["%.2f", "%s", "%.8f", "%.8f", "%+.1e", "%d"])

    for m_h in (0.010, 0.030):
        rows = []
        for fh in (500, 750, 1000, 1250, 1500, 2000, 2500, 3000, 4000, 6000, 10000):
            k_h = m_h * (2.0 * np.pi * fh) ** 2
            e_el, t_el, w_el = two_mass_exact(m_b, k1, m_h, k_h, v)
            e_h, t_h, nre, w_h = two_mass_ode(m_b, k1, n, m_h, k_h, v)
            r = k1 / k_h
            rows.append([fh, fh * tau, r, e_series(0.5, r), e_h, nre, t_h * 1e3, w_h, e_el])
        table("(3) trampoline scan: baseball (e0 = 0.5, tau = pi sqrt(m_b/k1) = 1 ms) on a wall "
              "mass m_h = %.0f g at hoop frequency f_h; 'e elastic ball' is the closed form of (2) "
              "(negative: the ball's first separation comes while it still moves forward)"
              % (1e3 * m_h),
              ["f_h Hz", "f_h*tau", "r", "massless e", "e (ODE)", "reloads", "tc ms",
               "wall energy", "e elastic ball"], rows,
              ["%d", "%.2f", "%.3f", "%.4f", "%.4f", "%d", "%.4f", "%.4f", "%.4f"])

    from shell_modes import bat_barrel, hoop_lumped
    for tau_s in (1.0e-3, 0.7e-3):
        k1s = m_b * np.pi ** 2 / tau_s ** 2
        rows = []
        for wall in (0.0005, 0.00075, 0.001, 0.0013, 0.0016, 0.002, 0.0025, 0.003, 0.004):
            fh, m_h, k_h, x_c = hoop_lumped(bat_barrel(wall), 2, "cap", "clamped")
            e_h, t_h, nre, w_h = two_mass_ode(m_b, k1s, n, m_h, k_h, v)
            r = k1s / k_h
            rows.append([1e3 * wall, fh, fh * tau_s, 1e3 * m_h, r, e_series(0.5, r), e_h, nre,
                         t_h * 1e3])
        table("(4) the hoop mode of shell_modes.py as the lumped wall: aluminium barrel D = 66.7 mm, "
              "L = 0.30 m, cap at one end, clamped at the other, ball at the mode's antinode; "
              "baseball e0 = 0.5, tau = %.1f ms" % (1e3 * tau_s),
              ["h mm", "f_h Hz", "f_h*tau", "m_eff g", "r", "massless e", "e (ODE)", "reloads",
               "tc ms"], rows,
              ["%.2f", "%.0f", "%.2f", "%.1f", "%.3f", "%.4f", "%.4f", "%d", "%.3f"])


if __name__ == "__main__":
    main()
