#!/usr/bin/env python3
"""A ball striking a string bed (a membrane) held in a rigid frame, by the bed's analytic modes.
An independent reference for the racket head of issue 25 (MODEL.md section 11): the program
solves the bed on a finite-difference grid, this script by exact modes and an exact solution in
time.

    /usr/bin/python3 scripts/references/bed_impact.py            # tables, ~30 s of CPU
    /usr/bin/python3 scripts/references/bed_impact.py --json     # the results as one JSON object

Bed: sigma w_tt = N_x w_xx + N_z w_zz + p(x, z, t), w = 0 on the edge; w is the deflection in the
ball's direction of travel (the program's MODEL.md writes -p with w the other way). Ball: mass
m_b, displacement y toward the bed, speed v at t = 0, just touching the bed at rest. Force
F = k c while c > 0, c = y - int (p/F) w dA (the bed under the ball averaged with the load's own
weights, so that F c is the work rate). The load is a paraboloid on a disc of radius a centred at
the impact point: p = F 2/(pi a^2) (1 - r^2/a^2). Contact ends at the first zero of c.

Modes, mass-normalised (int sigma phi_i phi_j dA = delta_ij):
  circle R, N_x = N_z = N:  J_m(j_mk r/R) cos(m theta) / sqrt(sigma pi R^2 J_{m+1}(j_mk)^2 (1 + delta_m0)/2)
  rectangle Lx x Lz:         2 sin(i pi x/Lx) sin(j pi z/Lz) / sqrt(sigma Lx Lz)
Participation g = int (p/F) phi dA. Every mode solves (Laplacian + kappa^2) phi = 0 (kappa = j_mk/R,
or kappa^2 = (i pi/Lx)^2 + (j pi/Lz)^2), so by the mean-value theorem of the Helmholtz equation a
radial load centred at x0 gives exactly g = phi(x0) P(kappa a), P(s) = 8 J_2(s)/s^2 (the load's
Fourier transform). Checked against a direct quadrature over the patch for every kept mode.

Ball and n kept modes: M x'' + K x = 0, x = (y, q_1..q_n), M = diag(m_b, 1..1),
K = diag(0, omega_i^2) + k_e h h^T, h = (1, -g). The modes above the kept ones enter by their
static flexibility f_res = f_static - sum_kept g_i^2/omega_i^2, in series with k:
1/k_e = 1/k + f_res (exact for the modes much stiffer than the contact; the error of this is
shown by the convergence in n). The system is solved exactly: eigen-decomposition of
M^-1/2 K M^-1/2, x(t) a sum of sines, c(t) in closed form, its first zero by brentq on a fine
bracket. The bed under the ball's centre adds F(t) (u_static(x0)/F - sum_kept g_i phi_i(x0)/omega_i^2).

Static flexibility of the circle, exact (Green's function of the disc and the mean-value property of
its harmonic regular part; p radial about x0 at r0 < R - a):
  f_static = int int p G p / F^2 = (ln(R (1 - r0^2/R^2)/a) + 11/24) / (2 pi N)
  u_static(x0)/F                  = (ln(R (1 - r0^2/R^2)/a) + 3/4) / (2 pi N)
Of the rectangle: the modal sums over ~ 10^6 modes (their convergence is printed), checked by
the single (Levy) sine series in x with each term's z-problem solved by its Green's function.
Sources, numbers and the self-checks: scripts/references/README.md.
"""
from _common import need, table  # noqa: E402

need(__file__, "numpy", "scipy")
import argparse  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from numpy.polynomial import legendre as leg  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402
from scipy.linalg import eigh  # noqa: E402
from scipy.optimize import brentq  # noqa: E402
from scipy.special import jn_zeros, jv  # noqa: E402


def patch_transform(s):
    """Fourier transform of the unit paraboloid load on a disc, 8 J_2(s)/s^2 (1 at s = 0)."""
    s = np.asarray(s, dtype=float)
    out = np.empty_like(s)
    small = s < 1e-3
    out[small] = 1.0 - s[small] ** 2 / 12.0
    out[~small] = 8.0 * jv(2, s[~small]) / s[~small] ** 2
    return out


def patch_quadrature(a, nr=28, nt=96):
    """Points (offsets from the patch centre) and weights of p/F on the disc of radius a."""
    r, wr = leg.leggauss(nr)
    r, wr = 0.5 * a * (r + 1.0), 0.5 * a * wr
    th = 2 * np.pi * np.arange(nt) / nt
    Rg, Tg = np.meshgrid(r, th, indexing="ij")
    dx, dz = (Rg * np.cos(Tg)).ravel(), (Rg * np.sin(Tg)).ravel()
    w = np.outer(wr * r * (2.0 / (np.pi * a * a)) * (1 - r ** 2 / a ** 2),
                 np.full(nt, 2 * np.pi / nt)).ravel()
    return dx, dz, w


