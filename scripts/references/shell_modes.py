#!/usr/bin/env python3
"""Free vibration of a thin circular cylindrical shell, one circumferential harmonic at a time:
an independent reference for the barrel-wall shell of issue 23 (MODEL.md section 9).

    /usr/bin/python3 scripts/references/shell_modes.py [--quick]

Method. Rayleigh-Ritz over the whole length (no grid along x): each of the axial, tangential
and radial amplitudes U(x), V(x), W(x) of

    u = U(x) cos n theta,   v = V(x) sin n theta,   w = W(x) cos n theta   (w outward)

is a Legendre series of degree N on [0, L]; the end conditions that hold displacements or the
slope (U, V, W, W') are imposed exactly as linear constraints on the coefficients (null space),
the force conditions of a free or partly free end come out of the energy (natural conditions).
Stiffness and mass are the exact integrals (Gauss-Legendre) of the Sanders-Koiter energy

    U_n = pi R / 2 int [ C (ex^2 + et^2 + 2 nu ex et + (1-nu)/2 g^2)
                         + D (kx^2 + kt^2 + 2 nu kx kt + 2 (1-nu) t^2) ] dx
    T_n = pi R rho h / 2 int (U_t^2 + V_t^2 + W_t^2) dx       (U_t = dU/dt)
    ex = U_x,  et = (n V + W)/R,  g = V_x - n U/R,
    kx = -W_xx,  kt = (n V + n^2 W)/R^2,  t = (n W_x + 3/4 V_x + n U/(4R))/R,
    C = E h/(1 - nu^2),  D = E h^3/(12 (1 - nu^2)),

(Sanders' twist; MODEL.md's tau is 2t; its coefficients 3/4 and 1/4 make every rigid motion
strain-free, which the script checks). With theory='donnell' the
curvatures drop the in-plane displacements (kt = n^2 W/R^2, t = n W_x/R). The frequencies
converge from above as N grows (a Ritz bound); the script prints that convergence.

End conditions (per end): free; clamped (U = V = W = W_x = 0); sd, the shear diaphragm or
'simply supported' end of Leissa (V = W = 0, N_x = M_x = 0), which is also what a stiff end cap
does to a harmonic n >= 2 (the cap keeps the end circular, lets it move axially and rotate);
hinged (U = V = W = 0, M_x = 0).

Checks printed: (0) the n = 1 rigid motions store no energy; (1) Ritz against the exact
shear-diaphragm solution of the same theory (sine modes, a 3x3 eigenproblem) and the Donnell
closed form (Soedel); (2) Rayleigh's ring formula, which the free-free shell's lowest mode of
each n (the nearly inextensional ovaling) approaches within 0.3 % at any length and the sd-sd
and clamped shells approach as L/R grows; (3) published
finite-cylinder values (ADINA's clamped cylinder, an ANSYS clamped-free and pinned cylinder);
(4) the n = 1 beam limit (Euler-Bernoulli free-free tube); (5) the hoop (n = 2) frequency of an
aluminium bat barrel with free ends, a stiff end cap and a clamped-like junction, against the
1-3 kHz measured by Russell. Sources and differences: scripts/references/README.md.
"""
import os
import sys

from _common import need, table, percent  # noqa: E402

need(__file__, "numpy", "scipy")
import argparse  # noqa: E402
from dataclasses import dataclass  # noqa: E402

import numpy as np  # noqa: E402
from numpy.polynomial import legendre as leg  # noqa: E402
from scipy.linalg import eigh, null_space  # noqa: E402

# Fields held at an end by each end condition: 'U', 'V', 'W' (values) and 'Wx' (slope).
END_HOLDS = {
    "free": (),
    "clamped": ("U", "V", "W", "Wx"),
    "sd": ("V", "W"),
    "cap": ("V", "W"),
    "hinged": ("U", "V", "W"),
}


@dataclass
class Shell:
    """A uniform thin cylindrical shell."""
    E: float    # Young's modulus (Pa)
    nu: float   # Poisson's ratio
    rho: float  # density (kg/m^3)
    R: float    # midsurface radius (m)
    h: float    # wall thickness (m)
    L: float    # length (m)

    @property
    def C(self):  # membrane stiffness (N/m)
        return self.E * self.h / (1.0 - self.nu ** 2)

    @property
    def D(self):  # bending stiffness (N m)
        return self.E * self.h ** 3 / (12.0 * (1.0 - self.nu ** 2))


