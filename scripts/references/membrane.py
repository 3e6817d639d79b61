#!/usr/bin/env python3
"""The string bed as a membrane: its modes on a rectangle, a circle and an ellipse, its static
stiffness under a ball-sized patch, and the published racket numbers. An independent reference
for the racket head of issue 25 (MODEL.md section 11).

    /usr/bin/python3 scripts/references/membrane.py

Membrane: sigma w_tt = N_x w_xx + N_z w_zz - p, w = 0 on the edge (a held frame).
  rectangle a x b:  f_mn = (1/2) sqrt((N_x (m/a)^2 + N_z (n/b)^2) / sigma)
  circle R (N_x = N_z = N): f_mk = j_mk / (2 pi R) sqrt(N/sigma), j_mk the Bessel zeros
  ellipse (semi-axes a, b): the even fundamental solves Mc1_0(xi0, q) = 0 (radial Mathieu
      function), h = sqrt(a^2 - b^2), cosh xi0 = a/h, k^2 = 4q/h^2, f = k/(2 pi) sqrt(N/sigma);
      unequal tensions map onto equal ones on the ellipse of semi-axes a/sqrt(N_x), b/sqrt(N_z)
  Independent check of all three: a Rayleigh-Ritz solution on the ellipse (polynomials times
  the edge factor 1 - x^2/a^2 - z^2/b^2, exact quadrature in elliptic polar coordinates).
Static stiffness of a circular bed of radius R, tension N, load F on a central patch of radius c:
  rigid flat disc (prescribed deflection):  k = 2 pi N / ln(R/c)            (MODEL.md's formula)
  uniform pressure on the patch:  deflection at the centre F/(2 pi N) (ln(R/c) + 1/2),
      mean over the patch F/(2 pi N) (ln(R/c) + 1/4)
A woven bed of strings of tension T, mass per length lambda, spacings s_m and s_c:
  N_x = T/s_m, N_z = T/s_c, sigma = lambda/s_m + lambda/s_c   (MODEL.md section 11).
Sources and every number compared: scripts/references/README.md.
"""
import os
import sys

from _common import need, table, percent  # noqa: E402

need(__file__, "numpy", "scipy")
import numpy as np  # noqa: E402
from numpy.polynomial import legendre as leg  # noqa: E402
from scipy.linalg import eigh, solve  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import jn_zeros, mathieu_modcem1, j1  # noqa: E402

LB = 4.4482216  # N per pound-force
STATIC_DEG = 40  # total degree of the even-even Ritz basis for the patch loads


def rectangle_f(a, b, Nx, Nz, sigma, m, n):
    return 0.5 * np.sqrt((Nx * (m / a) ** 2 + Nz * (n / b) ** 2) / sigma)


def circle_f(R, N, sigma, m, k):
    return jn_zeros(m, k)[-1] / (2 * np.pi * R) * np.sqrt(N / sigma)


def ellipse_mathieu_f(a, b, N, sigma):
    """Fundamental of an isotropic elliptical membrane from the radial Mathieu function."""
    if a < b:
        a, b = b, a
    h = np.sqrt(a * a - b * b)
    xi0 = np.arccosh(a / h)

    def g(q):
        return mathieu_modcem1(0, q, xi0)[0]
    qs = np.linspace(1e-3, 50.0, 5001)
    gs = [g(q) for q in qs]
    for i in range(len(qs) - 1):
        if np.sign(gs[i]) != np.sign(gs[i + 1]):
            q = brentq(g, qs[i], qs[i + 1], xtol=1e-14)
            return np.sqrt(4 * q) / h / (2 * np.pi) * np.sqrt(N / sigma)
    raise RuntimeError("no root")


