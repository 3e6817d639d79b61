#!/usr/bin/env python3
"""The batted ball's flight as A. M. Nathan's trajectory calculator computes it: an independent
port (issue 24, MODEL.md section 10), checked line by line against a trajectory his spreadsheet
published, plus sample trajectories and their convergence with the time step.

    /usr/bin/python3 scripts/references/flight.py

The model (Nathan, TrajectoryCalculator-new-3D.xlsx, baseball.physics.illinois.edu; batted
balls, aerodynamics fitted to 2015 Statcast data, 'Going Deep on Goin' Deep', The Hardball
Times, 6 April 2016), in the spreadsheet's units (ft, s, rpm, mph, deg F, inHg):

    dv/dt = -c0 C_D |v| v + c0 (C_L / |w|) |v| (w x v) - g z,      g = 32.174 ft/s^2
    c0    = 0.07182 rho[lb/ft^3] (5.125 / mass[oz]) (circumference[in] / 9.125)^2   (1/ft)
          = rho A / (2 m) for the standard ball
    decay = exp(-t |v| / (tau * 146.7)),  tau = 30 s          (spin decay; 146.7 ft/s = 100 mph)
    S     = (r w / |v|) decay,  r = circumference / (2 pi)
    C_L   = 1.120 S / (0.583 + 2.333 S)
    C_D   = 0.3008 + 0.0292 (w[rpm] / 1000) decay
    rho[kg/m^3] = 1.2929 (273/(T + 273)) (P e^(-beta h) - 0.3783 RH SVP / 100) / 760
          T in deg C, P = P[inHg] 1000/39.37 in mmHg, h the elevation in m, beta = 1.217e-4 /m,
          RH in per cent, SVP = 4.5841 exp((18.687 - T/234.5) T / (257.14 + T)) mmHg (Buck)
    rho[lb/ft^3] = 0.06261 rho[kg/m^3]      (the spreadsheet's factor; the exact one is 0.0624280)
    speeds: mph x 1.467 = ft/s; start at (0, 2, 3) ft (x lateral, y toward centre field, z up)
    step:  x += v dt + a dt^2/2,  v += a dt,  dt = 0.01 s   (a at the start of the step)

The spin vector is fixed in direction (backspin about the horizontal axis normal to the initial
velocity, sidespin about the axis normal to it in the vertical plane); only its magnitude decays.
The constants tau = 30 s and 0.06261 are not printed in any source found here: they are the values
with which this port reproduces the published trajectory (mosaicCalc's Fly_ball data set, made
with the spreadsheet) to 1e-6 ft over all 552 rows; with the exact 0.0624280 the port lands
0.5 ft long, without spin decay 1.5 ft. See README.md for every source and difference.
"""
import os
import sys

from _common import need, table, percent  # noqa: E402

need(__file__, "numpy", "scipy")
from dataclasses import dataclass, field  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.optimize import brentq  # noqa: E402

MPH = 1.467            # ft/s per mph, as the spreadsheet
KGM3_TO_LBFT3 = 0.06261  # the spreadsheet's factor (exact: 0.0624280)
FT = 0.3048            # m per ft
G_FT = 32.174          # ft/s^2

# mosaicCalc (ProjectMOSAIC/mosaicCalc, data/Fly_ball.rda, documented in R/Fly_ball.R): Nathan's
# TrajectoryCalculator-new-3D.xlsx output for 103 mph, 27.5 deg, 2500 rpm backspin, 70 deg F,
# RH 50 %, 29.92 inHg, elevation 15 ft, every 0.01 s; (t s, y ft, z ft) at a few of its 552 rows.
FLY_BALL_CASE = dict(v_mph=103.0, angle=27.5, backspin=2500.0, sidespin=0.0)
FLY_BALL_ROWS = [
    (0.01, 3.3376306613, 3.6962309579),
    (0.50, 63.1166664627, 34.2599250413),
    (1.00, 114.8804274649, 58.5059339720),
    (1.50, 159.9975222125, 76.0344896881),
    (2.00, 200.3091946728, 87.0761706303),
    (2.50, 237.0999037987, 91.8194068703),
    (3.00, 271.2743154036, 90.4427041708),
    (3.50, 303.4735453011, 83.1512964493),
    (4.00, 334.1620869025, 70.2084491631),
    (4.50, 363.6940053912, 51.9507380133),
    (5.00, 392.3572782046, 28.7840069917),
    (5.50, 420.3973433296, 1.1653175340),
    (5.51, 420.9532962454, 0.5708392151),
]
FLY_BALL_APEX = (2.64, 92.0427940213)  # (t s, z ft), the highest row of the data set