def rayleigh_ring(s, n):
    """Rayleigh's inextensional ring frequency (Hz) of harmonic n (MODEL.md section 9)."""
    w2 = s.E * s.h ** 2 * n ** 2 * (n ** 2 - 1) ** 2 / (
        12.0 * s.rho * (1.0 - s.nu ** 2) * s.R ** 4 * (n ** 2 + 1))
    return np.sqrt(w2) / (2.0 * np.pi)


def _strain_rows(s, n, theory, U, Ux, V, Vx, W, Wx, Wxx):
    """Rows (over the Ritz coefficients) of the six strains at one point."""
    R = s.R
    ex = Ux
    et = (n * V + W) / R
    g = Vx - n * U / R
    kx = -Wxx
    if theory == "sanders":
        kt = (n * V + n * n * W) / R ** 2
        tw = (n * Wx + 0.75 * Vx + n * U / (4.0 * R)) / R
    elif theory == "donnell":
        kt = n * n * W / R ** 2
        tw = n * Wx / R
    else:
        raise ValueError("theory must be sanders or donnell, not %r" % theory)
    return ex, et, g, kx, kt, tw


def _energy_matrix(s, rows, weight):
    """Stiffness contribution w * (strain energy density) for strain rows at one point."""
    ex, et, g, kx, kt, tw = rows
    nu = s.nu
    memb = (np.outer(ex, ex) + np.outer(et, et) + nu * (np.outer(ex, et) + np.outer(et, ex))
            + 0.5 * (1.0 - nu) * np.outer(g, g))
    bend = (np.outer(kx, kx) + np.outer(kt, kt) + nu * (np.outer(kx, kt) + np.outer(kt, kx))
            + 2.0 * (1.0 - nu) * np.outer(tw, tw))
    return weight * (s.C * memb + s.D * bend)


def ritz_matrices(s, n, N, theory="sanders"):
    """Stiffness and mass (common factor pi R dropped) on the Legendre coefficients
    [a_U (N+1), a_V (N+1), a_W (N+1)], and the basis values at the ends."""
    nb = N + 1
    xi, wq = leg.leggauss(N + 8)
    jac = 2.0 / s.L  # d xi / dx
    eye = np.eye(nb)
    P = np.array([leg.legval(xi, eye[k]) for k in range(nb)]).T
    P1 = np.array([leg.legval(xi, leg.legder(eye[k], 1)) for k in range(nb)]).T * jac
    P2 = np.array([leg.legval(xi, leg.legder(eye[k], 2)) for k in range(nb)]).T * jac ** 2
    K = np.zeros((3 * nb, 3 * nb))
    M = np.zeros((3 * nb, 3 * nb))
    z = np.zeros(nb)
    for q in range(len(xi)):
        U = np.concatenate([P[q], z, z])
        Ux = np.concatenate([P1[q], z, z])
        V = np.concatenate([z, P[q], z])
        Vx = np.concatenate([z, P1[q], z])
        W = np.concatenate([z, z, P[q]])
        Wx = np.concatenate([z, z, P1[q]])
        Wxx = np.concatenate([z, z, P2[q]])
        w = wq[q] / jac
        K += _energy_matrix(s, _strain_rows(s, n, theory, U, Ux, V, Vx, W, Wx, Wxx), w)
        M += w * s.rho * s.h * (np.outer(U, U) + np.outer(V, V) + np.outer(W, W))
    ends = {}
    for side, x0 in (("left", -1.0), ("right", 1.0)):
        val = np.array([leg.legval(x0, eye[k]) for k in range(nb)])
        der = np.array([leg.legval(x0, leg.legder(eye[k], 1)) for k in range(nb)]) * jac
        ends[side] = {"U": np.concatenate([val, z, z]), "V": np.concatenate([z, val, z]),
                      "W": np.concatenate([z, z, val]), "Wx": np.concatenate([z, z, der])}
    return K, M, ends


