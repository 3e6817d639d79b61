#!/usr/bin/env python3
"""Every figure of the paper's scenes, from the HDF5 files of scripts/run_paper.sh.

    scripts/paper_figures.py out/paper            # reads out/paper/*.h5, writes out/paper/*.png

Figures (PNG, in the same directory) and what they need:
  modes.png              mode periods of the 6 mm and 10 mm beams against (beta L)^2 sqrt(EI/mu L^4)
                         (modes-*.h5)
  waves.png              impact force, velocity of both ends, and the group-velocity check:
                         band-passed arrival times along the beam against v_g = 2 (EI w^2/mu)^(1/4)
                         (waves.h5, waves-n41.h5)
  acor.png               ACOR against impact point, 6 mm beams 0.3 / 0.6 / 1.1 m free and clamped,
                         hysteretic ball, the 10 mm beam, rigid-body curves, measured plateau band
                         (acor-*.h5)
  snapshots.png          y(x) at 1, 3, 5 ms for impacts at 55, 90, 103 cm (snapshots-*.h5)
  energy.png             energy partition against time, impacts at 55 and 90 cm (energy-*.h5)
  racket_acor.png        racket ACOR and contact time, handle free / pinned / clamped (racket-acor-*.h5)
  racket_snapshots.png   racket y(x) every 2 ms, pinned and clamped (racket-snapshots-*.h5)
  racket_energy.png      energy fractions and the handle's peak kinetic energy against impact
                         point (racket-energy/x*.h5, racket-acor-free.h5)
It also writes summary.txt: the numbers docs/paper-comparison.md quotes. A figure whose
files are missing is skipped with a message (exit status 1 at the end).
Needs numpy, h5py and matplotlib; re-executes itself with /usr/bin/python3 when the first
python lacks them.
"""
import argparse
import glob
import os
import sys

from beamimpact import files, style

import numpy as np

plt = style.plt

# docs/model.md section 1: beta L of the first flexural modes.
BETA_L = {
    "clamped-free": [1.87510, 4.69409, 7.85476, 10.99554],
    "free-free": [4.73004, 7.85320, 10.99561, 14.13717],
    "pinned-free": [3.92660, 7.06858, 10.21018],
}
MEASURED_PLATEAU = (0.45, 0.02)  # docs/model.md section 11: measured ACOR over the central section, 6 mm beams
END_ZONE = 0.15  # m: docs/model.md section 11, the ACOR is independent of the point more than ~15 cm from an end

SUMMARY = []
MISSING = []


def say(line=""):
    SUMMARY.append(line)
    print(line)


class Run:
    """One HDF5 file: attributes, /results columns, optional /series, /snapshots, /modes."""

    def __init__(self, path):
        self.path = path
        with files.open_file("paper_figures.py", path) as f:
            self.attrs = files.attrs(f)
            self.results = {k: f["results"][k][()] for k in f["results"]} if "results" in f else {}
            self.series = {k: f["series"][k][()] for k in f["series"]} if "series" in f else {}
            self.snapshots = {k: f["snapshots"][k][()] for k in f["snapshots"]} if "snapshots" in f else {}
            self.modes = {k: f["modes"][k][()] for k in f["modes"]} if "modes" in f else {}
        if self.results and "x" in self.results:
            order = np.argsort(self.results["x"], kind="stable")
            self.results = {k: v[order] for k, v in self.results.items()}

    def __getitem__(self, name):
        return self.results[name]

    def option(self, name):
        """The value of -name in the run's full option string (e.g. monitor points)."""
        words = str(self.attrs.get("options", "")).split()
        for i, w in enumerate(words):
            if w == "-" + name and i + 1 < len(words):
                return words[i + 1]
        return None


def load(d, name):
    path = os.path.join(d, name)
    if not os.path.exists(path):
        MISSING.append(path)
        return None
    return Run(path)


def need(*runs):
    return all(r is not None for r in runs)


def save(fig, d, name):
    path = style.save(fig, os.path.join(d, name), dpi=130, layout=False, tight_box=True)
    print("wrote", path)


def central(run, zone=END_ZONE):
    x, L = run["x"], run.attrs["beam_length"]
    return (x >= zone - 1e-9) & (x <= L - zone + 1e-9)


def fundamental_period_free(run):
    """Continuum free-free fundamental period (s) of the run's beam."""
    EI, mu, L = run.attrs["beam_EI"], run.attrs["beam_mu"], run.attrs["beam_length"]
    return 2 * np.pi / (BETA_L["free-free"][0] ** 2 * np.sqrt(EI / (mu * L**4)))