class EllipseRitz:
    """Rayleigh-Ritz for the membrane on the ellipse x^2/a^2 + z^2/b^2 <= 1 (a rectangle is
    done by the same code with the edge factor (1 - xi^2)(1 - eta^2) on [-a,a] x [-b,b])."""

    def __init__(self, a, b, Nx, Nz, sigma, deg=16, shape="ellipse", nr=48, nt=128, even=False):
        self.a, self.b, self.Nx, self.Nz, self.sigma, self.shape = a, b, Nx, Nz, sigma, shape
        if shape == "ellipse":
            r, wr = leg.leggauss(nr)
            r, wr = 0.5 * (r + 1.0), 0.5 * wr
            t = 2 * np.pi * np.arange(nt) / nt
            R, T = np.meshgrid(r, t, indexing="ij")
            xi, eta = (R * np.cos(T)).ravel(), (R * np.sin(T)).ravel()
            w = (np.outer(wr * r, np.full(nt, 2 * np.pi / nt))).ravel() * a * b
            B, Bx, Bz = 1 - xi ** 2 - eta ** 2, -2 * xi / a, -2 * eta / b
        else:
            g, wg = leg.leggauss(nr)
            XI, ETA = np.meshgrid(g, g, indexing="ij")
            xi, eta = XI.ravel(), ETA.ravel()
            w = np.outer(wg, wg).ravel() * a * b
            B = (1 - xi ** 2) * (1 - eta ** 2)
            Bx, Bz = -2 * xi * (1 - eta ** 2) / a, -2 * eta * (1 - xi ** 2) / b
        self.xi, self.eta, self.w = xi, eta, w
        self.deg = deg
        idx = [(i, j) for i in range(deg + 1) for j in range(deg + 1)
               if i + j <= deg and (not even or (i % 2 == 0 and j % 2 == 0))]
        self.idx = idx  # even: only the modes and loads symmetric about both axes
        phi, phx, phz = self.basis(xi, eta, B, Bx, Bz)
        self.phi = phi
        K = Nx * (phx * w) @ phx.T + Nz * (phz * w) @ phz.T
        M = sigma * (phi * w) @ phi.T
        # an orthonormal basis of the span (the polynomial basis is ill-conditioned at high degree)
        lam, V = np.linalg.eigh(M)
        keep = lam > 1e-12 * lam.max()
        self.Z = V[:, keep] / np.sqrt(lam[keep])
        self.K, self.M = K, M

    def basis(self, xi, eta, B=None, Bx=None, Bz=None):
        """Basis values and x, z derivatives at (xi, eta) = (x/a, z/b)."""
        a, b = self.a, self.b
        if B is None:
            if self.shape == "ellipse":
                B, Bx, Bz = 1 - xi ** 2 - eta ** 2, -2 * xi / a, -2 * eta / b
            else:
                B = (1 - xi ** 2) * (1 - eta ** 2)
                Bx, Bz = -2 * xi * (1 - eta ** 2) / a, -2 * eta * (1 - xi ** 2) / b
        eye = np.eye(self.deg + 1)
        Pxi = np.array([leg.legval(xi, eye[i]) for i in range(self.deg + 1)])
        Peta = np.array([leg.legval(eta, eye[i]) for i in range(self.deg + 1)])
        dPxi = np.array([leg.legval(xi, leg.legder(eye[i])) for i in range(self.deg + 1)])
        dPeta = np.array([leg.legval(eta, leg.legder(eye[i])) for i in range(self.deg + 1)])
        phi = np.array([B * Pxi[i] * Peta[j] for i, j in self.idx])
        phx = np.array([Bx * Pxi[i] * Peta[j] + B * dPxi[i] / a * Peta[j] for i, j in self.idx])
        phz = np.array([Bz * Pxi[i] * Peta[j] + B * Pxi[i] * dPeta[j] / b for i, j in self.idx])
        return phi, phx, phz

    def frequencies(self, count=6):
        lam = eigh(self.Z.T @ self.K @ self.Z, eigvals_only=True)
        return np.sqrt(lam[:count]) / (2 * np.pi)

    def patch_stiffness(self, c, nr=40, nt=96):
        """Uniform pressure on the central disc of radius c (total force 1), integrated on its own
        polar grid: stiffness from the centre deflection and from the mean deflection (N/m)."""
        r, wr = leg.leggauss(nr)
        r, wr = 0.5 * c * (r + 1.0), 0.5 * c * wr
        th = 2 * np.pi * np.arange(nt) / nt
        Rg, Tg = np.meshgrid(r, th, indexing="ij")
        x, z = (Rg * np.cos(Tg)).ravel(), (Rg * np.sin(Tg)).ravel()
        wq = np.outer(wr * r, np.full(nt, 2 * np.pi / nt)).ravel()
        phi, _, _ = self.basis(x / self.a, z / self.b)
        p = 1.0 / (np.pi * c * c)
        f = phi @ (wq * p)
        y = np.linalg.solve(self.Z.T @ self.K @ self.Z, self.Z.T @ f)
        coef = self.Z @ y
        w0 = coef @ self.basis(np.zeros(1), np.zeros(1))[0][:, 0]
        wbar = coef @ f          # = int p w dA / F with F = 1: the mean deflection over the patch
        return 1.0 / w0, 1.0 / wbar