def ritz_modes(s, n, left, right, N=24, theory="sanders"):
    """Frequencies (Hz, ascending, rigid modes removed), the radial share of each mode's
    kinetic energy, and the number of interior sign changes of W(x)."""
    K, M, ends = ritz_matrices(s, n, N, theory)
    rows = [ends["left"][f] for f in END_HOLDS[left]] + [ends["right"][f] for f in END_HOLDS[right]]
    Z = null_space(np.array(rows)) if rows else np.eye(K.shape[0])
    lam, Y = eigh(Z.T @ K @ Z, Z.T @ M @ Z)
    X = Z @ Y
    nb = N + 1
    xs = np.linspace(-1.0, 1.0, 401)
    Pw = leg.legvander(xs, N)
    freqs, radial, nodes = [], [], []
    scale = s.E / (s.rho * s.R ** 2)  # (membrane ring frequency)^2: rigid modes are ~0 next to it
    for k in range(len(lam)):
        if lam[k] < 1e-9 * scale:
            continue
        a = X[:, k]
        ke = [a[i * nb:(i + 1) * nb] @ M[i * nb:(i + 1) * nb, i * nb:(i + 1) * nb]
              @ a[i * nb:(i + 1) * nb] for i in range(3)]
        wx = Pw @ a[2 * nb:]
        big = np.abs(wx) > 1e-6 * np.max(np.abs(wx))
        sg = np.sign(wx[big])
        freqs.append(np.sqrt(lam[k]) / (2.0 * np.pi))
        radial.append(ke[2] / sum(ke))
        nodes.append(int(np.sum(sg[1:] != sg[:-1])))
    return np.array(freqs), np.array(radial), np.array(nodes)


def flexural(s, n, left, right, count=4, N=24, theory="sanders"):
    """The lowest `count` radial-dominant (bending-branch) frequencies (Hz) and their W nodes."""
    f, r, nd = ritz_modes(s, n, left, right, N, theory)
    keep = r > 0.5
    return f[keep][:count], nd[keep][:count]


def hoop_lumped(s, n, left, right, N=24, x_c=None, theory="sanders"):
    """The lowest flexural mode of harmonic n as a lumped mass-spring seen by a radial point
    force at (x_c, theta = 0): frequency (Hz), modal mass m_eff = 2T/(W(x_c)^2 omega^2)
    (kg; pi R from the theta integral), k_eff = m_eff omega^2 (N/m) and x_c (the radial
    antinode if not given)."""
    K, M, ends = ritz_matrices(s, n, N, theory)
    rows = [ends["left"][f] for f in END_HOLDS[left]] + [ends["right"][f] for f in END_HOLDS[right]]
    Z = null_space(np.array(rows)) if rows else np.eye(K.shape[0])
    lam, Y = eigh(Z.T @ K @ Z, Z.T @ M @ Z)
    nb = N + 1
    f_all, radial, _ = ritz_modes(s, n, left, right, N, theory)
    f0 = f_all[radial > 0.5][0]
    k = int(np.argmin(np.abs(np.sqrt(np.abs(lam)) / (2.0 * np.pi) - f0)))
    a = Z @ Y[:, k]
    xs = np.linspace(0.0, s.L, 2001)
    Wx = leg.legvander(2.0 * xs / s.L - 1.0, N) @ a[2 * nb:]
    if x_c is None:
        x_c = xs[int(np.argmax(np.abs(Wx)))]
    Wc = leg.legvander(np.array([2.0 * x_c / s.L - 1.0]), N)[0] @ a[2 * nb:]
    m_eff = np.pi * s.R * (a @ M @ a) / Wc ** 2
    w = 2.0 * np.pi * f0
    return f0, m_eff, m_eff * w * w, x_c


def exact_sd(s, n, m, theory="sanders"):
    """Exact frequencies (Hz, the three branches) of the sd-sd shell, m axial half-waves:
    U = A cos(k x), V = B sin(k x), W = C sin(k x), k = m pi / L, in the same energy."""
    k = m * np.pi / s.L
    R = s.R
    # strain amplitudes as rows over (A, B, C); the sin/cos averages are equal (L/2) and cancel
    ex = np.array([-k, 0.0, 0.0])
    et = np.array([0.0, n / R, 1.0 / R])
    g = np.array([-n / R, k, 0.0])
    kx = np.array([0.0, 0.0, k * k])
    if theory == "sanders":
        kt = np.array([0.0, n / R ** 2, n * n / R ** 2])
        tw = np.array([n / (4.0 * R * R), 0.75 * k / R, n * k / R])
    else:
        kt = np.array([0.0, 0.0, n * n / R ** 2])
        tw = np.array([0.0, 0.0, n * k / R])
    K = _energy_matrix(s, (ex, et, g, kx, kt, tw), 1.0)
    lam = eigh(K, s.rho * s.h * np.eye(3), eigvals_only=True)
    return np.sqrt(lam) / (2.0 * np.pi)