# ----------------------------------------------------------------------------------------
# modes
# ----------------------------------------------------------------------------------------
def fig_modes(d):
    rows = []
    for path in sorted(glob.glob(os.path.join(d, "modes-*.h5"))):
        r = Run(path)
        EI, mu, L = r.attrs["beam_EI"], r.attrs["beam_mu"], r.attrs["beam_length"]
        sup = "%s-%s" % (r.attrs["beam_left"], r.attrs["beam_right"])
        T = [p for p in r.modes["period"] if p > 0][:4]
        Ta = [2 * np.pi / (b**2 * np.sqrt(EI / (mu * L**4))) for b in BETA_L[sup]][: len(T)]
        rows.append((r.attrs["beam_thickness"] * 1e3, L, sup, int(r.attrs["beam_nodes"]), T, Ta))
    if not rows:
        MISSING.append(os.path.join(d, "modes-*.h5"))
        return
    rows.sort(key=lambda t: (t[0], t[2], t[1]))
    say("== modes: periods (ms) of the first four flexural modes, N = %d, against (beta L)^2 sqrt(EI/(mu L^4))" % rows[0][3])
    cells, worst = [], 0.0
    for a, L, sup, N, T, Ta in rows:
        err = [(t - ta) / ta for t, ta in zip(T, Ta)]
        worst = max(worst, max(abs(e) for e in err))
        cells.append(["%g mm" % a, "%g m" % L, sup] + ["%#.4g\n(%#.4g, %+.2f%%)" % (t * 1e3, ta * 1e3, 100 * e) for t, ta, e in zip(T, Ta, err)])
        say("  a = %2g mm  L = %.1f m  %-12s " % (a, L, sup) + "  ".join("%9.4f (%9.4f, %+.2f%%)" % (t * 1e3, ta * 1e3, 100 * e) for t, ta, e in zip(T, Ta, err)))
    say("  largest |relative error|: %.2f%% (mode 4); mode 1 within %.2f%%" % (100 * worst, 100 * max(abs(T[0] - Ta[0]) / Ta[0] for _, _, _, _, T, Ta in rows)))
    fig, ax = plt.subplots(figsize=(10.5, 0.62 * len(cells) + 1.4))
    ax.axis("off")
    tab = ax.table(cellText=cells, colLabels=["thickness", "length", "supports", "mode 1", "mode 2", "mode 3", "mode 4"], loc="center", cellLoc="center")
    tab.auto_set_font_size(False)
    tab.set_fontsize(8.5)
    tab.scale(1, 2.6)
    ax.set_title(
        "Mode periods (ms) of the aluminium beams (b = 32 mm), discrete model N = %d\n"
        "in brackets: continuum ($\\beta$L)$^2$ (EI/$\\mu$L$^4$)$^{1/2}$ and the relative difference of the discrete one" % rows[0][3],
        fontsize=10,
    )
    save(fig, d, "modes.png")


# ----------------------------------------------------------------------------------------
# waves and the group-velocity check
# ----------------------------------------------------------------------------------------
def band_envelope(t, s, fc, rel):
    """Envelope of s (uniformly sampled at t) through a Gaussian band filter at fc (Hz),
    standard deviation rel*fc, and the band's power-weighted mean frequency."""
    dt = t[1] - t[0]
    n = len(s)
    s = s - (s[0] + (s[-1] - s[0]) * np.arange(n) / (n - 1))  # no jump at the ends of the record
    S = np.fft.fft(s, 4 * n)
    fr = np.fft.fftfreq(4 * n, dt)
    H = 2 * np.exp(-0.5 * ((fr - fc) / (rel * fc)) ** 2) * (fr > 0)
    P = np.abs(S * H) ** 2
    return np.abs(np.fft.ifft(S * H))[:n], (fr * P).sum() / P.sum()


def first_peak(e, frac=0.5):
    """Index of the first local maximum of e that reaches frac of its largest value."""
    thr = frac * e.max()
    for i in range(1, len(e) - 1):
        if e[i] >= thr and e[i] >= e[i - 1] and e[i] >= e[i + 1]:
            return i
    return int(np.argmax(e))


def theil_sen(x, y):
    s = [(y[j] - y[i]) / (x[j] - x[i]) for i in range(len(x)) for j in range(i + 1, len(x)) if x[j] != x[i]]
    return float(np.median(s))


def vg_continuum(EI, mu, f):
    return 2 * (EI * (2 * np.pi * f) ** 2 / mu) ** 0.25


def vg_discrete(EI, mu, h, f):
    """Group velocity of the semi-discrete beam (5-point stencil, lumped mass):
    omega = c (4/h^2) sin^2(k h/2), c = sqrt(EI/mu), so d omega/dk = c (2/h) sin(k h)."""
    c = np.sqrt(EI / mu)
    q = np.asarray(2 * np.pi * f) * h * h / (4 * c)
    return np.where(q < 1, c * 2 / h * np.sin(2 * np.arcsin(np.sqrt(np.minimum(q, 1)))), np.nan)


BANDS = [400, 500, 600, 800, 1000, 1250, 1500]  # Hz