def report_modes():
    sigma, N = 0.2, 16000.0
    rows = []
    a, b = 0.30, 0.20
    Nx, Nz = 18000.0, 14000.0
    rz = EllipseRitz(a / 2, b / 2, Nx, Nz, sigma, deg=16, shape="rectangle")
    fr = rz.frequencies(6)
    exact = sorted(rectangle_f(a, b, Nx, Nz, sigma, m, n) for m in range(1, 6) for n in range(1, 6))[:6]
    for k in range(6):
        rows.append(["rectangle 0.30 x 0.20, N_x 18000, N_z 14000", k + 1, exact[k], fr[k],
                     percent(fr[k], exact[k])])
    R = 0.15
    cz = EllipseRitz(R, R, N, N, sigma, deg=18)
    fc = cz.frequencies(6)
    ex_c = sorted([circle_f(R, N, sigma, 0, 1), circle_f(R, N, sigma, 1, 1), circle_f(R, N, sigma, 1, 1),
                   circle_f(R, N, sigma, 2, 1), circle_f(R, N, sigma, 2, 1), circle_f(R, N, sigma, 0, 2)])
    for k in range(6):
        rows.append(["circle R = 0.15, N 16000", k + 1, ex_c[k], fc[k], percent(fc[k], ex_c[k])])
    for (ae, be) in ((0.17, 0.125), (0.16, 0.12), (0.20, 0.10)):
        ez = EllipseRitz(ae, be, N, N, sigma, deg=18)
        f1 = ez.frequencies(1)[0]
        fm = ellipse_mathieu_f(ae, be, N, sigma)
        rows.append(["ellipse %.3f x %.3f (Mathieu)" % (ae, be), 1, fm, f1, percent(f1, fm)])
    Nx, Nz = 17500.0, 15300.0
    ae, be = 0.17, 0.125
    ez = EllipseRitz(ae, be, Nx, Nz, sigma, deg=18)
    # unequal tensions: equal tension N0 on the ellipse of semi-axes a sqrt(N0/N_x), b sqrt(N0/N_z)
    fm = ellipse_mathieu_f(ae * np.sqrt(N / Nx), be * np.sqrt(N / Nz), N, sigma)
    f1 = ez.frequencies(1)[0]
    rows.append(["ellipse 0.17 x 0.125, N_x 17500, N_z 15300", 1, fm, f1, percent(f1, fm)])
    table("(1) membrane modes (sigma = 0.2 kg/m^2): analytic (rectangle, Bessel zeros, Mathieu) against "
          "an independent Ritz solution, Hz",
          ["shape", "mode", "analytic", "Ritz", "diff %"], rows, ["%s", "%d", "%.4f", "%.4f", "%+.1e"])
    rows = []
    for ae, be in ((0.15, 0.15), (0.17, 0.125), (0.16, 0.12), (0.20, 0.10), (0.25, 0.08)):
        A = np.pi * ae * be
        f = ellipse_mathieu_f(ae, be, N, sigma) if ae != be else circle_f(ae, N, sigma, 0, 1)
        fcirc = circle_f(np.sqrt(A / np.pi), N, sigma, 0, 1)
        fsq = 0.5 * np.sqrt(2 * N / sigma / A)
        rows.append([ae, be, ae / be, A * 1e4, f, fcirc, percent(f, fcirc), fsq])
    table("    shape against area (Cross & Bower: the frequency depends mainly on the area): the "
          "ellipse against the circle and the square of equal area",
          ["a m", "b m", "a/b", "area cm^2", "ellipse Hz", "circle Hz", "diff %", "square Hz"], rows,
          ["%.3f", "%.3f", "%.2f", "%.1f", "%.2f", "%.2f", "%+.2f", "%.2f"])


def report_stiffness():
    N = 16000.0
    R = 0.15
    rows = []
    cz = EllipseRitz(R, R, N, N, 0.2, deg=STATIC_DEG, nr=48, nt=96, even=True)
    for c in (0.01, 0.02, 0.03, 0.05):
        k_disc = 2 * np.pi * N / np.log(R / c)
        k_c = 2 * np.pi * N / (np.log(R / c) + 0.5)
        k_m = 2 * np.pi * N / (np.log(R / c) + 0.25)
        kr_c, kr_m = cz.patch_stiffness(c)
        rows.append([c * 100, k_disc, k_c, kr_c, percent(kr_c, k_c), k_m, kr_m, percent(kr_m, k_m)])
    table("(2) static stiffness of a circular bed (R = 0.15 m, N = 16000 N/m) under a central patch "
          "of radius c, N/m: rigid disc, uniform pressure (centre and mean deflection) against Ritz",
          ["c cm", "rigid disc", "pressure, centre", "Ritz", "diff %", "pressure, mean", "Ritz",
           "diff %"], rows, ["%.0f", "%.0f", "%.0f", "%.0f", "%+.2f", "%.0f", "%.0f", "%+.2f"])
    rows = []
    for (ae, be, Nx, Nz) in ((0.17, 0.125, 17500.0, 15300.0), (0.17, 0.125, 14000.0, 12200.0)):
        ez = EllipseRitz(ae, be, Nx, Nz, 0.2, deg=STATIC_DEG, nr=48, nt=96, even=True)
        Rq = np.sqrt(ae * be)
        Nq = np.sqrt(Nx * Nz)
        for c in (0.02, 0.03):
            kc, km = ez.patch_stiffness(c)
            rows.append([ae, be, Nx, Nz, c * 100, kc, km, 2 * np.pi * Nq / (np.log(Rq / c) + 0.25)])
    table("    elliptical bed, unequal tensions (Ritz): stiffness under a uniform patch, and the "
          "circle formula with R = sqrt(a b), N = sqrt(N_x N_z)",
          ["a m", "b m", "N_x", "N_z", "c cm", "k centre", "k mean", "circle formula (mean)"], rows,
          ["%.3f", "%.3f", "%.0f", "%.0f", "%.0f", "%.0f", "%.0f", "%.0f"])