@dataclass
class Air:
    temp_F: float = 70.0
    rh: float = 50.0          # relative humidity (%)
    p_inHg: float = 29.92
    elev_ft: float = 15.0
    beta: float = 1.217e-4    # 1/m

    def rho_kgm3(self):
        T = (self.temp_F - 32.0) * 5.0 / 9.0
        p_mmHg = self.p_inHg * 1000.0 / 39.37
        svp = 4.5841 * np.exp((18.687 - T / 234.5) * T / (257.14 + T))
        return 1.2929 * (273.0 / (T + 273.0)) * (
            p_mmHg * np.exp(-self.beta * self.elev_ft * FT) - 0.3783 * self.rh * svp / 100.0) / 760.0


@dataclass
class Aero:
    cd0: float = 0.3008
    cdspin: float = 0.0292    # per 1000 rpm
    cl0: float = 0.583
    cl1: float = 2.333
    cl2: float = 1.120
    tau: float = 30.0         # s, spin decay time at 100 mph
    mass_oz: float = 5.125
    circ_in: float = 9.125
    lbft3_per_kgm3: float = KGM3_TO_LBFT3


@dataclass
class Hit:
    v_mph: float
    angle: float              # launch angle (deg)
    backspin: float           # rpm
    sidespin: float = 0.0     # rpm
    x0: np.ndarray = field(default_factory=lambda: np.array([0.0, 2.0, 3.0]))  # ft


def spin_axis(hit):
    """Unit vectors of backspin and sidespin for a hit toward +y (spray angle 0)."""
    th = np.radians(hit.angle)
    e_back = np.array([1.0, 0.0, 0.0])                  # w x v lifts: (1,0,0) x (0,c,s) = (0,-s,c)
    e_side = np.array([0.0, -np.sin(th), np.cos(th)])   # normal to v in the vertical plane
    return e_back, e_side


class Model:
    """Nathan's batted-ball acceleration (ft units)."""

    def __init__(self, hit, air=None, aero=None):
        self.hit, self.air, self.aero = hit, air or Air(), aero or Aero()
        a = self.aero
        rho_lb = self.air.rho_kgm3() * a.lbft3_per_kgm3
        self.c0 = 0.07182 * rho_lb * (5.125 / a.mass_oz) * (a.circ_in / 9.125) ** 2
        eb, es = spin_axis(hit)
        w = hit.backspin * eb + hit.sidespin * es        # rpm
        self.spin = np.linalg.norm(w)
        self.w_hat = w / self.spin if self.spin > 0 else np.zeros(3)
        self.romega = a.circ_in / (24.0 * np.pi) * self.spin * np.pi / 30.0   # r w in ft/s

    def accel(self, t, v):
        a = self.aero
        vm = np.linalg.norm(v)
        decay = np.exp(-t * vm / (a.tau * 146.7))
        S = self.romega / vm * decay
        cl = a.cl2 * S / (a.cl0 + a.cl1 * S)
        cd = a.cd0 + a.cdspin * self.spin / 1000.0 * decay
        acc = -self.c0 * cd * vm * v + self.c0 * cl * vm * np.cross(self.w_hat, v)
        acc[2] -= G_FT
        return acc

    def v0(self):
        th = np.radians(self.hit.angle)
        return self.hit.v_mph * MPH * np.array([0.0, np.cos(th), np.sin(th)])


def spreadsheet_steps(model, dt=0.01, tmax=12.0):
    """The spreadsheet's step: x += v dt + a dt^2/2, v += a dt. Rows (t, x, y, z) until z < 0."""
    x, v, t = model.hit.x0.astype(float), model.v0(), 0.0
    rows = [(t, *x)]
    while t < tmax:
        a = model.accel(t, v)
        x = x + v * dt + 0.5 * a * dt * dt
        v = v + a * dt
        t += dt
        rows.append((t, *x))
        if x[2] < 0.0:
            break
    return np.array(rows)


def rk4_steps(model, dt):
    """Classical RK4 on (x, v) until z < 0: distance (ft) and hang time (s) at z = 0 from the
    cubic Hermite interpolant of the last step (positions and velocities: O(dt^4) like RK4)."""
    def f(t, y):
        return np.concatenate([y[3:], model.accel(t, y[3:])])
    y, t = np.concatenate([model.hit.x0.astype(float), model.v0()]), 0.0
    while True:
        k1 = f(t, y)
        k2 = f(t + dt / 2, y + dt / 2 * k1)
        k3 = f(t + dt / 2, y + dt / 2 * k2)
        k4 = f(t + dt, y + dt * k3)
        y1 = y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        if y1[2] < 0.0:
            break
        y, t = y1, t + dt

    def hermite(s):  # position at t + s dt
        h00, h10 = 2 * s ** 3 - 3 * s ** 2 + 1, s ** 3 - 2 * s ** 2 + s
        h01, h11 = -2 * s ** 3 + 3 * s ** 2, s ** 3 - s ** 2
        return h00 * y[:3] + h10 * dt * y[3:] + h01 * y1[:3] + h11 * dt * y1[3:]
    s = brentq(lambda s: hermite(s)[2], 0.0, 1.0, xtol=1e-15)
    p = hermite(s)
    return np.hypot(p[0], p[1]), t + s * dt