class Bed:
    """Modes of a bed under one impact point, sorted by frequency, those with g != 0 only;
    the exact (or summed) static flexibility at the load and deflection under its centre."""

    def kept(self, n):
        n = min(n, len(self.omega))
        return self.omega[:n], self.g[:n], self.phic[:n]

    def residual(self, n):
        w, g, ph = self.kept(n)
        return self.f_static - np.sum(g * g / w ** 2), self.u_static - np.sum(g * ph / w ** 2)


class Circle(Bed):
    def __init__(self, R, N, sigma, r0, a, J):
        """All modes with j_mk <= J (m = 0 only for a central load)."""
        self.R, self.N, self.sigma, self.r0, self.a = R, N, sigma, r0, a
        ms, js = [], []
        for m in ([0] if r0 == 0 else range(int(J) + 1)):
            nz = int((J - m) / np.pi) + 2   # zeros of J_m are > m apart by > pi (m >= 1)
            z = jn_zeros(m, nz)
            z = z[z <= J]
            if len(z) == 0:
                break
            ms += [m] * len(z)
            js += list(z)
        m, j = np.array(ms), np.array(js)
        o = np.argsort(j, kind="stable")
        m, j = m[o], j[o]
        kappa = j / R
        self.m, self.j, self.kappa = m, j, kappa
        self.norm = np.sqrt(sigma * np.pi * R * R * jv(m + 1, j) ** 2 * np.where(m == 0, 2.0, 1.0) / 2)
        self.omega = kappa * np.sqrt(N / sigma)
        self.phic = jv(m, kappa * r0) / self.norm
        self.g = self.phic * patch_transform(kappa * a)
        keep = np.abs(self.phic) > 1e-12 * np.abs(self.phic).max()
        for name in ("m", "j", "kappa", "norm", "omega", "phic", "g"):
            setattr(self, name, getattr(self, name)[keep])
        L = np.log(R * (1 - r0 * r0 / (R * R)) / a)
        self.f_static = (L + 11.0 / 24.0) / (2 * np.pi * N)
        self.u_static = (L + 0.75) / (2 * np.pi * N)
        self.static_source = "closed form"

    def phi_at(self, x, z, n):
        """Kept modes at points (x, z) from the circle's centre: array n x len(x)."""
        r, th = np.hypot(x, z), np.arctan2(z, x)
        m, k = self.m[:n, None], self.kappa[:n, None]
        return jv(m, k * r[None, :]) * np.cos(m * th[None, :]) / self.norm[:n, None]

    def centre(self):
        return self.r0, 0.0


class Rectangle(Bed):
    def __init__(self, Lx, Lz, Nx, Nz, sigma, x0, z0, a, ka_sum, kappa_keep):
        """Modes with kappa <= ka_sum/a for the static sums; the dynamic list those with
        kappa <= kappa_keep, by frequency. (x0, z0) is measured from the rectangle's centre."""
        self.Lx, self.Lz, self.Nx, self.Nz, self.sigma, self.a = Lx, Lz, Nx, Nz, sigma, a
        self.x0, self.z0 = x0, z0
        X0, Z0 = Lx / 2 + x0, Lz / 2 + z0
        amp = 2.0 / np.sqrt(sigma * Lx * Lz)
        # static sums over all modes with kappa <= K, several K (convergence), in slabs of i
        Ks = np.array([25.0, 50.0, 100.0, 200.0, ka_sum]) / a
        Ks = Ks[Ks <= ka_sum / a]
        fs, us = np.zeros(len(Ks)), np.zeros(len(Ks))
        K = Ks[-1]
        imax = int(K * Lx / np.pi)
        jj = np.arange(1, int(K * Lz / np.pi) + 1)
        sz = np.sin(jj * np.pi * Z0 / Lz)
        for i in range(1, imax + 1):
            al = i * np.pi / Lx
            be = jj * np.pi / Lz
            kap = np.hypot(al, be)
            ph = amp * np.sin(al * X0) * sz
            om2 = (Nx * al * al + Nz * be * be) / sigma
            P = patch_transform(kap * a)
            tf, tu = ph * ph * P * P / om2, ph * ph * P / om2
            for q, Kq in enumerate(Ks):
                sel = kap <= Kq
                fs[q] += tf[sel].sum()
                us[q] += tu[sel].sum()
        self.static_sums = list(zip(Ks * a, fs, us))
        self.f_static, self.u_static = fs[-1], us[-1]
        self.static_source = "modal sum, kappa a <= %g" % ka_sum
        # the dynamic list
        ii, jj = np.meshgrid(np.arange(1, int(kappa_keep * Lx / np.pi) + 2),
                             np.arange(1, int(kappa_keep * Lz / np.pi) + 2), indexing="ij")
        ii, jj = ii.ravel(), jj.ravel()
        al, be = ii * np.pi / Lx, jj * np.pi / Lz
        kap = np.hypot(al, be)
        sel = kap <= kappa_keep
        ii, jj, al, be, kap = ii[sel], jj[sel], al[sel], be[sel], kap[sel]
        om = np.sqrt((Nx * al * al + Nz * be * be) / sigma)
        ph = amp * np.sin(al * X0) * np.sin(be * Z0)
        keep = np.abs(ph) > 1e-9 * amp
        o = np.argsort(om[keep], kind="stable")
        self.i, self.jz = ii[keep][o], jj[keep][o]
        self.kappa, self.omega, self.phic = kap[keep][o], om[keep][o], ph[keep][o]
        self.g = self.phic * patch_transform(self.kappa * a)
        self.amp, self.X0, self.Z0 = amp, X0, Z0

    def phi_at(self, x, z, n):
        X, Z = x + self.Lx / 2, z + self.Lz / 2
        return (self.amp * np.sin(self.i[:n, None] * np.pi * X[None, :] / self.Lx)
                * np.sin(self.jz[:n, None] * np.pi * Z[None, :] / self.Lz))

    def centre(self):
        return self.x0, self.z0