def donnell_closed_form(s, n, m):
    """Soedel's Donnell-Mushtari frequency of the sd-sd shell (in-plane inertia neglected)."""
    lam = m * np.pi * s.R / s.L
    w2 = s.E / (s.rho * (1.0 - s.nu ** 2) * s.R ** 2) * (
        (1.0 - s.nu ** 2) * lam ** 4 / (lam ** 2 + n ** 2) ** 2
        + s.h ** 2 / (12.0 * s.R ** 2) * (lam ** 2 + n ** 2) ** 2)
    return np.sqrt(w2) / (2.0 * np.pi)


def midsurface(outer_diameter, wall):
    """Midsurface radius of a tube of outer diameter D and wall h: R = (D + d)/4, d = D - 2h."""
    return (2.0 * outer_diameter - 2.0 * wall) / 4.0


def ring_extensible(s, n):
    """The ring of the same theory with U = 0 and no x-dependence (a 2x2 problem): Rayleigh's
    formula without the inextensional assumption (lower by O(h^2/R^2))."""
    R = s.R
    et = np.array([n / R, 1.0 / R])
    kt = np.array([n / R ** 2, n * n / R ** 2])
    K = s.C * np.outer(et, et) + s.D * np.outer(kt, kt)
    lam = eigh(K, s.rho * s.h * np.eye(2), eigvals_only=True)
    return np.sqrt(lam[0]) / (2.0 * np.pi)


# --- published finite-cylinder values (README.md: where each comes from) -------------------

# ADINA R&D, "clamped cylinder" news item (adina.com/newsgH53.shtml), as quoted by P. Krysl's
# FinEtoolsFlexStructures example clamp_cyl_vibration_examples.jl: steel, R = 0.1 m,
# L = 0.4 m, h = 0.01 m, both ends clamped; fundamental (n = 2, m = 1) 1701 Hz (shell FE).
ADINA = dict(shell=Shell(200e9, 0.3, 7800.0, 0.1, 0.01, 0.4), ends=("clamped", "clamped"),
             values=[(2, 1701.0)])

# ANSYS frequencies listed in the header of F. Pinho's ShellPy example
# examples/linear_normal_modes/linear_normal_modes_cylindrical_shell.py: steel, R = 0.15 m,
# L = 0.5 m, h = 1 mm; (a) clamped-free, (b) 'pinned' both ends (u = v = w = 0, slope free).
# Each value is a pair of degenerate modes (cos / sin); the harmonic n is not given there and
# is identified here as the Ritz mode of the nearest frequency.
ANSYS_CF = dict(shell=Shell(2e11, 0.3, 7850.0, 0.15, 1e-3, 0.5), ends=("clamped", "free"),
                values=[188.86, 189.27, 267.89, 334.21, 384.93])
ANSYS_PP = dict(shell=Shell(2e11, 0.3, 7850.0, 0.15, 1e-3, 0.5), ends=("hinged", "hinged"),
                values=[445.26, 470.79, 531.61, 574.32, 727.87])

# The illustrative aluminium bat barrel of issue 23: outer diameter 2.625 in, wall 2-3 mm.
BAT_E, BAT_NU, BAT_RHO, BAT_D, BAT_L = 70e9, 0.33, 2700.0, 0.0667, 0.30


def bat_barrel(wall, length=BAT_L):
    return Shell(BAT_E, BAT_NU, BAT_RHO, midsurface(BAT_D, wall), wall, length)


def lowest_modes(s, ends, nmax, count, N):
    """The `count` lowest flexural frequencies over n = 2..nmax: (f, n, W nodes)."""
    out = []
    for n in range(2, nmax + 1):
        f, nd = flexural(s, n, *ends, count=2, N=N)
        out += [(fk, n, int(k)) for fk, k in zip(f, nd)]
    return sorted(out)[:count]


def report_rigid_body(N):
    """The n = 1 rigid motions (translation W = c, V = -c; rotation W = c x, V = -c x, U = -R c)
    must store no energy: Sanders' twist coefficients 3/4 and 1/4 are what makes this exact."""
    s = bat_barrel(0.0025)
    rows = []
    for theory in ("sanders", "donnell"):
        K, M, _ = ritz_matrices(s, 1, N, theory)
        nb = N + 1
        for name, (u, v, w) in (("translation", ([0.0], [-1.0], [1.0])),
                                ("rotation", ([-s.R], [-s.L / 2, -s.L / 2], [s.L / 2, s.L / 2]))):
            a = np.zeros(3 * nb)  # x = L (xi + 1)/2: c x = c L/2 (P0 + P1)
            for k, c in enumerate(u):
                a[k] = c
            for k, c in enumerate(v):
                a[nb + k] = c
            for k, c in enumerate(w):
                a[2 * nb + k] = c
            rows.append([theory, name, (a @ K @ a) / (a @ M @ a) / (2 * np.pi) ** 2])
    table("Rigid motions of the n = 1 harmonic: Rayleigh quotient as a frequency^2 (Hz^2); zero "
          "means strain-free", ["theory", "motion", "omega^2/(2 pi)^2"], rows, ["%s", "%s", "%.3e"])