def string_bed(T, lam, s_m, s_c):
    return T / s_m, T / s_c, lam / s_m + lam / s_c


def report_racket():
    # a 100 in^2 head (645 cm^2): ellipse 0.34 x 0.24 m; 16 mains x 19 crosses
    ae, be = 0.170, 0.1208
    s_m, s_c = 2 * be / 16, 2 * ae / 19
    rows = []
    for name, lam in (("nylon 1.30 mm (1.51 g/m)", 1140 * np.pi * 0.65e-3 ** 2),
                      ("polyester 1.25 mm (1.69 g/m)", 1380 * np.pi * 0.625e-3 ** 2),
                      ("gut 1.30 mm (1.69 g/m)", 1270 * np.pi * 0.65e-3 ** 2)):
        for T_lb in (40.0, 50.0, 55.0, 60.0, 70.0):
            T = T_lb * LB
            Nx, Nz, sigma = string_bed(T, lam, s_m, s_c)
            f_ell = ellipse_mathieu_f(ae * np.sqrt(Nz / Nx), be, Nz, sigma)
            L = np.sqrt(np.pi * ae * be)
            f_cross = np.sqrt(T / (4 * lam * L * L))
            rows.append([name, T_lb, T, f_ell, f_cross, f_ell * 0.7 ** 0.5])
    table("(3) string-bed frequency of a 100 in^2 head (ellipse %.0f x %.0f cm, 16 x 19), strings at "
          "tension T; Cross's formula sqrt(T / (4 lambda L^2)), L^2 = area; 'after stringing' is 70 %% "
          "of the pull tension (Cross & Bower); measured: 500-700 Hz (Cross 2006)"
          % (200 * ae, 200 * be),
          ["string", "T lb", "T N", "membrane Hz", "Cross formula Hz", "membrane at 0.7 T"], rows,
          ["%s", "%.0f", "%.0f", "%.0f", "%.0f", "%.0f"])

    # the program's racket (Cross 1999): free-free first bending mode of a uniform beam
    L, a_thk, E_rho = 0.72, 0.020, 1e7
    f1 = 4.730041 ** 2 / (2 * np.pi * L ** 2) * np.sqrt(E_rho * a_thk ** 2 / 12.0)
    print("\n    frame: the program's racket (L = 72 cm, a = 20 mm, E/rho = 1e7 N m/kg, MODEL.md section 4)"
          " has its free-free fundamental at %.1f Hz (measured rackets: 100-150 Hz)" % f1)

    # tension trend on a held frame: ball (tennis, 57 g) in series with the bed (massless bed)
    from series_spring import e_series
    m_b, k_ball, e0 = 0.057, 2.0e4, 0.75
    lam = 1140 * np.pi * 0.65e-3 ** 2
    rows = []
    for T_lb in (40.0, 50.0, 55.0, 60.0, 70.0):
        T = T_lb * LB
        Nx, Nz, sigma = string_bed(T, lam, s_m, s_c)
        ez = EllipseRitz(ae, be, Nx, Nz, sigma, deg=STATIC_DEG, nr=48, nt=96, even=True)
        k_bed = ez.patch_stiffness(0.02)[1]
        r = k_ball / k_bed
        rows.append([T_lb, k_bed, r, e_series(e0, r)])
    table("    tension trend on a rigid (held) frame: tennis ball (k = 2e4 N/m, e0 = 0.75) in series with "
          "the bed's stiffness under a 2 cm patch (massless bed, series_spring.py formula)",
          ["T lb", "k_bed N/m", "r = k_ball/k_bed", "e"], rows, ["%.0f", "%.0f", "%.3f", "%.4f"])


def main():
    print("membrane.py: the string bed as a membrane, modes and static stiffness; racket numbers")
    report_modes()
    report_stiffness()
    report_racket()


if __name__ == "__main__":
    main()