def group_velocity(run, rel=0.2):
    """v_g per band from the arrival times along the beam: for each band, the first peak of the
    band envelope of the velocity at every monitored interior point to the right of the impact;
    v_g is the (Theil-Sen) slope of distance against arrival time, so neither the source time
    nor the reflection from the near end (a constant extra path) enters. The band's frequency
    is its power-weighted mean (the force spectrum falls steeply, which pulls it below the centre)."""
    pts = np.array([float(p) for p in run.option("monitor_velocity_at").split(",")])
    t, v = run.series["time"], run.series["velocity_at"]
    L, ximp = run.attrs["beam_length"], run["x"][0]
    use = [i for i, p in enumerate(pts) if ximp < p < L]
    tu = np.arange(0, 0.03, 1e-5)
    out = []
    for fc in BANDS:
        arr, fe = [], []
        for i in use:
            e, ff = band_envelope(tu, np.interp(tu, t, v[i]), fc, rel)
            arr.append(tu[first_peak(e)])
            fe.append(ff)
        out.append((fc, float(np.median(fe)), theil_sen(np.array(arr), pts[use]), pts[use], np.array(arr)))
    return out


def fig_waves(d):
    fine, coarse = load(d, "waves.h5"), load(d, "waves-n41.h5")
    if not need(fine):
        return
    s = fine.series
    t = s["time"]
    pts = [float(p) for p in fine.option("monitor_velocity_at").split(",")]
    L, ximp = fine.attrs["beam_length"], fine["x"][0]
    EI, mu = fine.attrs["beam_EI"], fine.attrs["beam_mu"]
    i0, iL = pts.index(0.0), pts.index(L)
    fig, ax = plt.subplots(4, 1, figsize=(9, 14), gridspec_kw={"height_ratios": [1, 1.5, 1.5, 1.6]})
    ax[0].plot(t * 1e3, s["force"], color="k")
    ax[0].set_xlim(0, 8)
    ax[0].set_xlabel("time (ms)")
    ax[0].set_ylabel("impact force (N)")
    ax[0].set_title(
        "%.1f m free-free beam (a = %g mm) struck %g cm from the x = 0 end, 42 g ball at 1 m/s, N = %d"
        % (L, fine.attrs["beam_thickness"] * 1e3, ximp * 100, fine.attrs["beam_nodes"]),
        fontsize=10,
    )
    v = s["velocity_at"]
    ax[1].plot(t * 1e3, v[i0] * 1e3, label="near end, x = 0", color="tab:blue")
    ax[1].plot(t * 1e3, v[iL] * 1e3, label="far end, x = %.1f m" % L, color="tab:red")
    ax[1].axvspan(0, 20, color="0.93", zorder=0, label="enlarged below")
    ax[1].set_xlim(0, 60)
    ax[1].set_xlabel("time (ms)")
    ax[1].set_ylabel("beam velocity (mm/s)")
    ax[1].legend(loc="lower left", fontsize=8)
    ax[1].set_title("velocity of the two ends (rigid-body motion included)", fontsize=9)
    dist = L - ximp
    far = t <= 0.02
    ax[2].plot(t[far] * 1e3, v[iL][far] * 1e3, color="tab:red", label="far end, x = %.1f m, grid N = %d" % (L, fine.attrs["beam_nodes"]))
    if coarse is not None:
        pc = [float(p) for p in coarse.option("monitor_velocity_at").split(",")]
        tc = coarse.series["time"]
        fc_ = tc <= 0.02
        ax[2].plot(tc[fc_] * 1e3, coarse.series["velocity_at"][pc.index(L)][fc_] * 1e3, color="tab:blue", lw=0.9, alpha=0.8, label="far end, grid N = %d" % coarse.attrs["beam_nodes"])
    ax[2].set_xlim(0, 20)
    ylo, yhi = ax[2].get_ylim()
    for f in (2000, 1000, 500, 250, 125, 62.5):
        ta = dist / vg_continuum(EI, mu, f) * 1e3
        ax[2].axvline(ta, color="0.5", lw=0.7, ls=":")
        ax[2].text(ta, ylo + 0.02 * (yhi - ylo), " %g Hz" % f, rotation=90, va="bottom", ha="left", fontsize=7, color="0.3")
    ax[2].set_xlabel("time (ms)")
    ax[2].set_ylabel("far-end velocity (mm/s)")
    ax[2].legend(loc="upper left", fontsize=8)
    ax[2].set_title("the dispersed pulse at the far end; dotted: %.1f m / v$_g$(f) after the contact starts" % dist, fontsize=9)
    say("== waves: %.1f m beam, impact at %g m: contact %.2f ms, peak force %.1f N, ACOR %.3f (x 0.85: %.3f)"
        % (L, ximp, fine["contact_time"][0] * 1e3, fine["peak_force"][0], fine["acor"][0], fine["acor_corrected"][0]))
    f_plot = np.linspace(200, 2000, 200)
    ax[3].plot(f_plot, vg_continuum(EI, mu, f_plot), "k-", label="continuum  v$_g$ = 2 (EI $\\omega^2$/$\\mu$)$^{1/4}$")
    for run, colour, marker in ((fine, "tab:red", "o"), (coarse, "tab:blue", "s")):
        if run is None:
            continue
        N = int(run.attrs["beam_nodes"])
        h = run.attrs["beam_length"] / (N - 1)
        gv = group_velocity(run)
        ax[3].plot(f_plot, vg_discrete(EI, mu, h, f_plot), color=colour, ls="--", lw=1, label="grid N = %d (h = %.1f cm): (2/h) (EI/$\\mu$)$^{1/2}$ sin(kh)" % (N, h * 100))
        fe = np.array([g[1] for g in gv])
        vm = np.array([g[2] for g in gv])
        ax[3].plot(fe, vm, marker, color=colour, ms=6, label="measured, N = %d" % N)
        say("  group velocity, N = %d (h = %.1f cm): band centre -> mean frequency: measured v_g / continuum / grid (m/s)" % (N, h * 100))
        for (fc, f, vmeas, _, _) in gv:
            vc, vd = vg_continuum(EI, mu, f), float(vg_discrete(EI, mu, h, f))
            say("    %5d Hz -> %6.0f Hz: %6.0f  %6.0f  %6.0f   measured/continuum %.3f  measured/grid %.3f" % (fc, f, vmeas, vc, vd, vmeas / vc, vmeas / vd))
    ax[3].set_xlabel("frequency (Hz)")
    ax[3].set_ylabel("group velocity (m/s)")
    ax[3].set_xlim(200, 2000)
    ax[3].set_ylim(0, None)
    ax[3].legend(fontsize=8, loc="lower right")
    ax[3].set_title("group velocity: slope of distance against band arrival time, x = 0.3-0.9 m", fontsize=9)
    fig.tight_layout()
    save(fig, d, "waves.png")