def rect_levy(Lx, Lz, Nx, Nz, X0, Z0, a, ka_max, nq=None):
    """Static flexibility f and deflection u(x0)/F of the rectangle by the single (Levy) sine
    series in x: each term's 1-D problem N_z U'' - N_x alpha^2 U = -p_i(z) solved by its exact
    Green's function, the load's x-integral in closed form, the z-integrals by Gauss-Legendre
    in z = Z0 + a sin(theta) (split at the kink)."""
    I = int(ka_max * Lx / (np.pi * a))
    nq = nq or int(0.6 * ka_max) + 20
    t, wt = leg.leggauss(nq)
    def nodes(lo, hi):
        return 0.5 * (hi - lo) * t + 0.5 * (hi + lo), 0.5 * (hi - lo) * wt
    def G(mu, z, zeta):   # 1-D Green's function on [0, Lz], times N_z
        d, s = np.abs(z - zeta), z + zeta
        num = np.exp(-mu * d) - np.exp(-mu * s) - np.exp(-mu * (2 * Lz - s)) + np.exp(-mu * (2 * Lz - d))
        return num / (2 * mu * (1 - np.exp(-2 * mu * Lz)))
    def load(alpha, th):   # p_i(z) at z = Z0 + a sin th, unit force, times dz/dth
        x = alpha * a * np.cos(th)
        core = np.where(x < 1e-2, x ** 3 / 3 - x ** 5 / 30, np.sin(x) - x * np.cos(x))
        return ((2 / Lx) * (2 / (np.pi * a ** 4)) * np.sin(alpha * X0) * 4 * core / alpha ** 3
                * a * np.cos(th))
    f = u = 0.0
    thl, wl = nodes(-np.pi / 2, 0.0)
    thr, wr = nodes(0.0, np.pi / 2)
    th1, w1 = nodes(-np.pi / 2, np.pi / 2)
    for i in range(1, I + 1):
        al = i * np.pi / Lx
        mu = al * np.sqrt(Nx / Nz)
        for th, w in ((thl, wl), (thr, wr)):
            u += np.sin(al * X0) * np.sum(w * G(mu, Z0, Z0 + a * np.sin(th)) * load(al, th)) / Nz
        # the triangle theta' < theta (the kernel symmetric: twice it)
        T = th1[:, None]
        lo = -np.pi / 2
        th2 = 0.5 * (T - lo) * t[None, :] + 0.5 * (T + lo)
        w2 = 0.5 * (T - lo) * wt[None, :]
        P1 = load(al, th1)[:, None]
        P2 = load(al, th2)
        K = G(mu, Z0 + a * np.sin(T), Z0 + a * np.sin(th2))
        f += 2 * (Lx / 2) * np.sum(w1[:, None] * w2 * P1 * P2 * K) / Nz
    return f, u