def landing_from_rows(rows):
    """Distance (ft, from home plate in the x-y plane), hang time (s) at z = 0 by linear
    interpolation between the last two rows, and the apex (ft) of the rows."""
    (t0, x0, y0, z0), (t1, x1, y1, z1) = rows[-2], rows[-1]
    s = z0 / (z0 - z1)
    xl, yl = x0 + s * (x1 - x0), y0 + s * (y1 - y0)
    return np.hypot(xl, yl), t0 + s * (t1 - t0), rows[:, 3].max()


def converged(model, rtol=1e-12):
    """DOP853 to rtol with the landing and the apex located as events."""
    def f(t, y):
        return np.concatenate([y[3:], model.accel(t, y[3:])])

    def ground(t, y):
        return y[2]
    ground.terminal, ground.direction = True, -1

    def top(t, y):
        return y[5]
    top.direction = -1
    sol = solve_ivp(f, (0.0, 20.0), np.concatenate([model.hit.x0.astype(float), model.v0()]),
                    method="DOP853", rtol=rtol, atol=1e-12, events=[ground, top], dense_output=True)
    tl = sol.t_events[0][0]
    yl = sol.y_events[0][0]
    return dict(distance=np.hypot(yl[0], yl[1]), hang=tl, apex=sol.y_events[1][0][2],
                t_apex=sol.t_events[1][0], v_land=np.linalg.norm(yl[3:]), sol=sol)


def report_fly_ball():
    m = Model(Hit(**FLY_BALL_CASE), Air(70.0, 50.0, 29.92, 15.0))
    rows = spreadsheet_steps(m, tmax=5.515)
    out = []
    worst = 0.0
    for t, yp, zp in FLY_BALL_ROWS:
        k = int(round(t / 0.01))
        dy, dz = rows[k, 2] - yp, rows[k, 3] - zp
        worst = max(worst, abs(dy), abs(dz))
        out.append([t, yp, rows[k, 2], dy, zp, rows[k, 3], dz])
    table("(1) Nathan's spreadsheet, published run (103 mph, 27.5 deg, 2500 rpm, 70 F, RH 50 %, "
          "29.92 inHg, 15 ft; mosaicCalc Fly_ball) against this port, same step dt = 0.01 s; ft",
          ["t s", "y published", "y port", "diff", "z published", "z port", "diff"], out,
          ["%.2f", "%.6f", "%.6f", "%+.1e", "%.6f", "%.6f", "%+.1e"])
    print("    largest difference over these rows: %.2e ft; air density %.5f kg/m^3"
          % (worst, m.air.rho_kgm3()))
    variants = []
    for name, aero in (("port (tau 30 s, 0.06261)", Aero()),
                       ("exact lb/ft^3 factor 0.0624280", Aero(lbft3_per_kgm3=0.0624280)),
                       ("no spin decay (tau 1e4 s)", Aero(tau=1e4)),
                       ("tau 25 s", Aero(tau=25.0))):
        mm = Model(Hit(**FLY_BALL_CASE), Air(70.0, 50.0, 29.92, 15.0), aero)
        r = spreadsheet_steps(mm, tmax=5.515)
        y551, z551 = r[551, 2], r[551, 3]
        variants.append([name, y551, y551 - FLY_BALL_ROWS[-1][1], z551, z551 - FLY_BALL_ROWS[-1][2]])
    table("    the published row t = 5.51 s against variants of the constants (ft)",
          ["variant", "y(5.51)", "diff", "z(5.51)", "diff"], variants,
          ["%s", "%.4f", "%+.4f", "%.4f", "%+.4f"])


