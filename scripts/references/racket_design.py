#!/usr/bin/env python3
"""A racket's property table from its published mass, balance and swingweight (issue 25's anchors).

Builds options/bats/racket-pure-drive.properties (x from the butt; columns x EI mu kappaGA rhoI GJ
rhoJ) for a frame whose strung mass, balance point and swingweight are those measured by Tennis
Addict on the Babolat Pure Drive 2021 (321 g, 330 mm, 325 kg cm^2; scripts/references/README.md),
with the string bed of options/bats/racket-pure-drive.opts counted as the program counts it
(sigma = lambda/s_m + lambda/s_c over the head's ellipse, on the bed's own nodes).

The frame's mass per length is three levels (handle, throat, head) joined by 2 cm ramps; the
three levels solve the three linear conditions (mass, first moment, second moment about the
swingweight axis 10 cm from the butt) exactly. The roll inertia rhoJ is set so that the twistweight
(the moment of inertia about the long axis, strings included) is TWISTWEIGHT; EI and GJ are shapes
scaled by EI_SCALE and GJ_SCALE, which were tuned with `beamimpact -task modes` (the free frame's
first bending mode at 150 Hz, its first twisting mode near 400 Hz; racket_design.py cannot compute
those, the program's modes are the check). Prints the table and the inertial properties; --write
writes the file. Run with /usr/bin/python3 (numpy).
"""
import sys
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# --- Published (Tennis Addict, Babolat Pure Drive 2020/2021, strung) and ITF-legal geometry ---
L = 0.685              # 27 in (tennis.com's Pure Drive specification)
M_STRUNG = 0.321       # kg, strung (Tennis Addict)
BALANCE = 0.330        # m from the butt, strung (Tennis Addict)
SWINGWEIGHT = 325e-4   # kg m^2 about the axis 10 cm from the butt, strung (Tennis Addict: 325 kg cm^2)
PIVOT = 0.10
TWISTWEIGHT = 14e-4    # kg m^2 about the long axis: NOT published for this racket (see README), a typical value
HEAD_AREA = 0.0645     # 645 cm^2 = 100 in^2 (Tennis Addict, tennis.com)
# --- Geometry and strings of our own (not published for this racket) ---
HEAD_LENGTH = 0.335    # the ellipse 33.5 x 24.5 cm has pi a b = 644.6 cm^2
HEAD_WIDTH = 0.245
HEAD_CENTER = 0.5075   # the strung area ends 1 cm below the tip
MAINS, CROSSES = 16, 19
S_M = HEAD_WIDTH / MAINS          # 15.3 mm
S_C = HEAD_LENGTH / CROSSES       # 17.6 mm
LAMBDA = 1.51e-3                  # kg/m, nylon 1.30 mm
SIGMA = LAMBDA / S_M + LAMBDA / S_C
# Sections: handle to 0.17, ramp to 0.19, throat to 0.33, ramp to 0.35, lower head to 0.55, ramp
# to 0.57, upper head to the tip. The throat's mu is fixed (MU_THROAT: two carbon arms); the
# handle's and the two head levels' solve the three conditions.
X = np.array([0.0, 0.17, 0.19, 0.33, 0.35, 0.55, 0.57, L])
LEVEL = [0, 0, 1, 1, 2, 2, 3, 3]  # which level each row takes: handle, throat, lower head, upper head
MU_THROAT = 0.25                  # kg/m
# EI and GJ shapes (N m^2) before scaling, and the frame's depth for rhoI
EI_SHAPE = np.array([300.0, 300.0, 220.0, 180.0, 150.0, 150.0, 150.0, 150.0])
GJ_SHAPE = np.array([150.0, 150.0, 250.0, 250.0, 350.0, 350.0, 350.0, 350.0])
EI_SCALE = 1.049
GJ_SCALE = 1.0
DEPTH = 0.026                     # beam 23/26/23 mm (tennis.com)
G_OVER_RHO, KAPPA = 3.3e6, 0.5    # carbon-epoxy, as options/bats/racket-frame.properties
# rhoJ of the handle and throat (kg m): a 2.7 cm grip (radius of gyration ~1.2 cm) and two arms
# about 5 cm off the axis; the head's level takes the rest of the twistweight.
RHOJ_HANDLE_PER_MU = 0.012 ** 2
RHOJ_THROAT_PER_MU = 0.05 ** 2


def piecewise(values_by_level):
    return np.array([values_by_level[k] for k in LEVEL])


def integrals(f_rows, g=lambda x: 1.0):
    """int_0^L f(x) g(x) dx for f linear between the rows (Gauss, 5 points a piece)."""
    xg, wg = np.polynomial.legendre.leggauss(5)
    s = 0.0
    for i in range(len(X) - 1):
        a, b = X[i], X[i + 1]
        x = 0.5 * (a + b) + 0.5 * (b - a) * xg
        t = (x - a) / (b - a)
        f = (1 - t) * f_rows[i] + t * f_rows[i + 1]
        s += 0.5 * (b - a) * np.sum(wg * f * np.vectorize(g)(x))
    return s


def strings():
    """Mass, first moment, second moment about the pivot and about the long axis of the bed."""
    a, b = HEAD_LENGTH / 2, HEAD_WIDTH / 2
    area = np.pi * a * b
    m = SIGMA * area
    return m, m * HEAD_CENTER, m * ((HEAD_CENTER - PIVOT) ** 2 + a * a / 4), SIGMA * np.pi * a * b ** 3 / 4