def participation_check(bed, n):
    """Largest difference of the closed-form g from a direct quadrature over the patch, relative
    to the largest |g|, over the first n modes."""
    n = min(n, len(bed.omega))
    ka = bed.kappa[:n].max() * bed.a     # enough points for the fastest mode's waves on the patch
    dx, dz, w = patch_quadrature(bed.a, nr=max(28, int(0.6 * ka) + 24), nt=max(96, int(2 * ka) + 48))
    cx, cz = bed.centre()
    gq = np.zeros(n)
    for s in range(0, n, 200):
        e = min(n, s + 200)
        gq[s:e] = bed.phi_at(cx + dx, cz + dz, e)[s:e] @ w
    return np.max(np.abs(gq - bed.g[:n])) / np.max(np.abs(bed.g[:n]))


def sines(coef, om, t, deriv=0):
    """sum_j coef_j sin(om_j t) (deriv 0) or its derivative (deriv 1), t an array."""
    out = np.empty(len(t))
    for s in range(0, len(t), 512):
        tt = np.outer(t[s:s + 512], om)
        out[s:s + 512] = (np.sin(tt) @ coef) if deriv == 0 else (np.cos(tt) @ (coef * om))
    return out


def first_max(coef, om, t, vals):
    """Largest value of sum coef sin(om t) over the grid t, refined at the zero of its derivative."""
    i = int(np.argmax(vals))
    lo, hi = t[max(i - 1, 0)], t[min(i + 1, len(t) - 1)]
    d = lambda x: sines(coef, om, np.array([x]), 1)[0]  # noqa: E731
    if d(lo) > 0 > d(hi):
        tm = brentq(d, lo, hi, xtol=1e-16, rtol=1e-15, maxiter=200)
        return sines(coef, om, np.array([tm]))[0], tm
    return vals[i], t[i]


def merge_degenerate(omega, g, phic, rel=1e-12):
    """Modes of one frequency act on the ball as one: g = sqrt(sum g^2), phi = sum g phi / g
    (the combinations orthogonal to it are not excited). Exact; needed by the secular solver."""
    w, gg, pp = [omega[0]], [g[0] ** 2], [g[0] * phic[0]]
    for i in range(1, len(omega)):
        if omega[i] - w[-1] <= rel * omega[i]:
            gg[-1] += g[i] ** 2
            pp[-1] += g[i] * phic[i]
        else:
            w.append(omega[i])
            gg.append(g[i] ** 2)
            pp.append(g[i] * phic[i])
    geff = np.sqrt(np.array(gg))
    return np.array(w), geff, np.array(pp) / geff


def secular_eig(d, z, rho):
    """Eigen-decomposition of diag(d) + rho z z^T (d strictly ascending, rho > 0): the root
    lambda_j of 1/rho + sum z_i^2/(d_i - lambda) in (d_j, d_j+1), found as lambda_j = o_j + delta_j
    from the nearer pole o_j by bisection of |delta_j| on a log scale (relative precision ~1e-17
    whatever the span of d), vectors z_i/(d_i - lambda_j) from the same differences."""
    gap = np.append(np.diff(d), rho * (z @ z))
    z2 = z * z

    def sec(o, delta):                  # the secular function at o_j + delta_j, all j at once
        return 1.0 / rho + ((d[None, :] - o[:, None]) - delta[:, None]) ** -1.0 @ z2
    left = sec(d, 0.5 * gap) >= 0.0    # root in (d_j, d_j + gap/2]: measure from d_j
    left[-1] = True                     # the last root: above d_n by at most rho z.z
    o = np.where(left, d, np.append(d[1:], 0.0))
    sgn = np.where(left, 1.0, -1.0)
    hi = 0.5 * gap
    hi[-1] = gap[-1]
    lo = hi * 1e-60
    for _ in range(72):
        mid = np.sqrt(lo * hi)
        f = sec(o, sgn * mid)
        # f grows with lambda. From the left pole (lambda = o + |delta|) f > 0 puts the root at
        # a smaller |delta|; from the right one (lambda = o - |delta|) f < 0 does.
        shrink = np.where(left, f > 0, f < 0)
        hi = np.where(shrink, mid, hi)
        lo = np.where(shrink, lo, mid)
    delta = sgn * np.sqrt(lo * hi)
    lam = o + delta
    V = z[:, None] / ((d[:, None] - o[None, :]) - delta[None, :])
    V /= np.linalg.norm(V, axis=0)
    return lam, V