# ----------------------------------------------------------------------------------------
# ACOR of the aluminium beams
# ----------------------------------------------------------------------------------------
def fig_acor(d):
    names = {
        (L, s): "acor-6mm-%s-%s.h5" % (L, s) for L in ("0.3", "0.6", "1.1") for s in ("free", "clamped")
    }
    runs = {k: load(d, v) for k, v in names.items()}
    hyst = load(d, "acor-6mm-1.1-clamped-hysteresis.h5")
    thick = load(d, "acor-10mm-1.1-free.h5")
    if not any(r is not None for r in runs.values()):
        return
    fig, axs = plt.subplots(2, 2, figsize=(12, 9))
    panels = [("0.3", axs[0, 0]), ("0.6", axs[0, 1]), ("1.1", axs[1, 0])]
    m0, dm = MEASURED_PLATEAU
    say("== ACOR, 6 mm beams (linear spring; 'corr' = x 0.85). Central section: > %g m from both ends" % END_ZONE)
    for L, ax in panels:
        free, clamped = runs[(L, "free")], runs[(L, "clamped")]
        if L in ("0.6", "1.1"):
            ax.axhspan(m0 - dm, m0 + dm, color="0.85", zorder=0, label="measured plateau %.2f $\\pm$ %.2f" % (m0, dm))
        for run, colour, lab in ((free, "tab:blue", "free-free"), (clamped, "tab:red", "clamped at x = 0")):
            if run is None:
                continue
            x = run["x"] * 100
            ax.plot(x, run["acor_corrected"], "-", color=colour, lw=1.8, label="%s, x 0.85" % lab)
            ax.plot(x, run["acor"], ":", color=colour, lw=1.2, label="%s, raw" % lab)
            dbl = run["contacts"] > 1
            if dbl.any():
                ax.plot(x[dbl], run["acor_corrected"][dbl], "x", color=colour, ms=5, label="two or more contacts")
            c = central(run)
            if c.any():
                a = run["acor_corrected"][c]
                say("  L = %s m %-8s central mean %.3f, range %.3f-%.3f (%d points); contact %.2f-%.2f ms; free-free T1 = %.2f ms"
                    % (L, run.attrs["beam_left"], a.mean(), a.min(), a.max(), c.sum(), run["contact_time"].min() * 1e3, run["contact_time"].max() * 1e3,
                       fundamental_period_free(run) * 1e3))
        if free is not None and clamped is not None:
            xc = clamped["x"]
            diff = np.abs(np.interp(xc, free["x"], free["acor_corrected"]) - clamped["acor_corrected"])
            # the points from which on, up to END_ZONE before the free end, the clamp changes the ACOR by < 0.02
            inner = xc <= float(L) - END_ZONE + 1e-9
            big = np.where((diff > 0.02) & inner)[0]
            start = xc[big[-1] + 1] if len(big) else xc[0]
            if len(big) and (big[-1] + 1 >= len(xc) or not inner[big[-1] + 1]):
                say("  L = %s m: clamping x = 0 changes the ACOR by > 0.02 everywhere up to %.2f m (%g cm from the free end)" % (L, float(L) - END_ZONE, END_ZONE * 100))
            else:
                say("  L = %s m: clamping x = 0 changes the ACOR by < 0.02 for %.2f <= x <= %.2f m" % (L, start, float(L) - END_ZONE))
        if free is not None and free.attrs.get("rigid_loss_fraction", 0) > 0:
            f = free.attrs["rigid_loss_fraction"]
            ax.plot(free["x"] * 100, free["rigid_acor"], "k--", lw=1.2, label="rigid body, Eq. (11), f = %g" % f)
            dev = free["acor_corrected"] - free["rigid_acor"]
            say("  L = %s m free: rigid f = %g minus flexible (x 0.85): mean %+.3f, max |.| %.3f; forced f mean %.2f (range %.2f-%.2f) over the central section"
                % (L, f, -dev.mean(), np.abs(dev).max(), free["rigid_forced_loss_fraction"][central(free)].mean() if central(free).any() else np.nan,
                   free["rigid_forced_loss_fraction"][central(free)].min() if central(free).any() else np.nan,
                   free["rigid_forced_loss_fraction"][central(free)].max() if central(free).any() else np.nan))
        if L == "1.1" and hyst is not None:
            ax.plot(hyst["x"] * 100, hyst["acor"], "-", color="tab:green", lw=1.5, label="clamped, hysteretic ball")
            c = central(hyst)
            say("  L = 1.1 m clamped, hysteretic ball: central mean %.3f, range %.3f-%.3f" % (hyst["acor"][c].mean(), hyst["acor"][c].min(), hyst["acor"][c].max()))
            c2 = c & (hyst["x"] >= 0.35)
            lin = runs[("1.1", "clamped")]
            if lin is not None and c2.any():
                li = np.interp(hyst["x"][c2], lin["x"], lin["acor_corrected"])
                say("  ... over 0.35-0.95 m (beyond the clamp's reach): hysteretic %.3f-%.3f (mean %.3f); linear x 0.85 there: mean %.3f (hysteretic lower by %.3f)"
                    % (hyst["acor"][c2].min(), hyst["acor"][c2].max(), hyst["acor"][c2].mean(), li.mean(), li.mean() - hyst["acor"][c2].mean()))
        ax.set_title("L = %s m, a = 6 mm" % L)
    ax = axs[1, 1]
    six = runs[("1.1", "free")]
    ax.axhspan(m0 - dm, m0 + dm, color="0.85", zorder=0, label="measured plateau (6 mm) %.2f $\\pm$ %.2f" % (m0, dm))
    for run, colour, lab in ((thick, "tab:purple", "a = 10 mm"), (six, "tab:blue", "a = 6 mm")):
        if run is None:
            continue
        ax.plot(run["x"] * 100, run["acor_corrected"], "-", color=colour, lw=1.8, label="%s free-free, x 0.85" % lab)
        if run is thick:
            ax.plot(run["x"] * 100, run["acor"], ":", color=colour, lw=1.2, label="%s, raw" % lab)
            c = central(run)
            say("  L = 1.1 m a = 10 mm free: central mean %.3f, range %.3f-%.3f; contact %.2f-%.2f ms"
                % (run["acor_corrected"][c].mean(), run["acor_corrected"][c].min(), run["acor_corrected"][c].max(), run["contact_time"].min() * 1e3, run["contact_time"].max() * 1e3))
    ax.set_title("L = 1.1 m, a = 10 mm (6 mm for comparison)")
    for ax in axs.flat:
        ax.set_xlabel("impact point x (cm from the x = 0 end)")
        ax.set_ylabel("ACOR")
        ax.set_ylim(-0.2, 1.0)
        ax.axhline(0, color="0.5", lw=0.5)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="lower center")
    fig.suptitle("ACOR against impact point: aluminium beams (b = 32 mm), 42 g superball at 1 m/s", fontsize=12)
    fig.tight_layout()
    save(fig, d, "acor.png")