def report_samples():
    cases = [("100 mph 28 deg 2000 rpm, 70 F, sea level", Hit(100, 28, 2000), Air(70, 50, 29.92, 0)),
             ("103 mph 27.5 deg 2500 rpm (Fly_ball)", Hit(103, 27.5, 2500), Air(70, 50, 29.92, 15)),
             ("100 mph 28 deg 2000 rpm, Denver 5280 ft", Hit(100, 28, 2000), Air(70, 50, 29.92, 5280)),
             ("100 mph 28 deg 2000 rpm, 95 F", Hit(100, 28, 2000), Air(95, 50, 29.92, 0)),
             ("100 mph 28 deg 2000 rpm, 45 F", Hit(100, 28, 2000), Air(45, 50, 29.92, 0)),
             ("110 mph 25 deg 2200 rpm, 70 F", Hit(110, 25, 2200), Air(70, 50, 29.92, 0)),
             ("95 mph 30 deg 1800 rpm, 70 F", Hit(95, 30, 1800), Air(70, 50, 29.92, 0)),
             ("100 mph 28 deg, no spin, 70 F", Hit(100, 28, 0), Air(70, 50, 29.92, 0)),
             ("100 mph 28 deg 2000 rpm + 500 rpm side", Hit(100, 28, 2000, 500), Air(70, 50, 29.92, 0))]
    rows = []
    for name, hit, air in cases:
        m = Model(hit, air)
        d, th, ap = landing_from_rows(spreadsheet_steps(m))
        c = converged(m)
        rows.append([name, air.rho_kgm3(), d, c["distance"], th, c["hang"], ap, c["apex"],
                     c["v_land"] / MPH])
    table("(2) sample trajectories: the spreadsheet's step (dt = 0.01 s, landing interpolated "
          "to z = 0) and the converged solution (DOP853, rtol 1e-12)",
          ["case", "rho kg/m3", "dist sheet ft", "dist ft", "hang sheet s", "hang s",
           "apex sheet ft", "apex ft", "v land mph"], rows,
          ["%s", "%.4f", "%.2f", "%.3f", "%.3f", "%.4f", "%.2f", "%.3f", "%.2f"])


def report_convergence():
    m = Model(Hit(100, 28, 2000), Air(70, 50, 29.92, 0))
    ref = converged(m, rtol=1e-13)
    rows = []
    for dt in (0.04, 0.02, 0.01, 0.005, 0.0025, 0.00125):
        d_s, t_s, _ = landing_from_rows(spreadsheet_steps(m, dt))
        d_r, t_r = rk4_steps(m, dt)
        rows.append([dt, d_s, d_s - ref["distance"], d_r, d_r - ref["distance"]])
    table("(3) convergence of the distance (100 mph, 28 deg, 2000 rpm, 70 F, sea level): the "
          "spreadsheet's step is first order (its landing: linear interpolation), RK4 fourth order "
          "(landing on the cubic Hermite interpolant); reference %.6f ft (DOP853, rtol 1e-13)"
          % ref["distance"],
          ["dt s", "sheet ft", "error", "RK4 ft", "error"], rows,
          ["%.5f", "%.4f", "%+.2e", "%.6f", "%+.2e"])


def report_density():
    rows = []
    for name, air in (("70 F, RH 50, 29.92 inHg, 0 ft", Air(70, 50, 29.92, 0)),
                      ("70 F, RH 0", Air(70, 0, 29.92, 0)),
                      ("70 F, RH 100", Air(70, 100, 29.92, 0)),
                      ("45 F", Air(45, 50, 29.92, 0)),
                      ("95 F", Air(95, 50, 29.92, 0)),
                      ("Denver 5280 ft", Air(70, 50, 29.92, 5280)),
                      ("29.50 inHg", Air(70, 50, 29.50, 0))):
        rho = air.rho_kgm3()
        rows.append([name, rho, rho * KGM3_TO_LBFT3, percent(rho, Air(70, 50, 29.92, 0).rho_kgm3())])
    table("(4) air density of the spreadsheet's formula",
          ["conditions", "kg/m^3", "lb/ft^3 (x0.06261)", "vs 70 F sea level %"], rows,
          ["%s", "%.5f", "%.6f", "%+.2f"])
    m = Model(Hit(100, 28, 2000), Air(70, 50, 29.92, 0))
    print("\n    in SI for the program: c0 = %.6e 1/m (= rho' A/(2m) with rho' = %.5f kg/m^3, "
          "m = %.5f kg, R = %.5f m); g = %.5f m/s^2"
          % (m.c0 / FT, m.air.rho_kgm3() * KGM3_TO_LBFT3 / 0.0624280,
             5.125 * 0.028349523, 9.125 * 0.0254 / (2 * np.pi), G_FT * FT))


def main():
    print("flight.py: A. M. Nathan's batted-ball trajectory calculator, ported")
    report_fly_ball()
    report_samples()
    report_convergence()
    report_density()


if __name__ == "__main__":
    main()