def impact(omega, g, phic, f_res, u_res, mb, k, v, f_static=0.0, points=6000, solver="secular"):
    """The ball against the kept modes (exact in time); the residual modes as a static spring.
    solver: "secular" (the arrowhead structure, default) or "eigh" (LAPACK on the full matrix)."""
    ke = 1.0 / (1.0 / k + f_res)
    omega_all = omega
    omega, g, phic = merge_degenerate(omega, g, phic)
    ht = np.concatenate([[1.0 / np.sqrt(mb)], -g])
    if solver == "eigh":
        lam, V = eigh(np.diag(np.concatenate([[0.0], omega ** 2])) + ke * np.outer(ht, ht))
    else:
        lam, V = secular_eig(np.concatenate([[0.0], omega ** 2]), ht, ke)
    Om = np.sqrt(lam)
    b = np.sqrt(mb) * v * V[0, :]
    X = V * (b / Om)                     # (M^1/2 x)(t) = X sin(Om t)
    ycoef = X[0] / np.sqrt(mb)
    scoef = ht @ X                       # y - g.q
    qcoef = X[1:]
    ucoef = phic @ qcoef + ke * u_res * scoef
    # the first zero of the compression: a fine grid, then brentq
    T_est = np.pi * np.sqrt(mb * (1.0 / k + f_static))
    t0, ts = 0.0, None
    while ts is None:
        t = np.linspace(t0, t0 + 2 * T_est, points + 1)[1:]
        s = sines(scoef, Om, t)
        neg = np.nonzero(s <= 0)[0]
        if len(neg):
            i = neg[0]
            lo = t[i - 1] if i > 0 else t0
            ts = brentq(lambda x: sines(scoef, Om, np.array([x]))[0], lo, t[i],
                        xtol=1e-16, rtol=1e-15, maxiter=200)
        t0 += 2 * T_est
        if t0 > 50 * T_est:
            raise RuntimeError("no separation")
    tg = np.linspace(0.0, ts, points + 1)
    smax, _ = first_max(scoef, Om, tg, sines(scoef, Om, tg))
    umax, tu = first_max(ucoef, Om, tg, sines(ucoef, Om, tg))
    vy = sines(ycoef, Om, np.array([ts]), 1)[0]
    q = np.sin(Om * ts) @ qcoef.T
    qd = (np.cos(Om * ts) * Om) @ qcoef.T
    e_bed = 0.5 * np.sum(qd ** 2 + (omega * q) ** 2) / (0.5 * mb * v * v)
    acor = -vy / v
    return dict(acor=acor, contact_time=ts, peak_force=ke * smax, max_deflection=umax,
                time_of_max_deflection=tu, energy_fraction=e_bed,
                energy_balance=acor ** 2 + e_bed - 1.0, modes=len(omega_all),
                f_max_hz=omega_all[-1] / (2 * np.pi), k_series=ke)


def impact_ode(omega, g, f_res, mb, k, v, T):
    """The same system by an adaptive Runge-Kutta integration (an independent check of the
    eigen-solution), stopped at the compression's first zero."""
    ke = 1.0 / (1.0 / k + f_res)
    n = len(omega)

    def rhs(t, x):
        y, q, yd, qd = x[0], x[1:n + 1], x[n + 1], x[n + 2:]
        F = ke * (y - g @ q)
        return np.concatenate([[yd], qd, [-F / mb], -omega ** 2 * q + F * g])

    def sep(t, x):
        return x[0] - g @ x[1:n + 1]
    sep.terminal, sep.direction = True, -1
    x0 = np.zeros(2 * n + 2)
    x0[n + 1] = v
    sol = solve_ivp(rhs, (0.0, 10 * T), x0, method="DOP853", rtol=1e-13, atol=1e-16,
                    events=sep, first_step=T * 1e-4)
    te, xe = sol.t_events[0][0], sol.y_events[0][0]
    return -xe[n + 1] / v, te


def convergence(bed, ns, mb, k, v):
    rows = []
    for n in ns:
        if n > len(bed.omega):
            break
        w, g, ph = bed.kept(n)
        f_res, u_res = bed.residual(n)
        r = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static)
        r["acor_no_residual"] = impact(w, g, ph, 0.0, 0.0, mb, k, v, bed.f_static)["acor"]
        rows.append(r)
    fin = rows[-1]
    for r in rows:
        r["d_acor"] = r["acor"] / fin["acor"] - 1
        r["d_time"] = r["contact_time"] / fin["contact_time"] - 1
    return rows


def print_case(title, bed, rows, check):
    table(title,
          ["modes", "top Hz", "ACOR", "rel diff", "contact ms", "rel diff", "peak N",
           "defl. mm", "E_bed/E_0", "ACOR w/o resid."],
          [[r["modes"], r["f_max_hz"], r["acor"], r["d_acor"], 1e3 * r["contact_time"], r["d_time"],
            r["peak_force"], 1e3 * r["max_deflection"], r["energy_fraction"],
            r["acor_no_residual"]] for r in rows],
          ["%d", "%.0f", "%.9f", "%+.1e", "%.7f", "%+.1e", "%.5f", "%.6f", "%.7f", "%.6f"])
    fin = rows[-1]
    print("    static: f_static = %.9e m/N (k_bed = %.2f N/m), u(x0)/F = %.9e m/N (%s); "
          "energy balance ACOR^2 + E_bed/E_0 - 1 = %.1e; participations: closed form against "
          "quadrature, largest difference %.1e of max |g|"
          % (bed.f_static, 1 / bed.f_static, bed.u_static, bed.static_source,
             fin["energy_balance"], check))