# ----------------------------------------------------------------------------------------
# snapshots
# ----------------------------------------------------------------------------------------
def snapshot_panel(ax, run, title, every=None):
    sn = run.snapshots
    x = sn["x"] * 100
    colours = ["tab:blue", "tab:orange", "tab:red", "tab:green", "tab:purple", "tab:brown", "k"]
    for k, (tk, y) in enumerate(zip(sn["time"], sn["y"])):
        ax.plot(x, y * 1e3, color=colours[k % len(colours)], lw=1.6, label="t = %g ms" % (tk * 1e3))
    ximp = run["x"][0] * 100
    ax.axvline(ximp, color="k", lw=0.8, ls="--")
    ax.annotate("impact", (ximp, ax.get_ylim()[1]), xytext=(3, -12), textcoords="offset points", fontsize=8)
    ax.axhline(0, color="0.5", lw=0.5)
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("x (cm)")
    ax.set_ylabel("displacement y (mm)")
    ax.grid(alpha=0.3)


def fig_snapshots(d):
    runs = [(p, load(d, "snapshots-%s.h5" % p)) for p in ("0.55", "0.90", "1.03")]
    runs = [(p, r) for p, r in runs if r is not None]
    if not runs:
        return
    fig, axs = plt.subplots(len(runs), 1, figsize=(9, 3.3 * len(runs)), sharex=True)
    axs = np.atleast_1d(axs)
    say("== snapshots of the 1.1 m free beam (linear spring)")
    for ax, (p, r) in zip(axs, runs):
        snapshot_panel(ax, r, "impact at %g cm: contact %.2f ms, %d contact(s), ACOR x 0.85 = %.3f" % (float(p) * 100, r["contact_time"][0] * 1e3, r["contacts"][0], r["acor_corrected"][0]))
        ax.legend(fontsize=8, loc="best")
        y = r.snapshots["y"]
        say("  impact %s m: contact %.2f ms, contacts %d, ACOR %.3f (x 0.85 %.3f); max |y| at 1/3/5 ms: %s mm"
            % (p, r["contact_time"][0] * 1e3, r["contacts"][0], r["acor"][0], r["acor_corrected"][0], ", ".join("%.3f" % (np.abs(yy).max() * 1e3) for yy in y)))
    for ax in axs[:-1]:
        ax.set_xlabel("")
    fig.suptitle("1.1 m x 6 mm aluminium beam, free-free: displacement at 1, 3, 5 ms (ball moving in +y)", fontsize=11)
    fig.tight_layout()
    save(fig, d, "snapshots.png")