def report_convergence(N_list):
    s = bat_barrel(0.0025)
    rows = []
    for ends in (("free", "free"), ("clamped", "free"), ("clamped", "clamped")):
        for N in N_list:
            f, _ = flexural(s, 2, *ends, count=3, N=N)
            rows.append(["%s-%s" % ends, N] + list(f))
    table("Ritz convergence in the Legendre degree N (bat barrel, h = 2.5 mm, n = 2), Hz",
          ["ends", "N", "1st", "2nd", "3rd"], rows, ["%s", "%d", "%.3f", "%.3f", "%.3f"])


def report_exact_sd(N):
    s = bat_barrel(0.0025)
    rows = []
    for theory in ("sanders", "donnell"):
        for n in (2, 3, 4):
            f, _ = flexural(s, n, "sd", "sd", count=3, N=N, theory=theory)
            for m in (1, 2, 3):
                ex = exact_sd(s, n, m, theory)[0]
                soedel = donnell_closed_form(s, n, m) if theory == "donnell" else float("nan")
                rows.append([theory, n, m, f[m - 1], ex, percent(f[m - 1], ex), soedel])
    table("Shear-diaphragm ends: Ritz against the exact sine solution of the same energy "
          "(bat barrel, h = 2.5 mm), Hz",
          ["theory", "n", "m", "Ritz", "exact", "diff %", "Soedel (no in-plane inertia)"], rows,
          ["%s", "%d", "%d", "%.2f", "%.2f", "%+.1e", "%.1f"])


def report_ring_limit(N):
    s0 = bat_barrel(0.0025)
    rows = []
    for n in (2, 3, 4):
        rows.append([n, rayleigh_ring(s0, n), ring_extensible(s0, n),
                     percent(ring_extensible(s0, n), rayleigh_ring(s0, n))])
    table("Rayleigh's ring (inextensional) and the extensible ring of the same theory, "
          "R = %.2f mm, h = 2.5 mm, Hz" % (1e3 * s0.R),
          ["n", "Rayleigh", "extensible ring", "diff %"], rows, ["%d", "%.2f", "%.2f", "%+.3f"])
    rows = []
    for LR in (1, 2, 5, 10, 20, 50, 100):
        s = Shell(s0.E, s0.nu, s0.rho, s0.R, s0.h, LR * s0.R)
        row = [LR]
        for n in (2, 3):
            fr = rayleigh_ring(s, n)
            for ends in (("free", "free"), ("sd", "sd"), ("clamped", "clamped")):
                row.append(flexural(s, n, *ends, count=1, N=N)[0][0] / fr)
        rows.append(row)
    table("Long-cylinder limit: lowest flexural frequency / Rayleigh's ring frequency",
          ["L/R", "n=2 FF", "n=2 SS", "n=2 CC", "n=3 FF", "n=3 SS", "n=3 CC"], rows,
          ["%d"] + ["%.4f"] * 6)


def report_beam_limit(N):
    rows = []
    for LR in (20, 40, 80, 160):
        s = Shell(70e9, 0.33, 2700.0, 0.0321, 0.0025, LR * 0.0321)
        f, radial, _ = ritz_modes(s, 1, "free", "free", N)
        f1 = f[radial > 0.3][0]  # beam bending: W and V share the kinetic energy
        # thin-walled tube: EI/mu = E (pi R^3 h) / (rho 2 pi R h) = E R^2 / (2 rho)
        eb = 4.730041 ** 2 / (2.0 * np.pi * s.L ** 2) * np.sqrt(s.E * s.R ** 2 / (2.0 * s.rho))
        rows.append([LR, f1, eb, percent(f1, eb), percent(f1, eb) * LR ** 2 / 1e4])
    table("n = 1 is the beam: free-free tube against Euler-Bernoulli (4.73004^2 sqrt(EI/mu)/L^2), Hz",
          ["L/R", "shell n=1", "Euler-Bernoulli", "diff %", "diff % x (L/R)^2/1e4"], rows,
          ["%d", "%.3f", "%.3f", "%+.3f", "%+.3f"])