def args_parser():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    A = ap.add_argument
    A("--R", type=float, default=0.15, help="circle radius, m (0.15)")
    A("--N", type=float, default=16000.0, help="circle tension per length, N/m (16000)")
    A("--circle-sigma", type=float, default=0.2, help="circle areal mass, kg/m^2 (0.2)")
    A("--r0", type=float, default=0.06, help="circle off-centre impact radius, m (0.06)")
    A("--Lx", type=float, default=0.30, help="rectangle side along x, m (0.30)")
    A("--Lz", type=float, default=0.20, help="rectangle side along z, m (0.20)")
    A("--Nx", type=float, default=18000.0, help="rectangle tension N_x, N/m (18000)")
    A("--Nz", type=float, default=14000.0, help="rectangle tension N_z, N/m (14000)")
    A("--rect-sigma", type=float, default=0.2, help="rectangle areal mass, kg/m^2 (0.2)")
    A("--x0", type=float, default=0.05, help="rectangle off-centre impact x from the centre, m (0.05)")
    A("--z0", type=float, default=0.03, help="rectangle off-centre impact z from the centre, m (0.03)")
    A("--mb", type=float, default=0.057, help="ball mass, kg (0.057)")
    A("--k", type=float, default=3.0e4, help="contact spring, N/m (3e4)")
    A("--v", type=float, default=1.0, help="incoming speed, m/s (1)")
    A("--a", type=float, default=0.0165, help="load patch radius, m (0.0165)")
    A("--modes", default="25,50,100,200,400,800,1600",
      help="modes kept, the convergence rows of the 2-D cases (25,...,1600)")
    A("--modes-axisym", default="5,10,20,40,80,160,320",
      help="modes kept for the central circle (m = 0 only) (5,...,320)")
    A("--static-ka", type=float, default=400.0,
      help="rectangle: the static sums run over kappa a <= this (400)")
    A("--no-checks", action="store_true", help="skip the self-checks (3)")
    A("--json", action="store_true", help="print the results as one JSON object, no tables")
    return ap


def kappa_for(n, area):
    """A wavenumber bound holding at least n modes of a 2-D bed (Weyl: n ~ area kappa^2/(4 pi))."""
    return 1.3 * np.sqrt(4 * np.pi * n / area) + 200.0