# ----------------------------------------------------------------------------------------
# energy against time
# ----------------------------------------------------------------------------------------
def fig_energy(d):
    runs = [(p, load(d, "energy-%s.h5" % p)) for p in ("0.55", "0.90")]
    runs = [(p, r) for p, r in runs if r is not None]
    if not runs:
        return
    fig, axs = plt.subplots(1, len(runs), figsize=(6.2 * len(runs), 4.8), sharey=True)
    axs = np.atleast_1d(axs)
    say("== energy: 1.1 m free beam, hysteretic ball (mJ; incident %.2f mJ)" % (0.5 * runs[0][1].attrs["ball_mass"] * runs[0][1].attrs["ball_speed"] ** 2 * 1e3))
    for ax, (p, r) in zip(axs, runs):
        s = r.series
        t = s["time"] * 1e3
        ax.plot(t, s["ball_kinetic"] * 1e3, color="tab:blue", lw=1.5, label="ball kinetic")
        ax.plot(t, (s["ball_stored"] + s["ball_dissipated"]) * 1e3, color="tab:cyan", lw=1.5, label="ball potential + lost (work done on the ball)")
        ax.plot(t, s["ball_dissipated"] * 1e3, color="tab:gray", lw=1.2, ls="-.", label="of which lost (booked at maximum compression)")
        ax.plot(t, s["beam_kinetic"] * 1e3, color="tab:red", lw=1.5, label="beam kinetic")
        ax.plot(t, s["beam_strain"] * 1e3, color="tab:orange", lw=1.5, label="beam potential (strain)")
        ax.plot(t, s["total_energy"] * 1e3, "k--", lw=1, label="sum")
        ax.set_title("impact at %g cm: ACOR %.3f, contact %.2f ms" % (float(p) * 100, r["acor"][0], r["contact_time"][0] * 1e3), fontsize=10)
        ax.set_xlabel("time (ms)")
        ax.grid(alpha=0.3)
        E0 = s["total_energy"][0]
        say("  impact %s m: at 20 ms ball KE %.2f%%, lost in ball %.2f%%, beam KE %.2f%%, beam PE %.2f%% of the incident; "
            "after the collision: translation %.1f%%, rotation %.1f%%, vibration %.1f%%; energy error %.1e"
            % (p, 100 * s["ball_kinetic"][-1] / E0, 100 * s["ball_dissipated"][-1] / E0, 100 * s["beam_kinetic"][-1] / E0, 100 * s["beam_strain"][-1] / E0,
               100 * r["translation_fraction"][0], 100 * r["rotation_fraction"][0], 100 * r["vibration_fraction"][0], r["energy_error"][0]))
    axs[0].set_ylabel("energy (mJ)")
    axs[0].set_ylim(-0.5, 1.45 * 1e3 * runs[0][1].series["total_energy"][0])
    axs[-1].legend(fontsize=7.5, loc="upper right", ncol=2, framealpha=0.95)
    fig.suptitle("Energy during the impact: 1.1 m x 6 mm free beam, 42 g hysteretic ball at 1 m/s (Crank-Nicolson, 5 $\\mu$s)", fontsize=11)
    fig.tight_layout()
    save(fig, d, "energy.png")


# ----------------------------------------------------------------------------------------
# racket
# ----------------------------------------------------------------------------------------
STRINGS = (1, 34)  # cm