def report_published(N):
    rows = []
    s = ADINA["shell"]
    for n, fpub in ADINA["values"]:
        f, nd = flexural(s, n, *ADINA["ends"], count=1, N=N)
        rows.append(["ADINA clamped-clamped", "n=%d m=1" % n, fpub, f[0], percent(f[0], fpub)])
    for case, name in ((ANSYS_CF, "ANSYS clamped-free"), (ANSYS_PP, "ANSYS pinned-pinned")):
        # the published list is the lowest modes in order: compare rank by rank
        modes = lowest_modes(case["shell"], case["ends"], 12, len(case["values"]), N)
        for fpub, (fk, n, nodes) in zip(case["values"], modes):
            rows.append([name, "n=%d nodes=%d" % (n, nodes), fpub, fk, percent(fk, fpub)])
    table("Published finite cylinders (Sanders-Koiter Ritz here against the published FE), Hz",
          ["case", "mode", "published", "this script", "diff %"], rows,
          ["%s", "%s", "%.2f", "%.2f", "%+.2f"])


def report_all_ends(N):
    s = bat_barrel(0.0025)
    rows = []
    for ends in (("free", "free"), ("clamped", "free"), ("clamped", "clamped"), ("sd", "sd"),
                 ("cap", "free"), ("cap", "clamped")):
        for n in (2, 3, 4):
            f, nd = flexural(s, n, *ends, count=3, N=N)
            rows.append(["%s-%s" % ends, n] + ["%.1f (%d)" % (fk, k) for fk, k in zip(f, nd)])
    table("Bat barrel (D = 66.7 mm, h = 2.5 mm, L = 0.30 m, aluminium): the three lowest "
          "flexural frequencies per n, Hz (W nodes)",
          ["ends", "n", "1st", "2nd", "3rd"], rows, ["%s", "%d", "%s", "%s", "%s"])


def report_hoop(N):
    rows = []
    for wall in (0.0020, 0.0025, 0.0030):
        s = bat_barrel(wall)
        row = [1e3 * wall, 1e3 * s.R, rayleigh_ring(s, 2)]
        for ends in (("free", "free"), ("cap", "free"), ("cap", "cap"), ("cap", "clamped"),
                     ("clamped", "clamped")):
            row.append(flexural(s, 2, *ends, count=1, N=N)[0][0])
        row.append(flexural(s, 2, "cap", "clamped", count=1, N=N, theory="donnell")[0][0])
        rows.append(row)
    table("Hoop (n = 2) frequency of the aluminium bat barrel, L = 0.30 m, Hz "
          "(Russell: 1000-2500 Hz softball bats; an aluminium bat's ping at 2200 Hz)",
          ["h mm", "R mm", "Rayleigh", "free-free", "cap-free", "cap-cap", "cap-clamped",
           "clamped-clamped", "Donnell cap-clamped"], rows,
          ["%.1f", "%.2f"] + ["%.0f"] * 7)
    rows = []
    for L in (0.10, 0.15, 0.20, 0.30, 0.40):
        s = bat_barrel(0.0025, L)
        rows.append([L] + [flexural(s, 2, *e, count=1, N=N)[0][0]
                           for e in (("free", "free"), ("cap", "free"), ("cap", "cap"),
                                     ("cap", "clamped"), ("clamped", "clamped"))])
    table("Hoop frequency against the barrel length (h = 2.5 mm), Hz",
          ["L m", "free-free", "cap-free", "cap-cap", "cap-clamped", "clamped-clamped"], rows,
          ["%.2f"] + ["%.0f"] * 5)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--N", type=int, default=24, help="Legendre degree of each field (default 24)")
    ap.add_argument("--quick", action="store_true", help="fewer convergence rows")
    args = ap.parse_args()
    print("shell_modes.py: thin cylindrical shell modes per harmonic n, Sanders-Koiter, "
          "Rayleigh-Ritz with Legendre series of degree N = %d" % args.N)
    report_rigid_body(args.N)
    report_convergence((8, 12, 16, 24) if args.quick else (8, 12, 16, 20, 24, 32))
    report_exact_sd(args.N)
    report_ring_limit(args.N)
    report_beam_limit(args.N)
    report_published(args.N)
    report_all_ends(args.N)
    report_hoop(args.N)


if __name__ == "__main__":
    main()