def main():
    args = args_parser().parse_args()
    t_start = time.process_time()
    mb, k, v, a = args.mb, args.k, args.v, args.a
    ns = [int(s) for s in args.modes.split(",")]
    ns0 = [int(s) for s in args.modes_axisym.split(",")]
    out = {"parameters": vars(args).copy(), "cases": {}, "checks": {}}
    say = (lambda *x: None) if args.json else print
    say("bed_impact.py: a ball on a string bed (membrane) in a rigid frame, by analytic modes")
    say("  circle R = %g m, N = %g N/m, sigma = %g kg/m^2; off-centre r0 = %g m"
        % (args.R, args.N, args.circle_sigma, args.r0))
    say("  rectangle %g x %g m, N_x = %g, N_z = %g N/m, sigma = %g kg/m^2; off-centre (x0, z0) = "
        "(%g, %g) m from the centre" % (args.Lx, args.Lz, args.Nx, args.Nz, args.rect_sigma,
                                         args.x0, args.z0))
    say("  ball m_b = %g kg, k = %g N/m, v = %g m/s; paraboloid load on a disc of radius a = %g m"
        % (mb, k, v, a))
    say("  rigid wall: contact time pi sqrt(m_b/k) = %.6f ms" % (1e3 * np.pi * np.sqrt(mb / k)))

    Jmax = lambda n: kappa_for(n, np.pi * args.R ** 2 / 2) * args.R  # noqa: E731 (cos modes only)
    cases = [
        ("circle_centre", "(1a) circle, central hit (m = 0 modes)",
         lambda: Circle(args.R, args.N, args.circle_sigma, 0.0, a, np.pi * (max(ns0) + 2)), ns0),
        ("circle_offcentre", "(1b) circle, hit at r0 = %g m" % args.r0,
         lambda: Circle(args.R, args.N, args.circle_sigma, args.r0, a, Jmax(max(ns))), ns),
        ("rectangle_centre", "(2a) rectangle, central hit (odd i, j only)",
         lambda: Rectangle(args.Lx, args.Lz, args.Nx, args.Nz, args.rect_sigma, 0.0, 0.0, a,
                           args.static_ka, kappa_for(4 * max(ns), args.Lx * args.Lz)), ns),
        ("rectangle_offcentre", "(2b) rectangle, hit at (x0, z0) = (%g, %g) m" % (args.x0, args.z0),
         lambda: Rectangle(args.Lx, args.Lz, args.Nx, args.Nz, args.rect_sigma, args.x0, args.z0,
                           a, args.static_ka, kappa_for(max(ns), args.Lx * args.Lz)), ns),
    ]
    beds = {}
    for key, title, make, nl in cases:
        bed = make()
        beds[key] = bed
        rows = convergence(bed, nl, mb, k, v)
        check = participation_check(bed, rows[-1]["modes"])
        if isinstance(bed, Circle) and bed.r0 > 0:
            title += ", m <= %d at the finest" % bed.m[:rows[-1]["modes"]].max()
        if not args.json:
            print_case(title + ": modes kept against the results (rel diff: from the last row)",
                       bed, rows, check)
            if isinstance(bed, Rectangle):
                table("    its static sums against the cutoff",
                      ["kappa a <=", "f_static m/N", "u(x0)/F m/N"],
                      [[ka, f, u] for ka, f, u in bed.static_sums], ["%g", "%.12e", "%.12e"])
        out["cases"][key] = {"result": rows[-1], "convergence": rows, "f_static": bed.f_static,
                             "u_static": bed.u_static, "participation_check": check,
                             "static_source": bed.static_source}
        if isinstance(bed, Rectangle):
            out["cases"][key]["static_sums"] = bed.static_sums

    if not args.no_checks:
        out["checks"] = self_checks(args, beds, say)
    out["cpu_seconds"] = time.process_time() - t_start
    if args.json:
        print(json.dumps(out, default=float))
    else:
        print("\n(CPU %.1f s)" % out["cpu_seconds"])