def solve_mu():
    ms, s1, s2, _ = strings()
    throat = piecewise([0.0, MU_THROAT, 0.0, 0.0])
    A = np.zeros((3, 3))
    for col, k in enumerate((0, 2, 3)):
        basis = piecewise([1.0 if j == k else 0.0 for j in range(4)])
        A[0, col] = integrals(basis)
        A[1, col] = integrals(basis, lambda x: x)
        A[2, col] = integrals(basis, lambda x: (x - PIVOT) ** 2)
    rhs = np.array([M_STRUNG - ms - integrals(throat), M_STRUNG * BALANCE - s1 - integrals(throat, lambda x: x),
                    SWINGWEIGHT - s2 - integrals(throat, lambda x: (x - PIVOT) ** 2)])
    h, lo, up = np.linalg.solve(A, rhs)
    return np.array([h, MU_THROAT, lo, up])


def table():
    mu_lv = solve_mu()
    mu = piecewise(mu_lv)
    _, _, _, sj = strings()
    # rhoJ: handle and throat from their mass, the head's level from what is left of the twistweight
    rj_h, rj_t = mu_lv[0] * RHOJ_HANDLE_PER_MU, mu_lv[1] * RHOJ_THROAT_PER_MU
    base = piecewise([rj_h, rj_t, 0.0, 0.0])
    head_basis = piecewise([0.0, 0.0, 1.0, 1.0])
    rj_head = (TWISTWEIGHT - sj - integrals(base)) / integrals(head_basis)
    rhoJ = piecewise([rj_h, rj_t, rj_head, rj_head])
    EI = EI_SCALE * EI_SHAPE
    GJ = GJ_SCALE * GJ_SHAPE
    kGA = KAPPA * G_OVER_RHO * mu
    rhoI = mu * DEPTH ** 2 / 12
    return mu_lv, np.column_stack([X, EI, mu, kGA, rhoI, GJ, rhoJ])


def main():
    mu_lv, T = table()
    ms, s1, s2, sj = strings()
    mu = T[:, 2]
    mf = integrals(mu)
    m1 = integrals(mu, lambda x: x) + s1
    m2 = integrals(mu, lambda x: (x - PIVOT) ** 2) + s2
    tw = integrals(T[:, 6]) + sj
    M = mf + ms
    print(f"strings: sigma {SIGMA:.4f} kg/m^2, {ms * 1e3:.2f} g over the head's ellipse")
    print(f"levels mu: handle {mu_lv[0]:.4f}, throat {mu_lv[1]:.4f} (fixed), lower head {mu_lv[2]:.4f}, upper head {mu_lv[3]:.4f} kg/m; "
          f"rhoJ head {T[-1, 6]:.4e} kg m")
    print(f"mass {M * 1e3:.2f} g (target {M_STRUNG * 1e3:.1f}), balance {m1 / M * 1e3:.2f} mm (target {BALANCE * 1e3:.1f}), "
          f"swingweight {m2 * 1e4:.2f} kg cm^2 (target {SWINGWEIGHT * 1e4:.1f}), twistweight {tw * 1e4:.2f} kg cm^2 (target {TWISTWEIGHT * 1e4:.1f})")
    icm = m2 - M * (m1 / M - PIVOT) ** 2
    print(f"moment of inertia about the centre of mass {icm:.5f} kg m^2, about the butt {icm + M * (m1 / M) ** 2:.5f} kg m^2")
    for r in T:
        print("  ".join(f"{v:.4g}" for v in r))
    if "--write" in sys.argv:
        path = os.path.join(ROOT, "options", "bats", "racket-pure-drive.properties")
        with open(path, "w") as f:
            f.write(HEADER)
            f.write("#   x (m)   EI (N m^2)   mu (kg/m)   kappaGA (N)   rhoI (kg m)   GJ (N m^2)   rhoJ (kg m)\n")
            for r in T:
                f.write(f"{r[0]:.4f}  {r[1]:.4g}  {r[2]:.5f}  {r[3]:.5g}  {r[4]:.4e}  {r[5]:.4g}  {r[6]:.4e}\n")
        print("wrote", path)


HEADER = """# A racket frame matched to the Babolat Pure Drive 2021 as measured by Tennis Addict (strung: 321 g,
# balance 330 mm from the butt, swingweight 325 kg cm^2; head 645 cm^2, 16 x 19, 27 in), with
# the string bed of racket-pure-drive.opts. Written by scripts/references/racket_design.py
# --write (the derivation and the sources: scripts/references/README.md, docs/racket-anchors.md).
# x from the butt. mu: handle 0-17 cm, throat 19-33 cm (0.25 kg/m, fixed), lower head 35-55 cm,
# upper head 57 cm to the tip, joined by 2 cm ramps; the handle's and the two head levels solve
# mass, balance and swingweight with the strings' 11.9 g.
# rhoJ: the twistweight 14.0 kg cm^2 (a typical value: not published for this racket).
# EI, GJ: shapes of our own scaled so that the free frame's first bending mode is 150 Hz and its
# first twisting mode is about 400 Hz (beamimpact -task modes); NOT measured for this racket.
# kappaGA = 0.5 (G/rho) mu with G/rho = 3.3e6 m^2/s^2; rhoI = mu a^2/12 with a = 26 mm.
"""

if __name__ == "__main__":
    main()