def fig_racket_acor(d):
    runs = [(s, load(d, "racket-acor-%s.h5" % s)) for s in ("free", "pinned", "clamped")]
    runs = [(s, r) for s, r in runs if r is not None]
    if not runs:
        return
    fig, axs = plt.subplots(2, 1, figsize=(9, 9), sharex=True)
    colours = {"free": "tab:blue", "pinned": "tab:orange", "clamped": "tab:red"}
    labels = {"free": "handle free", "pinned": "pinned at 72 cm", "clamped": "clamped 62-72 cm"}
    for ax in axs:
        ax.axvspan(*STRINGS, color="0.9", zorder=0, label="strings %d-%d cm" % STRINGS)
    say("== racket ACOR (tennis ball, hysteretic); strings %d-%d cm" % STRINGS)
    strings = None
    for s, r in runs:
        x = r["x"] * 100
        axs[0].plot(x, r["acor"], "-", color=colours[s], lw=1.8, label=labels[s])
        axs[1].plot(x, r["contact_time"] * 1e3, "-", color=colours[s], lw=1.8, label=labels[s])
        dbl = r["contacts"] > 1
        if dbl.any():
            axs[0].plot(x[dbl], r["acor"][dbl], "x", color=colours[s], ms=6)
        strings = (x >= STRINGS[0] - 1e-9) & (x <= STRINGS[1] + 1e-9)
        k = np.argmax(np.where(strings, r["acor"], -1))
        say("  %-8s max ACOR on the strings %.3f at %g cm; ACOR at 10/20/30 cm %s; contact at 10/20/30 cm %s ms; double contacts at %s cm"
            % (s, r["acor"][k], x[k], " ".join("%.3f" % np.interp(c, x, r["acor"]) for c in (10, 20, 30)),
               " ".join("%.2f" % (np.interp(c, x, r["contact_time"]) * 1e3) for c in (10, 20, 30)), ",".join("%g" % v for v in x[dbl]) or "none"))
    free = dict(runs).get("free")
    if free is not None:
        f = free.attrs["rigid_loss_fraction"]
        axs[0].plot(free["x"] * 100, free["rigid_acor"], "k--", lw=1.2, label="rigid free racket, Eq. (11), f = %g" % f)
        st = (free["x"] * 100 >= STRINGS[0]) & (free["x"] * 100 <= STRINGS[1])
        dev = free["rigid_acor"][st] - free["acor"][st]
        say("  free: rigid f = %g minus flexible over the strings: mean %+.3f, max |.| %.3f; forced f on the strings %.2f-%.2f"
            % (f, dev.mean(), np.abs(dev).max(), free["rigid_forced_loss_fraction"][st].min(), free["rigid_forced_loss_fraction"][st].max()))
    cl = dict(runs).get("clamped")
    if free is not None and cl is not None:
        st = (free["x"] * 100 >= STRINGS[0]) & (free["x"] * 100 <= STRINGS[1])
        single = st & (np.interp(free["x"], cl["x"], cl["contacts"]) == 1) & (free["contacts"] == 1)
        ratio = np.interp(free["x"][single], cl["x"], cl["contact_time"]) / free["contact_time"][single]
        k = np.argmax(ratio)
        say("  contact time clamped / free over the strings, single contacts (%.0f-%.0f cm): %.2f-%.2f (mean %.2f), largest at %.0f cm"
            % (free["x"][single].min() * 100, free["x"][single].max() * 100, ratio.min(), ratio.max(), ratio.mean(), free["x"][single][k] * 100))
    axs[0].set_ylabel("ACOR")
    axs[0].set_ylim(-0.2, 1.0)
    axs[0].axhline(0, color="0.5", lw=0.5)
    axs[0].legend(fontsize=8, loc="lower right")
    axs[0].set_title("Racket (L = 72 cm, M = 320 g, a = 20 mm), 57 g hysteretic ball at 1 m/s; shaded: strings; x: two contacts", fontsize=10)
    axs[1].set_ylabel("contact time (ms)")
    axs[1].set_xlabel("impact point x (cm from the tip)")
    axs[1].legend(fontsize=8)
    for ax in axs:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, d, "racket_acor.png")


def fig_racket_snapshots(d):
    runs = [(s, load(d, "racket-snapshots-%s.h5" % s)) for s in ("pinned", "clamped")]
    runs = [(s, r) for s, r in runs if r is not None]
    if not runs:
        return
    fig, axs = plt.subplots(len(runs), 1, figsize=(9, 3.6 * len(runs)), sharex=True)
    axs = np.atleast_1d(axs)
    say("== racket snapshots")
    for ax, (s, r) in zip(axs, runs):
        what = "pinned at 72 cm" if s == "pinned" else "clamped over 62-72 cm"
        snapshot_panel(ax, r, "handle %s, impact at %g cm: contact %.2f ms, ACOR %.3f" % (what, r["x"][0] * 100, r["contact_time"][0] * 1e3, r["acor"][0]))
        if s == "clamped":
            ax.axvspan(62, 72, color="0.85", zorder=0, label="clamped 62-72 cm")
        ax.legend(fontsize=8, ncol=2, loc="best")
        say("  %s, impact %.2f m: contact %.2f ms, ACOR %.3f, contacts %d" % (s, r["x"][0], r["contact_time"][0] * 1e3, r["acor"][0], r["contacts"][0]))
    for ax in axs[:-1]:
        ax.set_xlabel("")
    axs[-1].set_xlabel("x (cm from the tip)")
    fig.suptitle("Racket displacement every 2 ms (57 g hysteretic ball at 1 m/s, moving in +y)", fontsize=11)
    fig.tight_layout()
    save(fig, d, "racket_snapshots.png")