def self_checks(args, beds, say):
    mb, k, v, a = args.mb, args.k, args.v, args.a
    checks = {}
    # (3a) the circle's static closed form against its modal sum
    rows = []
    for r0 in (0.0, args.r0):
        for J in (50.0, 100.0, 200.0):
            c = Circle(args.R, args.N, args.circle_sigma, r0, a, J if r0 > 0 else 40 * J)
            fsum, usum = np.sum(c.g ** 2 / c.omega ** 2), np.sum(c.g * c.phic / c.omega ** 2)
            rows.append([r0, c.kappa.max() * a, len(c.omega), fsum, fsum / c.f_static - 1,
                         usum / c.u_static - 1])
    checks["circle_static_sums"] = rows
    if not args.json:
        table("(3a) circle: the closed-form static flexibility f_static and deflection u(x0)/F "
              "against the modal sums up to kappa a", ["r0 m", "kappa a <=", "modes",
                                                       "sum g^2/w^2", "rel diff f", "rel diff u"],
              rows, ["%g", "%.0f", "%d", "%.10e", "%+.1e", "%+.1e"])

    rows = []
    for key in ("rectangle_centre", "rectangle_offcentre"):
        bed = beds[key]
        for ka in (50.0, 100.0, 200.0):
            f, u = rect_levy(bed.Lx, bed.Lz, bed.Nx, bed.Nz, bed.X0, bed.Z0, a, ka)
            rows.append([key, ka, f, f / bed.f_static - 1, u, u / bed.u_static - 1])
    checks["rectangle_levy"] = rows
    if not args.json:
        table("    rectangle: the modal sums (kappa a <= %g) against the single (Levy) sine series in x "
              "up to alpha a, each term's z-problem by its exact Green's function" % args.static_ka,
              ["case", "alpha a <=", "Levy f m/N", "rel diff", "Levy u(x0)/F", "rel diff"], rows,
              ["%s", "%g", "%.12e", "%+.1e", "%.12e", "%+.1e"])

    # (3b) the secular eigen-solution against LAPACK's eigh on the full matrix and an adaptive
    # ODE integration
    rows = []
    for key in ("circle_offcentre", "rectangle_offcentre"):
        bed = beds[key]
        w, g, ph = bed.kept(20)
        f_res, u_res = bed.residual(20)
        r = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static)
        e_ode, t_ode = impact_ode(w, g, f_res, mb, k, v, np.pi * np.sqrt(mb / k))
        rows.append([key, 20, "DOP853", r["acor"], e_ode - r["acor"], 1e3 * r["contact_time"],
                     t_ode / r["contact_time"] - 1])
        for n in (20, 200):
            w, g, ph = bed.kept(n)
            f_res, u_res = bed.residual(n)
            r = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static)
            re = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static, solver="eigh")
            rows.append([key, n, "eigh", r["acor"], re["acor"] - r["acor"],
                         1e3 * r["contact_time"], re["contact_time"] / r["contact_time"] - 1])
    checks["solvers"] = rows
    if not args.json:
        table("(3b) the secular eigen-solution against an adaptive integration (DOP853, rtol 1e-13) "
              "and against LAPACK's eigh of the full matrix",
              ["case", "modes", "other", "ACOR", "other - ACOR", "contact ms", "rel diff"],
              rows, ["%s", "%d", "%s", "%.12f", "%+.1e", "%.10f", "%+.1e"])

    # (3c) a stiff bed: tension times s -> the rigid wall
    T0 = np.pi * np.sqrt(mb / k)
    rows = []
    for key in ("circle_centre", "rectangle_offcentre"):
        for s in (1.0, 10.0, 100.0, 1e3, 1e4):
            if key == "circle_centre":
                bed = Circle(args.R, s * args.N, args.circle_sigma, 0.0, a, np.pi * 162)
                n = 160
            else:
                bed = Rectangle(args.Lx, args.Lz, s * args.Nx, s * args.Nz, args.rect_sigma,
                                args.x0, args.z0, a, 200.0, kappa_for(400, args.Lx * args.Lz))
                n = 400
            w, g, ph = bed.kept(n)
            f_res, u_res = bed.residual(n)
            r = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static)
            t_qs = np.pi * np.sqrt(mb * (1 / k + bed.f_static))
            rows.append([key, s, w[0] / (2 * np.pi), 1 - r["acor"], 1e3 * r["contact_time"],
                         r["contact_time"] / T0 - 1, r["contact_time"] / t_qs - 1])
    checks["stiff"] = rows
    if not args.json:
        table("(3c) stiff bed (tensions times s): ACOR -> 1 and the contact time -> pi sqrt(m_b/k) "
              "= %.6f ms; t_qs = pi sqrt(m_b (1/k + f_static)), the ball on the bed's static "
              "stiffness in series" % (1e3 * T0),
              ["case", "s", "f_1 Hz", "1 - ACOR", "contact ms", "t/T_rigid - 1", "t/t_qs - 1"],
              rows, ["%s", "%g", "%.0f", "%.2e", "%.6f", "%+.2e", "%+.2e"])

    # (3d) a small patch on a soft, light bed: the quasi-static series spring
    a_s, N_s = 0.002, args.N / 8
    rows = []
    for sig in (0.2, 2e-2, 2e-3, 2e-4, 2e-5, 2e-6, 2e-7, 2e-8, 2e-9, 2e-10):
        bed = Circle(args.R, N_s, sig, 0.0, a_s, np.pi * 42)
        w, g, ph = bed.kept(40)
        f_res, u_res = bed.residual(40)
        r = impact(w, g, ph, f_res, u_res, mb, k, v, bed.f_static)
        ks = 1 / (1 / k + bed.f_static)
        t_qs = np.pi * np.sqrt(mb / ks)
        F_qs = v * np.sqrt(mb * ks)
        rows.append([sig, w[0] / (2 * np.pi), 1 - r["acor"], 1e3 * r["contact_time"],
                     r["contact_time"] / t_qs - 1, r["peak_force"] / F_qs - 1,
                     r["max_deflection"] / (F_qs * bed.u_static) - 1])
    checks["quasi_static"] = {"a": a_s, "N": N_s, "k_bed": 1 / bed.f_static,
                              "t_qs": t_qs, "F_qs": F_qs, "u_qs": F_qs * bed.u_static, "rows": rows}
    if not args.json:
        table("(3d) small patch a = %g m on a soft bed (central circle, N = %g N/m, k_bed = "
              "1/f_static = %.1f N/m), areal mass sigma -> 0: the quasi-static limit, k in series "
              "with k_bed: t_qs = %.6f ms, F_qs = v sqrt(m_b k_s) = %.6f N, deflection F_qs u(0)/F = "
              "%.6f mm, ACOR 1" % (a_s, N_s, 1 / bed.f_static, 1e3 * t_qs, F_qs,
                                   1e3 * F_qs * bed.u_static),
              ["sigma", "f_1 Hz", "1 - ACOR", "contact ms", "t/t_qs - 1", "F/F_qs - 1",
               "defl/qs - 1"], rows, ["%g", "%.0f", "%.2e", "%.6f", "%+.2e", "%+.2e", "%+.2e"])
    return checks


if __name__ == "__main__":
    main()