def fig_racket_energy(d):
    paths = sorted(glob.glob(os.path.join(d, "racket-energy", "x*.h5")))
    if not paths:
        MISSING.append(os.path.join(d, "racket-energy", "x*.h5"))
        return
    runs = [Run(p) for p in paths]
    runs.sort(key=lambda r: r["x"][0])
    col = lambda k: np.array([r[k][0] for r in runs])  # noqa: E731
    x = col("x") * 100
    say("== racket energy (free racket), %d points" % len(runs))
    fig, axs = plt.subplots(2, 1, figsize=(9, 9), sharex=True)
    for ax in axs:
        ax.axvspan(*STRINGS, color="0.9", zorder=0, label="strings")
    ax = axs[0]
    acor = col("acor")
    parts = [
        ("ball_loss_fraction", "lost in the ball", "tab:gray"),
        ("vibration_fraction", "beam vibration", "tab:orange"),
        ("translation_fraction", "beam translation", "tab:blue"),
        ("rotation_fraction", "beam rotation", "tab:green"),
    ]
    for k, lab, c in parts:
        ax.plot(x, col(k), "-o", color=c, ms=3, lw=1.6, label=lab)
    ax.plot(x, acor**2, "-o", color="tab:purple", ms=3, lw=1.2, label="ball rebound, ACOR$^2$")
    loss = col("ball_loss_fraction") + col("vibration_fraction")
    ax.plot(x, loss, "k-", lw=1, label="ball loss + vibration")
    sweep = load(d, "racket-acor-free.h5")
    if sweep is not None:
        ax.plot(sweep["x"] * 100, sweep["rigid_forced_loss_fraction"], "k:", lw=1.5, label="forced rigid fit f (Eq. 11), racket-acor sweep")
        fi = np.interp(col("x"), sweep["x"], sweep["rigid_forced_loss_fraction"])
        say("  forced rigid f minus (ball loss + vibration): max |.| %.1e" % np.abs(fi - loss).max())
    ax.set_ylabel("fraction of the incident energy")
    ax.set_ylim(0, 1)
    ax.legend(fontsize=8, loc="upper center", ncol=2)
    ax.set_title("Free racket, 57 g hysteretic ball at 1 m/s: where the energy goes (after the collision)", fontsize=10)
    ax = axs[1]
    peak = col("segment_kinetic_peak") * 1e3
    E0 = 0.5 * runs[0].attrs["ball_mass"] * runs[0].attrs["ball_speed"] ** 2 * 1e3
    ax.plot(x, peak, "-o", color="tab:red", ms=3, lw=1.6, label="peak within 30 ms")
    ax.set_ylabel("handle (62-72 cm) kinetic energy (mJ)")
    ax.set_xlabel("impact point x (cm from the tip)")
    ax2 = ax.secondary_yaxis("right", functions=(lambda e: e / E0, lambda q: q * E0))
    ax2.set_ylabel("fraction of the incident %.1f mJ" % E0)
    ax.legend(fontsize=8)
    ax.set_title("Peak kinetic energy of the last 10 cm of the handle, t <= 30 ms", fontsize=10)
    for a in axs:
        a.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, d, "racket_energy.png")
    st = (x >= STRINGS[0]) & (x <= STRINGS[1])
    kmin, kmax = np.argmin(np.where(st, peak, np.inf)), np.argmax(np.where(st, peak, -np.inf))
    for c in (10, 20, 30):
        i = np.argmin(np.abs(x - c))
        say("  x = %g cm: ball loss %.3f, vibration %.3f, translation %.3f, rotation %.3f, rebound %.3f; handle peak %.3f mJ at %.1f ms"
            % (x[i], col("ball_loss_fraction")[i], col("vibration_fraction")[i], col("translation_fraction")[i], col("rotation_fraction")[i], acor[i] ** 2, peak[i],
               col("segment_kinetic_peak_time")[i] * 1e3))
    say("  handle peak on the strings: min %.3f mJ at %g cm, max %.3f mJ at %g cm; vibration fraction on the strings %.3f-%.3f (min at %g cm)"
        % (peak[kmin], x[kmin], peak[kmax], x[kmax], col("vibration_fraction")[st].min(), col("vibration_fraction")[st].max(), x[st][np.argmin(col("vibration_fraction")[st])]))
    say("  energy check: max |fractions + ACOR^2 - 1| = %.1e" % np.abs(loss + col("translation_fraction") + col("rotation_fraction") + acor**2 - 1).max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", help="directory with the scenes' HDF5 files (out/paper); figures are written there")
    args = ap.parse_args()
    d = args.dir
    if not os.path.isdir(d):
        sys.stderr.write("paper_figures.py: %s is not a directory (run scripts/run_paper.sh first; it writes out/paper/)\n" % d)
        return 2
    plt.rcParams.update({"font.size": 9, "axes.titlesize": 10})
    for fig in (fig_modes, fig_waves, fig_acor, fig_snapshots, fig_energy, fig_racket_acor, fig_racket_snapshots, fig_racket_energy):
        fig(d)
    with open(os.path.join(d, "summary.txt"), "w") as f:
        f.write("\n".join(SUMMARY) + "\n")
    print("wrote", os.path.join(d, "summary.txt"))
    if MISSING:
        sys.stderr.write("paper_figures.py: missing (their figures skipped or incomplete):\n  " + "\n  ".join(MISSING) + "\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
