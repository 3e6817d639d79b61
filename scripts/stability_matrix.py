#!/usr/bin/env python3
"""Stability study (issue 5): stiff and extreme cases x every advertised integrator.

    scripts/stability_matrix.py [--exe build/release/beamimpact] [--jobs 2]
                                [--h5 out/stability.h5] [--md docs/stability.md]
                                [--cases a,b] [--integrators rk4,cn] [--list]

Every cell (case x integrator) runs `beamimpact -task impact` as a subprocess with
a timeout and the energy monitor on (-impact_energy_check), so a crash or a hang is
caught and classified rather than fatal. Each cell is then one of

  correct      the run finished and every number was verified against a reference
               within the tolerances in TOL (ACOR, first contact time, peak force,
               maximum compression, number of contacts, ended-in-contact), with no
               NaN/Inf anywhere in /results, and any physics check of the case (the
               rigid-body formula Eq. 11, the wall formulas, the energy bound, a free
               racket's three momenta) held;
  clear error  the program exited nonzero with a one-line message that names the
               cause, and the message is one of those the case declares acceptable
               for that integrator (ACCEPT: the right diagnosis for that cell);
  wrong        anything else: a number outside tolerance, an unexpected or
               unclear error, a crash, a hang, a NaN, a refusal that did not come.

References: the exact modal solution (`-reference modal`, linear spring) or, for the
hysteretic ball, tight runs (Crank-Nicolson at T_r/8000 and T_r/4000, Dormand-Prince at
-ts_rtol 1e-11) of which two must agree to TOL["reference"]; plus the closed forms where a
case has them.

Every derived scale comes from the program's own files, through scripts/beamimpact/derived.py:
the contact time T_r that sets each column's step (contact_time_scale of a one-point probe of
the case: a -task sweep cut off after 1 ns, which records the scene's root attributes without
computing an impact), the rigid-body ACOR of Eq. (11) (/results/rigid_acor of the cell) and the
wall's contact time and restitution (ball_wall_contact_time, ball_wall_cor). A beamimpact that
does not record them stops the study with a message naming the attribute (exit status 2).

Writes an HDF5 file with every cell (/cells/*, one row per cell, and /references/*)
and a Markdown report (table, tolerances, commands, non-correct cells, which
integrator is safe where). Exit status: 0 when no cell is wrong, 1 otherwise, 2 on
a usage or set-up problem.
"""
import argparse
import concurrent.futures
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

from beamimpact import derived, files

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# ---------------------------------------------------------------------------
# Tolerances: what "verified" means.
TOL = {
    "acor": 1e-3,            # |acor - acor_ref| (ACOR is in units of v_i)
    "contact_time": 1e-3,    # relative, duration of the first contact
    "peak_force": 1e-3,      # relative
    "max_compression": 1e-3, # relative
    "energy_growth": 1e-3,   # -impact_energy_growth_tol: the program stops beyond this
    "rigid": 1e-3,           # |acor - Eq. 11| in the rigid limit (continuum inertia M L^2/12)
    "wall": 1e-3,            # wall: contact time pi sqrt(m/k) (relative), e = 1 or sqrt((m+1)/(n+1))
    "reference": 1e-4,       # two tight reference runs must agree to this (ACOR)
    "spin": 1e-3,            # oblique rows: relative, the batted ball's spin (rad/s)
    "launch_angle": 0.05,    # oblique rows: degrees, the batted ball's launch angle
    "momentum": 1e-9,        # free racket rows: |change| of momentum, angular momentum and roll momentum (normalized, /results)
}

# Columns of /results that are NaN where they do not apply (the results table, issue 20: a swinging
# bat's, a pivoted rig's, Eq. (11) only for a free beam at rest, the hands', a monitored segment's);
# a NaN anywhere else, and an Inf anywhere, is a wrong cell. read_results leaves out the columns
# whose attribute applies is 0; this list is for files written without that attribute.
NAN_WHERE_NOT_APPLICABLE = {"bbs", "collision_efficiency", "bat_speed_end", "bat_angular_velocity_end", "recoil_factor", "bbcor",
                            "rigid_acor", "rigid_forced_loss_fraction", "grip_force_peak", "grip_force_peak_time", "grip_stored_end",
                            "hand_work_end", "segment_kinetic_peak", "segment_kinetic_peak_time"}

# ---------------------------------------------------------------------------
# Diagnoses: the one-line messages the program gives, by cause.
DIAGNOSES = {
    "held": r"is not allowed: that point is held fixed",
    "stability": r"is above the stability limit dt_max = \S+ s of -ts_type rk",
    "energy": r"energy grew by \S+ of the incident kinetic energy at t = \S+ s \(-ts_type \S+",
    "nan": r"the solution is not finite \(NaN/Inf\) at t = ",
    "diverged": r"time stepping stopped at t = \S+ s with -ts_type \S+: ",
    "chatter": r"more than -impact_max_contacts \d+ separate contacts",
    "no-modes": r"-ts_type modal needs the beam's modes: ",
    # Safety nets for two fixed defects (see ACCEPT_* below): the program names them if they recur.
    # the Newton residual of alpha2's second-order form has a round-off floor eps omega_max^2 |y|
    # above -snes_rtol x its initial norm (fine grids, a stiff beam, a beam that has flown away);
    "newton-stall": r"the Newton iteration stalled at a residual norm of \S+ .*round-off level.*set -snes_atol",
    # the maximum compression right after a reload (hysteretic law; the loading force jumps above
    # the unloading force there) can be missed, which would skip the lossy unloading branch.
    "reload-missed": r"separated at t = \S+ s while the hysteretic law was still in its loading branch: the maximum-compression event was missed",
}
# The two diagnoses above guard defects that are fixed (a Newton convergence test aware of the
# residual's round-off floor; event crossings that count a start within the event tolerance as
# before the crossing). They stay in the program as safety nets, but no cell may need them: if
# one fires again, the cell is 'wrong'.
ACCEPT_ALWAYS = {}
ACCEPT_HYSTERESIS = []

# ---------------------------------------------------------------------------
# The integrators: the advertised configurations (options/integrators/*.opts) with the
# step set per case from the contact time T_r = pi sqrt(m_r / k_eff), the ball's mass
# reduced with the free beam's, m_r = m_b M / (m_b + M) (the program's scale for its
# "cannot resolve the contact" warning, read from its file: contact_time_scale): fixed-step
# implicit types at T_r/400 (BDF2, whose
# error constant is larger, at T_r/800: the options files use the same 2:1 ratio); RK4 at
# the program's default step min(0.9 dt_max, T_c/200); Dormand-Prince adaptive at the
# file's tolerances.
INTEGRATORS = [
    # id, label, options, steps per T_c (None: the program chooses)
    ("rk4", "rk 4 fixed", "-ts_type rk -ts_rk_type 4 -ts_adapt_type none", None),
    ("rk5dp", "rk 5dp adaptive", "-ts_type rk -ts_rk_type 5dp -ts_rtol 1e-8 -ts_atol 1e-10", None),
    ("cn", "cn", "-ts_type cn", 400),
    ("theta", "theta (midpoint)", "-ts_type theta -ts_theta_theta 0.5", 400),
    ("bdf2", "bdf 2", "-ts_type bdf -ts_bdf_order 2 -ts_adapt_type none", 800),
    ("arkimex", "arkimex", "-ts_type arkimex -ts_adapt_type none", 400),
    ("rosw", "rosw", "-ts_type rosw -ts_adapt_type none", 400),
    ("irk", "irk (gauss 2)", "-ts_type irk -ts_irk_nstages 2 -ts_adapt_type none", 400),
    ("alpha2", "alpha2 (radius 0.8)", "-ts_type alpha2 -ts_alpha_radius 0.8", 400),
    ("modal", "modal (order 4)", "-ts_type modal -ts_modal_order 4", 100),
]
EXPLICIT = {"rk4": "4", "rk5dp": "5dp"}

# ---------------------------------------------------------------------------
# The scene every case starts from: the paper's 1.1 m x 6 mm x 32 mm aluminium beam,
# free-free, N = 41, the 42 g superball at 1 m/s as a linear spring k = 2e4 N/m,
# struck at the centre.
BASE = {
    "-beam_length": 1.1, "-beam_youngs_modulus": 7e10, "-beam_density": 2700.0,
    "-beam_thickness": 0.006, "-beam_width": 0.032, "-beam_nodes": 41,
    "-beam_left": "free", "-beam_right": "free",
    "-ball_mass": 0.042, "-ball_speed": 1.0, "-ball_law": "linear", "-ball_k": 2e4,
    "-impact_x": 0.55,
}
# A bat from options/bats/ replaces the strip: the uniform section's options are removed.
BAT = {"-beam_length": None, "-beam_youngs_modulus": None, "-beam_density": None, "-beam_thickness": None, "-beam_width": None}
# A held circular bed (bed_impact.py's defaults, tests/test_racket.cpp: R = 15 cm, 240 N strings
# 15 mm apart, 1.5 g/m), struck by a linear ball of 57 g, k = 3e4 N/m.
HELD_BED = {"-strings_frame": "held", "-head_shape": "ellipse", "-head_length": 0.30, "-head_width": 0.30, "-strings_tension": 240.0,
            "-strings_spacing": 0.015, "-strings_linear_density": 0.0015, "-strings_nodes": 41, "-strings_patch_radius": 0.0165,
            "-ball_mass": 0.057, "-ball_k": 3e4}
HYST = {"-ball_law": "hysteresis", "-ball_k": None, "-ball_k1": 2e4, "-ball_m": 1.0, "-ball_n": 1.768}


class Case:
    """One row of the matrix.

    params   options on top of BASE (None removes one)
    expect   "result" (every integrator must give a verified number) or "refuse"
             (every integrator must stop with one of accept["*"])
    accept   {integrator id or "*": [diagnosis names]}: errors that are the right
             diagnosis for that cell
    per_int  {integrator id: extra options} (placed last: they win)
    checks   physics checks: "rigid", "wall", "negative_acor", "energy_bound", "oblique",
             "momenta" (a free racket: momentum, angular momentum and roll momentum kept)
    """

    def __init__(self, cid, title, params, expect="result", accept=None, per_int=None, checks=(),
                 timeout=300, ranks=1, why="", modal_reference=True):
        self.id, self.title, self.expect, self.why = cid, title, expect, why
        self.modal_reference = modal_reference  # False: tight runs are the reference
        self.params = dict(BASE)
        for k, v in params.items():
            if v is None:
                self.params.pop(k, None)
            else:
                self.params[k] = v
        self.accept = accept or {}
        self.per_int = per_int or {}
        self.checks = tuple(checks)
        self.timeout = timeout
        self.ranks = ranks

    def law(self):
        return self.params["-ball_law"]

    def nodes(self):
        """The grid's nodes along the frame (a held string bed's frame is its -strings_nodes)."""
        return self.params.get("-beam_nodes", self.params.get("-strings_nodes"))

    def args(self):
        out = []
        for k, v in self.params.items():
            out += [k, fmt(v)]
        return out

    def accepted(self, integ):
        out = list(self.accept.get("*", [])) + list(self.accept.get(integ, [])) + list(ACCEPT_ALWAYS.get(integ, []))
        if self.law() == "hysteresis":
            out += ACCEPT_HYSTERESIS
        return list(dict.fromkeys(out))


def preset(path):
    """The options of a ball, bat or base file (options/balls/*.opts, options/bats/*.opts,
    options/base/*.opts) as {option: value}, so that a matrix row runs the preset's own numbers.
    A nested -options_file is read in its place (options/base/racket-strung.opts includes
    racket.opts), later lines winning as in the program; a flag is written "true". A file path in
    it is relative to the preset file, as the program reads it."""
    out = {}
    with open(os.path.join(ROOT, path)) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if not line:
                continue
            if line[0] == "-options_file":
                out.update(preset(os.path.normpath(os.path.join(os.path.dirname(path), line[1]))))
            else:
                out[line[0]] = line[1] if len(line) > 1 else "true"  # a flag (-beam_torsion)
    for name in ("-beam_profile", "-beam_properties", "-ball_cor_table"):
        if name in out and not os.path.isabs(out[name]):
            out[name] = os.path.normpath(os.path.join(os.path.dirname(path), out[name]))
    return out


# The strung racket of issue 25 (the uniform frame, its roll, the bed), its options written out.
RACKET = preset("options/base/racket-strung.opts")


def fmt(v):
    if isinstance(v, float):
        return "%.10g" % v
    return str(v)




def cases():
    """The matrix rows (at least those of the issue)."""
    s = 5e-3  # s: short window for the stiff grids (the reference uses the same one)
    c = [
        Case("default", "default impact (1.1 m free-free, N = 41, centre)", {},
             why="baseline: no diagnostic may fire"),
        Case("hyst-default", "hysteretic ball, x = 0.9 m", dict(HYST, **{"-impact_x": 0.9}),
             checks=("energy_bound",)),
        Case("grid-1001", "stiff grid N = 1001 (window 5 ms)", {"-beam_nodes": 1001, "-impact_window": s},
             timeout=600),
        Case("grid-2001", "stiff grid N = 2001 (window 5 ms)", {"-beam_nodes": 2001, "-impact_window": s},
             timeout=900),
    ]
    # T_c: the 42 g ball's contact time on a wall, pi sqrt(m/k) (the title only; the steps use the program's T_r)
    for k, tc in ((1e3, "20.4"), (1e5, "2.04"), (1e6, "0.644"), (1e7, "0.204"), (1e8, "0.0644")):
        c.append(Case("k-%.0e" % k, "ball k = %.0e N/m (T_c = %s ms), x = 0.9 m" % (k, tc), {"-ball_k": k, "-impact_x": 0.9}))
    c += [
        Case("rigid", "nearly rigid beam (E x 1e4), x = 0.9 m", {"-beam_youngs_modulus": 7e14, "-impact_x": 0.9},
             checks=("rigid",)),
        Case("soft", "very soft beam (E / 1e2), x = 0.9 m", {"-beam_youngs_modulus": 7e8, "-impact_x": 0.9}),
        Case("heavy", "heavy ball 5 kg (beam 0.57 kg), centre", {"-ball_mass": 5.0}, checks=("negative_acor",)),
        Case("heavy-rigid", "heavy ball 5 kg on the rigid beam (E x 1e4), x = 0.9 m",
             {"-ball_mass": 5.0, "-beam_youngs_modulus": 7e14, "-impact_x": 0.9}, checks=("rigid", "negative_acor")),
        Case("light", "light ball 1 g, x = 0.9 m", {"-ball_mass": 0.001, "-impact_x": 0.9}),
        Case("tip-0", "free tip x = 0", {"-impact_x": 0.0}),
        Case("tip-L", "free tip x = L", {"-impact_x": 1.1}),
        Case("clamped-1node", "one node from the clamped end (x = h)", {"-beam_left": "clamped", "-impact_x": 1.1 / 40}),
        Case("pinned-point", "on the pinned end (x = L, pinned): refused", {"-beam_right": "pinned", "-impact_x": 1.1},
             expect="refuse", accept={"*": ["held"]}),
        Case("clamp-region", "inside -beam_clamp 0.9,1.1 (x = 1.0): refused", {"-beam_clamp": "0.9,1.1", "-impact_x": 1.0},
             expect="refuse", accept={"*": ["held"]}),
        Case("racket-pinned", "racket pinned at the handle (72 cm), tennis ball, x = 36 cm",
             dict(HYST, **{"-beam_length": 0.72, "-beam_youngs_modulus": None, "-beam_density": None,
                           "-beam_width": None, "-beam_mass": 0.32, "-beam_youngs_over_density": 1e7,
                           "-beam_thickness": 0.02, "-beam_right": "pinned", "-ball_mass": 0.057,
                           "-impact_x": 0.36}), checks=("energy_bound",)),
        Case("fast-40", "40 m/s, hysteretic superball, x = 0.9 m", dict(HYST, **{"-ball_speed": 40.0, "-impact_x": 0.9}),
             checks=("energy_bound",)),
        Case("baseball-40", "baseball 145 g at 40 m/s, hysteretic k1 = 1.5e6, n = 7 (e = 0.5), x = 0.9 m",
             dict(HYST, **{"-ball_mass": 0.145, "-ball_speed": 40.0, "-ball_k1": 1.5e6, "-ball_n": 7.0, "-impact_x": 0.9}),
             checks=("energy_bound",)),
        Case("baseball-preset", "baseball preset (options/balls/baseball.opts: e(v) table, 0.78 ms at 26.8 m/s) at 40 m/s, x = 0.9 m",
             dict(preset("options/balls/baseball.opts"), **{"-ball_k": None, "-ball_speed": 40.0, "-impact_x": 0.9}),
             checks=("energy_bound",), why="a ball law is finished only when the studies run it too"),
        # Real bats (options/bats/): a varying section replaces the strip (its options removed).
        # The Timoshenko bat's fastest waves are shear and bar waves (limit ~ h, not h^2), and the
        # hollow bat's knob is a thick ring next to a thin handle (a step in EI of 11x).
        Case("r161-euler", "R161 wood bat (profile), Euler-Bernoulli, N = 169, baseball preset at 40 m/s, x = 0.7 m",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "euler", "-beam_nodes": 169, "-impact_x": 0.7}},
             checks=("energy_bound",), why="a beam model is finished only when the studies run it too"),
        Case("r161-timoshenko", "R161 wood bat, Timoshenko (two dofs per node), N = 169, baseball preset at 40 m/s, x = 0.7 m",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.7}},
             checks=("energy_bound",)),
        Case("aluminium-timoshenko", "hollow aluminium bat, Timoshenko, N = 337, superball (linear) at 1 m/s, x = 0.8 m",
             {**BAT, **preset("options/bats/aluminium-bat.opts"), **{"-beam_theory": "timoshenko", "-beam_nodes": 337, "-impact_x": 0.8}},
             why="hollow sections with a step at the knob; the exact modal solution as reference"),
        # The barrel wall as a shell (issue 23): three harmonics' U, V, W per node in series with
        # the ball; a thin wall (hoop mode 1.6 kHz, soft in series) and a thick one (the corked
        # wood bat's 19-20 mm wall, hoop modes above 24 kHz: stiff dofs for the explicit limit).
        Case("shell-thin", "aluminium bat, its 2.5 mm barrel wall as a shell (-beam_shell), Timoshenko, N = 169, superball (linear) at 1 m/s, x = 0.66 m",
             {**BAT, **preset("options/bats/aluminium-bat.opts"), **{"-beam_theory": "timoshenko", "-beam_shell": "true", "-impact_x": 0.66}},
             why="the wall's fields in every tool; the exact modal solution (with the wall) as reference"),
        Case("shell-thick", "R161 corked (1 in bore, 19-20 mm wall) with -beam_shell, Timoshenko, superball (linear) at 1 m/s, x = 0.73 m",
             {**BAT, **preset("options/bats/r161.opts"), **{"-beam_profile": "options/bats/r161-corked.profile", "-beam_theory": "timoshenko",
                                                             "-beam_shell": "true", "-impact_x": 0.73}},
             why="a thick wall: stiff shell dofs (hoop modes > 24 kHz) next to the beam's"),
        # The bat in play: a swinging bat (its rigid motion is the initial state), a pivoted rig,
        # the hands (a time-dependent drive and a non-proportional damper on the handle).
        Case("r161-swing", "R161 swinging (V_cm 24 m/s, Omega 51 1/s), Timoshenko, N = 169, baseball preset at 40 m/s, x = 0.73 m",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.73, "-bat_speed": 24.0, "-bat_angular_velocity": 51.0}},
             checks=("energy_bound",), why="a swinging bat: approach speed 72 m/s at the impact point"),
        # Oblique impacts (issue 24): the normal run is the head-on one at v cos(theta); across the
        # line of centres friction (grip and slip, e_T) on the ball, its spin and the bat flexible
        # in its second plane (in its modes). Checked: spin and launch angle against the tight runs'.
        Case("r161-oblique", "R161 swinging, Timoshenko, N = 169, baseball at 40 m/s with 2000 rpm backspin, D = 2 cm, mu 0.5, e_T 0.3, x = 0.7 m",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.7, "-bat_speed": 24.0, "-bat_angular_velocity": 51.0,
                 "-impact_offset": 0.02, "-ball_spin": 209.4, "-ball_friction": 0.5, "-ball_tangential_cor": 0.3}},
             checks=("energy_bound", "oblique"), modal_reference=False, why="friction with grip and slip, the bat flexible in both planes"),
        Case("r161-oblique-high", "the same at a high offset D = 6 cm (theta = 62 deg: mostly sliding), mu 0.5, e_T 0.3",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.7, "-bat_speed": 24.0, "-bat_angular_velocity": 51.0,
                 "-impact_offset": 0.06, "-ball_spin": 209.4, "-ball_friction": 0.5, "-ball_tangential_cor": 0.3}},
             checks=("energy_bound", "oblique"), modal_reference=False, why="a glancing hit: a short, soft normal contact and a long slide"),
        Case("r161-oblique-grip", "the same at D = 3 cm with ample friction (mu 2) and a rigid grip (no e_T) on the flexible plane",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.7, "-bat_speed": 24.0, "-bat_angular_velocity": 51.0,
                 "-impact_offset": 0.03, "-ball_spin": 209.4, "-ball_friction": 2.0}},
             checks=("energy_bound", "oblique"), modal_reference=False, why="a rigid grip against the bat's ringing in its second plane (a constraint)"),
        Case("r161-pivot", "R161 pivoted at 15 cm (the BBCOR rig), baseball preset at 60.8 m/s, x = 0.73 m",
             {**BAT, **preset("options/bats/r161.opts"), **preset("options/balls/baseball.opts"),
              **{"-ball_k": None, "-beam_theory": "timoshenko", "-beam_nodes": 169, "-impact_x": 0.73, "-beam_pivot": 0.15, "-ball_speed": 60.8}},
             checks=("energy_bound",)),
        Case("grip", "the paper beam held over 0-15 cm (k' 1e6 N/m/m, c' 500 N s/m/m, 0.2 kg hands), x = 0.9 m",
             {"-grip": "0,0.15", "-grip_stiffness": 1e6, "-grip_damping": 500.0, "-grip_mass": 0.2, "-impact_x": 0.9}, modal_reference=False,
             accept={"modal": ["no-modes"]},
             why="the hands: a stiff, damped handle (non-proportional damping; the exact modal paths, -ts_type modal among them, refuse it by name)"),
        # A tuned absorber made extreme (issue 35; a structure part, system/parts/absorber.cpp): 20 g on a
        # 20 kHz spring (w_a 1.3e5 rad/s, 2.7 x the beam's w_max at N = 41) with zeta 0.5 near the tip:
        # its stiff, damped dof sets the explicit limit; its dashpot is not proportional damping.
        Case("absorber-stiff", "the paper beam with a stiff, damped absorber at 2 cm (-absorber 0.02,0.02,2e4,0.5), x = 0.9 m",
             {"-absorber": "0.02,0.02,2e4,0.5", "-impact_x": 0.9}, modal_reference=False, accept={"modal": ["no-modes"]},
             checks=("energy_bound",),
             why="a stiff, damped dof on its own field, coupled through the hat at x_a (non-proportional damping: -ts_type "
                 "modal refuses it by name; tight runs as reference)"),
        Case("double", "double impact: 30 cm clamped at x = 0, x = 29 cm",
             {"-beam_length": 0.3, "-beam_left": "clamped", "-impact_x": 0.29}),
        Case("triple", "triple impact: 30 cm clamped at x = 0, 100 g ball, x = 29.5 cm",
             {"-beam_length": 0.3, "-beam_left": "clamped", "-ball_mass": 0.1, "-impact_x": 0.295}),
        Case("long", "long window: 1 s after the impact, x = 0.9 m", {"-impact_x": 0.9, "-impact_window": 1.0}),
        Case("long-hyst", "long window, hysteretic ball: 1 s, x = 0.9 m", dict(HYST, **{"-impact_x": 0.9, "-impact_window": 1.0}),
             checks=("energy_bound",)),
        Case("dt-below", "N = 201, every type at 0.98 x its explicit limit (implicit: rk4's)", {"-beam_nodes": 201},
             per_int={"rk4": "-ts_dt {0.98*dtmax_rk4}", "rk5dp": "-ts_dt {0.98*dtmax_rk5dp}", "*": "-ts_dt {0.98*dtmax_rk4}"},
             why="fixed-step RK4 just below its limit must run and be right"),
        Case("dt-above", "N = 201, every type at 1.02 x its explicit limit (implicit: rk4's)", {"-beam_nodes": 201},
             per_int={"rk4": "-ts_dt {1.02*dtmax_rk4}", "rk5dp": "-ts_dt {1.02*dtmax_rk5dp}", "*": "-ts_dt {1.02*dtmax_rk4}"},
             accept={"rk4": ["stability"]},
             why="fixed-step RK4 must be refused naming dt_max; adaptive 5dp only starts there (its controller must bring "
                 "the step down)"),
        Case("dt-above-fixed5dp", "N = 201, RK 5dp (and RK4) with a fixed step 1.02 x its limit", {"-beam_nodes": 201},
             per_int={"rk5dp": "-ts_adapt_type none -ts_dt {1.02*dtmax_rk5dp}", "*": "-ts_dt {1.02*dtmax_rk4}"},
             accept={"rk4": ["stability"], "rk5dp": ["stability"]}),
        Case("wall", "wall (EI 1e10, mu 1e5, clamped both ends, N = 21)",
             {"-beam_youngs_modulus": None, "-beam_density": None, "-beam_thickness": None, "-beam_width": None,
              "-beam_EI": 1e10, "-beam_mu": 1e5, "-beam_nodes": 21, "-beam_left": "clamped", "-beam_right": "clamped"},
             checks=("wall",)),
        Case("wall-hyst", "wall, hysteretic ball",
             dict(HYST, **{"-beam_youngs_modulus": None, "-beam_density": None, "-beam_thickness": None, "-beam_width": None,
                           "-beam_EI": 1e10, "-beam_mu": 1e5, "-beam_nodes": 21, "-beam_left": "clamped", "-beam_right": "clamped"}),
             checks=("wall", "energy_bound")),
        Case("mpi2", "default impact on 2 MPI ranks, x = 0.9 m", {"-impact_x": 0.9}, ranks=2),
        # Rayleigh damping C = alpha M + beta K (reference: the exact modal solution, its contact
        # phases in the damped first-order modes). Light: zeta = 0.006 + 0.00016 at the
        # fundamental. Heavy beta: the grid-scale
        # modes are overdamped (beta omega_max / 2 = 2.3), their fast eigenvalue ~ -beta omega_max^2
        # sets the explicit limit (RK4: 1.34e-5 s, 1/4.5 of the undamped 6.1e-5 s): explicit types
        # are step-limited, implicit ones are not; above the damped limit a fixed RK step is refused.
        Case("damped", "Rayleigh damping alpha = 2 1/s, beta = 2e-6 s, x = 0.9 m",
             {"-beam_damping_mass": 2.0, "-beam_damping_stiffness": 2e-6, "-impact_x": 0.9},
             why="light damping: every integrator right, no diagnostic"),
        Case("damped-beta", "heavy stiffness damping beta = 1e-4 s (grid modes overdamped), x = 0.9 m",
             {"-beam_damping_stiffness": 1e-4, "-impact_x": 0.9},
             why="explicit RK step-limited by beta omega_max^2: its default step follows the damped limit (RK4 1.34e-5 s instead of 6.1e-5 s)"),
        Case("damped-beta-above", "beta = 1e-4 s, every type at 1.02 x RK4's damped limit",
             {"-beam_damping_stiffness": 1e-4, "-impact_x": 0.9},
             per_int={"rk4": "-ts_dt {1.02*dtmax_rk4}", "rk5dp": "-ts_adapt_type none -ts_dt {1.02*dtmax_rk5dp}", "*": "-ts_dt {1.02*dtmax_rk4}"},
             accept={"rk4": ["stability"], "rk5dp": ["stability"]},
             why="fixed-step RK refused naming the damped dt_max; implicit types run at that step"),
        # The racket (issue 25; options/base/racket-strung.opts: the uniform frame that rolls, a
        # string bed on its head): the bed's membrane dofs and the roll next to the beam's. A held
        # bed alone; the free racket struck off its axis; a bed 1e3 times tighter, whose grid modes
        # set the explicit limit (RK4's dt_max 2.5e-7 s against the frame's 3.9e-6 s at 250 N);
        # the hysteretic tennis ball. The linear rows have the exact modal solution (with the bed's
        # and the roll's modes); the free racket's three momenta are invariants of every integrator.
        Case("bed-held", "string bed in a held frame (circle R = 15 cm, N 16000 N/m, 41 nodes), linear ball 57 g, k = 3e4, load on a 16.5 mm disc, centre",
             {**BAT, **HELD_BED, **{"-beam_nodes": None, "-beam_left": None, "-beam_right": None, "-impact_x": 0.15}},
             why="the bed alone (a 2-D membrane on the system's fields); the exact modal solution as reference"),
        # An oblique impact on the held bed (issue 39): the normal run at v cos(40 deg), the mains
        # sliding sideways on their tension (the tangential plane's mode) under Coulomb friction;
        # spin and launch angle against the exact modal reference's.
        Case("bed-oblique", "the held bed struck at 40 deg with 20 rad/s of spin in, mu 0.4, the mains sliding (default in-plane spring), centre",
             {**BAT, **HELD_BED, **{"-beam_nodes": None, "-beam_left": None, "-beam_right": None, "-impact_x": 0.15, "-ball_radius": 0.0335,
                                    "-ball_inertia_factor": 0.55, "-impact_angle": 40.0, "-ball_spin": 20.0, "-ball_friction": 0.4}},
             checks=("energy_bound", "oblique"), why="friction, spin and the strings' in-plane slide on the membrane's normal run"),
        Case("racket-offaxis", "free strung racket (racket-strung.opts), linear ball 57 g, k = 2e4, x = 15 cm, 5 cm off the axis",
             {**BAT, **RACKET, **{"-ball_mass": 0.057, "-ball_radius": 0.0335, "-ball_k": 2e4, "-impact_x": 0.15, "-impact_z": 0.05}},
             checks=("momenta",), why="the bed on the rolling frame; the exact modal solution as reference; momentum, angular momentum and roll momentum kept"),
        Case("bed-stiff", "the same racket with the strings' tension x 1e3 (250 kN a string), 3 cm off the axis",
             {**BAT, **RACKET, **{"-strings_tension": 2.5e5, "-ball_mass": 0.057, "-ball_radius": 0.0335, "-ball_k": 2e4, "-impact_x": 0.15, "-impact_z": 0.03}},
             checks=("momenta",), why="stiff bed dofs: explicit types step-limited (RK4's default step 15 times finer than "
                                      "at 250 N, the limit now the bed's), implicit ones not"),
        Case("bed-stiff-above", "the stiff bed, every type at 1.02 x RK4's limit",
             {**BAT, **RACKET, **{"-strings_tension": 2.5e5, "-ball_mass": 0.057, "-ball_radius": 0.0335, "-ball_k": 2e4, "-impact_x": 0.15, "-impact_z": 0.03}},
             per_int={"rk4": "-ts_dt {1.02*dtmax_rk4}", "rk5dp": "-ts_adapt_type none -ts_dt {1.02*dtmax_rk5dp}", "*": "-ts_dt {1.02*dtmax_rk4}"},
             accept={"rk4": ["stability"], "rk5dp": ["stability"]}, checks=("momenta",), timeout=600,
             why="the explicit limit counts the bed's fastest modes: a fixed RK step above it is refused naming dt_max; implicit types run at that step"),
        Case("racket-hands", "the strung racket held by stiff hands over 52-72 cm (k' 1e6 N/m/m, c' 500 N s/m/m, the roll's k'_phi 1e4 N m/rad/m and c'_phi 5 N m s/rad/m, 0.3 kg), linear ball 57 g, k = 2e4, x = 15 cm, 5 cm off the axis",
             {**BAT, **RACKET, **{"-grip": "0.52,0.72", "-grip_stiffness": 1e6, "-grip_damping": 500.0, "-grip_torsion_stiffness": 1e4, "-grip_torsion_damping": 5.0, "-grip_mass": 0.3,
                                 "-ball_mass": 0.057, "-ball_radius": 0.0335, "-ball_k": 2e4, "-impact_x": 0.15, "-impact_z": 0.05}},
             modal_reference=False, accept={"modal": ["no-modes"]},
             why="the hands on the handle's deflection and roll: stiff, damped, non-proportional (the exact modal paths refuse it by name)"),
        Case("racket-hysteresis", "free strung racket, the tennis-ball preset (options/base/tennis-ball.opts), x = 15 cm, 5 cm off the axis",
             {**BAT, **RACKET, **preset("options/base/tennis-ball.opts"),
              **{"-ball_k": None, "-impact_x": 0.15, "-impact_z": 0.05}},
             checks=("energy_bound", "momenta"), why="the hysteretic ball on the bed; tight runs as reference"),
    ]
    return c


# ---------------------------------------------------------------------------
# Running.
def mpi_env():
    env = dict(os.environ)
    if hasattr(os, "getuid") and os.getuid() == 0:
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    return env


def run(cmd, timeout, cwd):
    """Runs cmd; returns dict(rc, out, err, elapsed, timeout). Never raises for the program's faults."""
    t0 = time.time()
    try:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=mpi_env(), start_new_session=True)
    except OSError as e:
        return {"rc": None, "out": "", "err": str(e), "elapsed": 0.0, "timeout": False}
    try:
        out, err = p.communicate(timeout=timeout)
        to = False
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, 9)  # the process group this cell started (mpiexec and its ranks)
        except OSError:
            pass
        out, err = p.communicate()
        to = True
    return {"rc": p.returncode, "out": out, "err": err, "elapsed": time.time() - t0, "timeout": to}


def read_results(path):
    """The /results row (and /events) of an impact file, or None; and the file itself, kept
    open for the derived quantities of the checks (res["_file"])."""
    try:
        f = h5py.File(path, "r")
        res = {k: float(np.asarray(f["results"][k][()]).ravel()[0]) for k in f["results"]
               if int(f["results"][k].attrs.get("applies", 1))}  # a column that does not apply to the case is NaN: left out
        if "events" in f:
            res["_events_kind"] = np.asarray(f["events"]["kind"][()])
            res["_events_compression"] = np.asarray(f["events"]["compression"][()])
        res["_file"] = f
        return res
    except Exception:  # a missing or damaged file is classified by the caller
        return None


def error_message(r):
    lines = [l for l in (r["err"] + "\n" + r["out"]).splitlines() if "beamimpact: error:" in l]
    if lines:
        return lines[0].split("beamimpact: error:", 1)[1].strip()
    return ""


def warnings_of(r):
    return [l.strip() for l in (r["out"] + "\n" + r["err"]).splitlines() if l.strip().startswith("WARNING")]


class Study:
    def __init__(self, exe, workdir, jobs, mpiexec):
        self.exe, self.workdir, self.jobs, self.mpiexec = exe, workdir, jobs, mpiexec
        self.dtmax = {}  # (case, rk type) -> dt_max (s)
        self.t_r = {}  # case -> T_r (s), the program's contact time scale

    def probe_scales(self, case):
        """T_r (s) of the case, from the program: a one-point -task sweep of the case cut off after
        1 ns (its file records the scene's root attributes, contact_time_scale among them, without
        computing an impact; the point itself ends as a failed row). None for a case that must be
        refused (its point cannot run: no step is needed). Raises derived.Missing when the
        program does not record the scale."""
        if case.expect == "refuse":
            return None
        if case.id not in self.t_r:
            d = os.path.join(self.workdir, "probe")
            os.makedirs(d, exist_ok=True)
            out = os.path.join(d, case.id + ".h5")
            if os.path.exists(out):
                os.remove(out)
            params = [w for w in case.args()]
            k = params.index("-impact_x")
            x = params[k + 1]
            del params[k:k + 2]
            cmd = [self.exe, "-task", "sweep"] + params + ["-sweep_x", x, "-impact_max_time", "1e-9", "-sweep_quiet", "-output", out]
            r = run(cmd, 300, ROOT)
            if r["rc"] not in (0, 2) or not os.path.exists(out):
                raise RuntimeError("the scales probe of case %s failed (exit %s): %s" % (case.id, r["rc"], (error_message(r) or (r["err"] + r["out"]))[-400:]))
            with files.open_file("stability_matrix.py", out) as f:
                self.t_r[case.id] = derived.contact_time_scale(f)
        return self.t_r[case.id]

    def resolve_time(self, case):
        """T_r (s): the contact against the free beam's mass, the program's scale (probe_scales)."""
        return self.probe_scales(case)

    def cmd(self, case, extra, out, ranks=None):
        ranks = ranks or case.ranks
        pre = [self.mpiexec, "-n", str(ranks)] if ranks > 1 else []
        return pre + [self.exe, "-task", "impact"] + case.args() + extra + ["-output", out]

    def probe_dtmax(self, case, rk):
        """dt_max of -ts_rk_type rk on the case's grid, from the program's own refusal of a huge fixed step."""
        key = (case.id, rk)
        if key not in self.dtmax:
            r = run([self.exe, "-task", "impact"] + case.args() +
                    ["-ts_type", "rk", "-ts_rk_type", rk, "-ts_adapt_type", "none", "-ts_dt", "1", "-output", "none"], 120, ROOT)
            m = re.search(r"dt_max = (\S+) s", error_message(r))
            if not m:
                raise RuntimeError("could not read dt_max of rk %s for case %s: %s" % (rk, case.id, (r["err"] + r["out"])[-400:]))
            self.dtmax[key] = float(m.group(1))
        return self.dtmax[key]

    def integrator_args(self, case, iid, opts, steps):
        extra = shlex.split(opts)
        if steps is not None and case.expect != "refuse":  # a refused case's point cannot run: no step
            extra += ["-ts_dt", "%.6g" % (self.resolve_time(case) / steps)]
        tmpl = case.per_int.get(iid, case.per_int.get("*"))
        if tmpl:
            def subst(m):
                factor, name = m.group(1), m.group(2)
                return "%.6g" % (float(factor) * self.probe_dtmax(case, EXPLICIT[name.split("_")[1]]))
            extra += shlex.split(re.sub(r"\{([0-9.]+)\*(dtmax_rk4|dtmax_rk5dp)\}", subst, tmpl))
        return extra + ["-impact_energy_check", "-impact_energy_growth_tol", fmt(TOL["energy_growth"])]

    # -- references --------------------------------------------------------
    def reference(self, case):
        """dict(method, res, note) or dict(method=None, note=why not)."""
        if case.expect == "refuse":
            return {"method": "none", "res": None, "note": "refusal expected", "cmd": ""}
        d = os.path.join(self.workdir, "ref")
        os.makedirs(d, exist_ok=True)
        if case.law() == "linear" and case.modal_reference:
            out = os.path.join(d, case.id + "-modal.h5")
            cmd = self.cmd(case, ["-reference", "modal"], out, ranks=1)
            r = run(cmd, 1800, ROOT)
            res = read_results(out) if r["rc"] == 0 else None
            if res is not None:
                return {"method": "modal", "res": res, "note": "exact modal solution", "cmd": cmd}
            note = "modal reference failed (%s); " % (error_message(r) or "rc %s" % r["rc"])
        else:
            note = ""
        # Tight runs: Crank-Nicolson at T_r/8000 and T_r/4000, and (grids up to N = 201)
        # Dormand-Prince at -ts_rtol 1e-11. The reference is the first of them, in that order,
        # that another one agrees with (ACOR within TOL["reference"], same contacts).
        tr = self.resolve_time(case)
        tight = [("CN at T_r/8000", ["-ts_type", "cn", "-ts_dt", "%.6g" % (tr / 8000)], "cn8000"),
                 ("RK 5dp at -ts_rtol 1e-11", ["-ts_type", "rk", "-ts_rk_type", "5dp", "-ts_rtol", "1e-11", "-ts_atol", "1e-14"], "rk5dp"),
                 ("CN at T_r/4000", ["-ts_type", "cn", "-ts_dt", "%.6g" % (tr / 4000)], "cn4000")]
        if int(case.nodes()) > 201:
            tight = [t for t in tight if t[2] != "rk5dp"]
        runs = []
        for name, extra, tag in tight:
            out = os.path.join(d, "%s-%s.h5" % (case.id, tag))
            cmd = self.cmd(case, extra, out, ranks=1)
            r = run(cmd, 3600, ROOT)
            res = read_results(out) if r["rc"] == 0 else None
            runs.append((name, res, cmd, error_message(r) or "rc %s" % r["rc"]))
        summary = "; ".join("%s: %s" % (n, ("ACOR %.8f, %d contacts" % (q["acor"], q["contacts"])) if q else "failed (%s)" % e[:200])
                            for n, q, _, e in runs)
        for i, (name, q, cmd, _) in enumerate(runs):
            if q is None:
                continue
            for name2, q2, _, _ in runs[i + 1:]:
                if q2 is not None and abs(q["acor"] - q2["acor"]) <= TOL["reference"] and q["contacts"] == q2["contacts"]:
                    return {"method": "tight", "res": q, "cmd": cmd,
                            "note": note + "%s, confirmed by %s (%s)" % (name, name2, summary)}
        return {"method": None, "res": None, "cmd": runs[0][2], "note": note + "no two tight runs agree: " + summary}

    # -- one cell ----------------------------------------------------------
    def cell(self, case, integ):
        iid, label, opts, steps = integ
        d = os.path.join(self.workdir, "cells")
        os.makedirs(d, exist_ok=True)
        out = os.path.join(d, "%s--%s.h5" % (case.id, iid))
        if os.path.exists(out):
            os.remove(out)
        try:
            extra = self.integrator_args(case, iid, opts, steps)
        except RuntimeError as e:
            return {"case": case.id, "integrator": iid, "cmd": [], "run": None, "setup_error": str(e)}
        cmd = self.cmd(case, extra, out)
        r = run(cmd, case.timeout, ROOT)
        res = read_results(out) if r["rc"] == 0 else None
        return {"case": case.id, "integrator": iid, "cmd": cmd, "run": r, "res": res}


# ---------------------------------------------------------------------------
# Classification.
def classify(case, cell, ref):
    """Returns (status, reason, measured dict)."""
    m = {}
    if cell.get("setup_error"):
        return "wrong", "study set-up: " + cell["setup_error"], m
    r = cell["run"]
    text = r["out"] + r["err"]
    m["warnings"] = warnings_of(r)
    if r["timeout"]:
        return "wrong", "no answer within the %d s timeout (hang or far too slow)" % case.timeout, m
    if r["rc"] is None:
        return "wrong", "could not start: " + r["err"].strip(), m
    if r["rc"] < 0 or r["rc"] > 1:
        return "wrong", "crash (exit status %d): %s" % (r["rc"], text.strip()[-300:]), m
    accepted = case.accepted(cell["integrator"])
    if r["rc"] != 0:
        msg = error_message(r)
        m["message"] = msg
        if not msg:
            return "wrong", "nonzero exit without a message: " + text.strip()[-300:], m
        for name in accepted:
            if re.search(DIAGNOSES[name], msg):
                return "clear error", "%s: %s" % (name, msg), m
        if re.search(r"\bnan\b", msg, re.I) and not re.search(DIAGNOSES["nan"], msg):
            return "wrong", "error message passes on a NaN: " + msg, m
        return "wrong", "unexpected error for this cell (acceptable: %s): %s" % (", ".join(accepted) or "none", msg), m
    if case.expect == "refuse":
        return "wrong", "accepted, but it must be refused (%s)" % ", ".join(accepted), m
    res = cell["res"]
    if res is None:
        return "wrong", "exit 0 but no readable /results in the output file", m
    if re.search(r"\b(nan|inf)\b", r["out"], re.I):
        return "wrong", "the summary prints NaN/Inf", m
    bad = [k for k, v in res.items() if not k.startswith("_") and not np.isfinite(v) and not (np.isnan(v) and k in NAN_WHERE_NOT_APPLICABLE)]
    if bad:
        return "wrong", "non-finite result(s): " + ", ".join(bad), m
    for k in ("acor", "contacts", "contact_time", "peak_force", "max_compression", "energy_error", "steps",
              "rejected_steps", "failed_solves", "wall_time", "dt_nominal", "dt_stable", "ended_in_contact"):
        m[k] = res.get(k, float("nan"))
    problems = []
    # Physics checks that need no reference.
    # A swinging bat gives the ball energy: there the bound holds in the bat's frame, on the
    # collision efficiency q = (bbs - V(x)) / (v_ball + V(x)).
    swinging = "-bat_speed" in case.params or "-bat_angular_velocity" in case.params
    e_bound = res.get("collision_efficiency", res["acor"]) if swinging else res["acor"]
    if "energy_bound" in case.checks and e_bound ** 2 > 1 + 1e-9:
        problems.append("%s^2 = %.6f > 1: the ball left with more than the incident energy%s" % ("q" if swinging else "ACOR", e_bound ** 2, " (in the bat's frame)" if swinging else ""))
    if res["energy_error"] > TOL["energy_growth"]:
        problems.append("energy grew by %.2e (> %.0e) without the monitor stopping the run" % (res["energy_error"], TOL["energy_growth"]))
    if "negative_acor" in case.checks and not res["acor"] < 0:
        problems.append("ACOR %.6f is not negative (the heavy ball must keep going forward)" % res["acor"])
    if "rigid" in case.checks:
        e11 = derived.rigid_acor(res["_file"])  # Eq. (11), f = 0, as the program computes it for this run
        m["rigid_acor"] = e11
        if abs(res["acor"] - e11) > TOL["rigid"]:
            problems.append("ACOR %.6f differs from Eq. 11 (%.6f) by more than %.0e" % (res["acor"], e11, TOL["rigid"]))
    if "oblique" in case.checks:  # the batted ball: every oblique column finite
        for k in ("exit_speed", "launch_angle", "spin", "friction_dissipated"):
            m[k] = res.get(k, float("nan"))
            if not np.isfinite(m[k]):
                problems.append("oblique: %s is %s" % (k, m[k]))
    if "momenta" in case.checks:  # a free racket: momentum, angular momentum and the roll's about the axis
        for k in ("linear_momentum_error", "angular_momentum_error", "roll_momentum_error"):
            m[k] = res.get(k, float("nan"))
            if not abs(m[k]) <= TOL["momentum"]:
                problems.append("%s %.1e (> %.0e)" % (k, m[k], TOL["momentum"]))
    if "wall" in case.checks:
        # the ball's contact time on a rigid wall (checked for the linear law: pi sqrt(m/k)) and its
        # wall COR (1, or sqrt((m+1)/(n+1)) for the hysteretic law), as the program records them
        T = derived.ball_wall_contact_time(res["_file"]) if case.law() == "linear" else None
        e = derived.ball_wall_cor(res["_file"])
        if T is not None and abs(res["contact_time"] / T - 1) > TOL["wall"]:
            problems.append("wall contact time %.6e differs from pi sqrt(m/k) = %.6e" % (res["contact_time"], T))
        if abs(res["acor"] - e) > TOL["wall"]:
            problems.append("wall ACOR %.6f differs from %.6f" % (res["acor"], e))
        if res["contacts"] != 1:
            problems.append("%d contacts on a wall" % res["contacts"])
    # Against the reference.
    if ref["res"] is None:
        problems.append("no reference: " + ref["note"])
        return ("wrong" if problems[:-1] else "unverified"), "; ".join(problems), m
    q = ref["res"]
    m["acor_ref"] = q["acor"]
    m["acor_error"] = abs(res["acor"] - q["acor"])
    if m["acor_error"] > TOL["acor"]:
        problems.append("ACOR %.6f vs reference %.6f (error %.1e > %.0e)" % (res["acor"], q["acor"], m["acor_error"], TOL["acor"]))
    if int(res["contacts"]) != int(q["contacts"]):
        problems.append("%d contacts vs %d in the reference" % (res["contacts"], q["contacts"]))
    if bool(res["ended_in_contact"]) != bool(q["ended_in_contact"]):
        problems.append("ended_in_contact %d vs %d in the reference" % (res["ended_in_contact"], q["ended_in_contact"]))
    for k in ("contact_time", "peak_force", "max_compression"):
        m[k + "_ref"] = q[k]
        if abs(res[k] - q[k]) > TOL[k] * abs(q[k]):
            problems.append("%s %.6e vs reference %.6e (relative %.1e > %.0e)" % (k, res[k], q[k], abs(res[k] / q[k] - 1), TOL[k]))
    if "oblique" in case.checks:  # spin and launch angle against the reference's
        for k, tol, rel in (("spin", TOL["spin"], True), ("launch_angle", TOL["launch_angle"], False)):
            m[k + "_ref"] = q.get(k, float("nan"))
            err = abs(res[k] - q[k]) / (abs(q[k]) if rel else 1.0)
            if not err <= tol:
                problems.append("%s %.6f vs reference %.6f (%s %.1e > %.0e)" % (k, res[k], q[k], "relative" if rel else "deg", err, tol))
    if problems:
        return "wrong", "; ".join(problems), m
    return "correct", "", m


# ---------------------------------------------------------------------------
# Report.
SYMBOL = {"correct": "correct", "clear error": "clear error", "wrong": "**WRONG**", "unverified": "**unverified**"}


def short(status, reason, m):
    if status == "correct":
        return "correct %.0e" % m["acor_error"] if m.get("acor_error", 0) > 0 else "correct 0"
    if status == "clear error":
        return "clear error (%s)" % reason.split(":", 1)[0]
    return SYMBOL[status]


def write_markdown(path, study_args, table, refs, integ, all_cases, counts, elapsed, exe):
    lines = []
    add = lines.append
    add("# Stability study: stiff and extreme cases x every advertised integrator")
    add("")
    add("Generated by `scripts/stability_matrix.py` (run it with `scripts/run_stability.sh`); "
        "issue 5. Every cell is one `beamimpact -task impact` run with the energy monitor on "
        "(`-impact_energy_check -impact_energy_growth_tol %g`), as a subprocess with a timeout." % TOL["energy_growth"])
    add("")
    add("**Result: %d cells: %d correct, %d clear error, %d wrong%s.** Study time %.0f s with %d parallel jobs."
        % (sum(counts.values()), counts["correct"], counts["clear error"], counts["wrong"],
           (", %d unverified" % counts["unverified"]) if counts["unverified"] else "", elapsed, study_args.jobs))
    add("")
    add("* **correct** — the run finished and its numbers match the reference within the tolerances below "
        "(the number in the cell is |ACOR − ACOR_ref|); no NaN/Inf anywhere; the case's physics checks hold.")
    add("* **clear error** — the program stopped (nonzero exit) with a one-line message naming the cause, and that "
        "message is the right diagnosis for the cell (listed per cell below).")
    add("* **WRONG** — anything else: a number outside tolerance, an unexpected or unclear error, a crash, a hang, a NaN, "
        "a refusal that did not come.")
    add("")
    add("## The matrix")
    add("")
    add("| case | reference ACOR (contacts) | " + " | ".join(lab for _, lab, _, _ in integ) + " |")
    add("|---|---|" + "---|" * len(integ))
    for case in all_cases:
        ref = refs[case.id]
        if ref["res"] is not None:
            rtxt = "%.6f (%d) %s" % (ref["res"]["acor"], ref["res"]["contacts"], "modal" if ref["method"] == "modal" else "tight")
        else:
            rtxt = "refused" if case.expect == "refuse" else "none"
        row = [short(*table[(case.id, i[0])][:3]) for i in integ]
        add("| `%s` %s | %s | %s |" % (case.id, case.title, rtxt, " | ".join(row)))
    add("")
    add("## Tolerances")
    add("")
    add("| quantity | tolerance |")
    add("|---|---|")
    add("| ACOR | absolute %g (units of v_i) |" % TOL["acor"])
    add("| first contact time, peak force, maximum compression | relative %g |" % TOL["contact_time"])
    add("| number of contacts, ended in contact | equal |")
    add("| energy | growth beyond %g of the incident energy stops the run (monitor); a finished run must be below it |" % TOL["energy_growth"])
    add("| rigid limit (`rigid`, `heavy-rigid`) | ACOR within %g of Eq. (11), f = 0, I = M L²/12 |" % TOL["rigid"])
    add("| wall (`wall`, `wall-hyst`) | contact time within %g (relative) of π√(m/k); ACOR within %g of 1 (linear) or √((m+1)/(n+1)) |" % (TOL["wall"], TOL["wall"]))
    add("| hysteretic ball | ACOR² ≤ 1 (energy can only be lost) |")
    add("| free racket (`racket-*`, `bed-stiff*`) | momentum, angular momentum about x = 0 and about the frame's axis (the roll) conserved: each change, normalized as in /results, within %g |" % TOL["momentum"])
    add("| tight references (hysteretic ball) | two of CN at T_r/8000, RK 5dp at -ts_rtol 1e-11 (N <= 201), CN at T_r/4000 agree within %g in ACOR and in contacts |" % TOL["reference"])
    add("")
    add("References: the exact modal solution (`-reference modal`) for the linear spring; for the hysteretic ball the first "
        "of CN at T_r/8000, RK 5dp at -ts_rtol 1e-11 and CN at T_r/4000 that another of them confirms. T_c = π√(m_b/k_eff) "
        "is the program's contact-time scale on a wall; T_r = T_c √(M/(M+m_b)) the contact against the free beam's mass M "
        "(the program's scale for its resolution warnings), read from the program's file (`contact_time_scale`), as are Eq. (11) "
        "(`/results/rigid_acor`) and the wall's contact time and restitution (`ball_wall_contact_time`, `ball_wall_cor`).")
    add("")
    add("## Integrators (the columns)")
    add("")
    add("| column | options | step |")
    add("|---|---|---|")
    for iid, lab, opts, steps in integ:
        step = "T_r/%d" % steps if steps else ("the program's default: min(0.9 dt_max, T_c/200)" if iid == "rk4" else "adaptive (capped at T_c/8)")
        add("| %s | `%s` | %s |" % (lab, opts, step))
    add("")
    add("Every cell also gets `-impact_energy_check -impact_energy_growth_tol %g`. Rows `dt-below`, `dt-above` and "
        "`dt-above-fixed5dp` replace the step by a multiple of the explicit stability limit dt_max, read from the program's own "
        "refusal of a huge fixed step." % TOL["energy_growth"])
    add("")
    add("## Cases (the rows) and their commands")
    add("")
    add("Each command is the case's options; a cell appends its column's options (and step). Run from the repository root.")
    add("")
    add("No cell may stop with `newton-stall` or `reload-missed`: those diagnoses guard two defects found by this "
        "study and fixed (see the end of this page); a recurrence makes the cell 'wrong'.")
    add("")
    for case in all_cases:
        acc = ", ".join("%s: %s" % (k, "/".join(v)) for k, v in case.accept.items()) or "none besides those above"
        add("* `%s` — %s. Expected: %s. Acceptable errors: %s.%s%s" % (
            case.id, case.title, "refusal" if case.expect == "refuse" else "a verified result", acc,
            (" Checks: %s." % ", ".join(case.checks)) if case.checks else "", (" " + case.why + ".") if case.why else ""))
        add("  `beamimpact -task impact %s`%s" % (" ".join(shlex.quote(a) for a in case.args()),
                                                 " (2 ranks: `mpiexec -n 2`)" if case.ranks > 1 else ""))
    add("")
    add("## Every cell that is not 'correct'")
    add("")
    nc = [(k, v) for k, v in table.items() if v[0] != "correct"]
    if not nc:
        add("None.")
    for (cid, iid), (status, reason, m, cmd) in sorted(nc, key=lambda kv: [c.id for c in all_cases].index(kv[0][0])):
        add("* `%s` × %s — **%s**: %s" % (cid, iid, status, reason))
    add("")
    add("## Warnings printed before the run")
    add("")
    warned = [(k, v[2].get("warnings")) for k, v in table.items() if v[2].get("warnings")]
    if not warned:
        add("None (no cell uses a step or tolerance that cannot resolve the contact).")
    for (cid, iid), w in warned:
        add("* `%s` × %s: %s" % (cid, iid, " / ".join(w)))
    add("")
    add("## Energy over a long window (1 s after the impact)")
    add("")
    add("Relative change of the total energy (ball kinetic + ball work + beam kinetic + strain) at the end of the run; "
        "it is exactly conserved by the semi-discrete model, so this is the integrator's drift.")
    add("")
    add("| case | " + " | ".join(lab for _, lab, _, _ in integ) + " |")
    add("|---|" + "---|" * len(integ))
    for cid in ("long", "long-hyst"):
        if any(c.id == cid for c in all_cases):
            row = []
            for i in integ:
                st, _, m, _ = table[(cid, i[0])]
                row.append("%.1e" % m["energy_error"] if "energy_error" in m else st)
            add("| `%s` | %s |" % (cid, " | ".join(row)))
    add("")
    add(DIAGNOSTICS)
    add("")
    add(SAFE_WHERE)
    add("")
    add("## Reproducing")
    add("")
    add("<!-- doc_commands: skip (about 15 minutes on 2 cores; the stability_subset test runs a fast part) -->")
    add("```sh")
    add("scripts/run_stability.sh            # builds nothing: uses build/release/beamimpact (or the path given)")
    add("scripts/stability_matrix.py --exe %s --jobs %d --h5 %s --md %s" % (
        os.path.relpath(exe, ROOT) if exe.startswith(ROOT) else exe, study_args.jobs, study_args.h5, study_args.md))
    add("scripts/stability_matrix.py --cases k-1e+08,double --integrators cn,rk4 --md none   # a part of it (--md none: this page stays)")
    add("```")
    add("")
    add("The HDF5 file holds every cell (`/cells/<column>`: case, integrator, status, reason, message, command, and the "
        "measured and reference numbers) and every reference (`/references/...`); its attributes hold the tolerances.")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


DIAGNOSTICS = """## What the program tells you

Checked by `tests/stability_subset.sh` (CTest `stability_subset`, about 20 s): each fires where it must,
and none fires on the default scene.

**Before the run** (`-task impact`): the integrator, its step and, for explicit types, the stability limit

    ts rk (explicit)  dt 2.276e-05 s
    explicit stability limit dt_max 6.0596e-05 s (omega_max <= 4.6677e+04 rad/s, set by the beam's bending)

and a warning when the step or the tolerance cannot resolve the contact:

    WARNING: fixed step -ts_dt 0.0001 s resolves the contact time scale 0.00439367 s with only 44 steps: errors of 1e-3 or more in the ACOR are possible; use -ts_dt <= 1.10e-05 (T_r/400)
    WARNING: fixed step -ts_dt 0.001 s is more than 1/8 of the contact time scale ...: the contact is poorly resolved and events may be missed
    WARNING: adaptive step with -ts_rtol 0.0001 -ts_atol 0.0001 cannot resolve the contact (compression scale 0.00145 m, contact time 0.00439 s): ...

Refused before any step: a fixed explicit step above dt_max (`-ts_dt 2.5e-06 is above the stability limit
dt_max = 2.42538e-06 s of -ts_type rk -ts_rk_type 4 on this grid (N = 201, ..., set by the beam's bending); use
-ts_dt <= 2.42538e-06, fewer nodes, or an implicit type`: the part named is the one whose row of `M⁻¹K` sets the
bound, the string bed's in `bed-stiff-above`), RK tableaus unstable on the imaginary axis, types that cannot roll back a
step, an impact point that is held.

**During the run** (`-impact_energy_check`, on in the study): growth of the total energy beyond
`-impact_energy_growth_tol` (1e-3 of the incident energy; it can only be conserved with the linear law and
lost with the hysteretic one) stops the run naming the time, integrator, step and likely cause:

    energy grew by 0.00106 of the incident kinetic energy at t = 0.000951014 s (-ts_type rk -ts_rk_type 5dp, adaptive, last step 4.84458e-05 s): with the linear law energy can only be conserved; likely cause: the error controller let the step reach the explicit stability limit dt_max = 2.13674e-05 s; tighten -ts_rtol/-ts_atol or use a fixed -ts_dt below dt_max

(for ARKIMEX: the contact force is its explicit part; for implicit types: the step or tolerance does not
resolve the contact). A NaN/Inf in the state stops the run at once; more than `-impact_max_contacts` contacts
is called chatter only when the energy has not grown (otherwise: an unstable integration).

**After the run**: PETSc's diverged reasons as a sentence — a failed Newton solve with its SNES reason,
iterations and residuals; a Newton iteration stalled at round-off with the `-snes_atol` that fixes it; too
many rejected steps. A separation in the hysteretic law's loading branch (a missed maximum compression) and
a non-finite final state are refused rather than reported. The summary line counts `rejected` steps and
`failed` solves.
"""

SAFE_WHERE = """## Which integrator is safe where

Read with the matrix: a cell marked correct is verified at the column's settings; the step matters more
than the type. The program warns before the run when a fixed step gives fewer than 100 steps per contact
time T_r, or when an adaptive run's tolerances are coarser than -ts_rtol 1e-4 or -ts_atol 1e-3 of the
compression scale (PETSc's default -ts_atol 1e-4 always is: a 1.2 mm compression cannot be followed to
0.1 mm) and the step can grow past T_r/100: not for an explicit type whose dt_max is below T_r/100, whose
steps the stability limit keeps finer than that (the bare default run: ACOR within 2.1e-6 of the exact
modal solution); it refuses fixed explicit steps above dt_max, RK types unstable on the imaginary axis, types that
cannot roll back a step, and impact points that are held.

| regime | safe | notes |
|---|---|---|
| default scenes (N = 41, superball, 1 m/s to 40 m/s, either law) | every column | RK4 at its default step is the cheapest |
| stiff grids (N = 1001, 2001) | cn, theta, bdf 2, arkimex, rosw | RK4 and RK 5dp are correct but need 1e5 to 1e6 steps (dt_max ~ h^2: 34 s and 210 s at N = 2001 for a 9 ms run); alpha2 correct |
| stiff ball (k up to 1e8 N/m, contact 64 us) | every column at T_r/400 | with adaptive steps ARKIMEX (contact force explicit) is stopped by the energy monitor; adaptive BDF2 at -ts_rtol 1e-4 gave ACOR errors of 1e-2 for k = 1e7 (not a column here): use fixed steps |
| nearly rigid beam, heavy ball (rigid limit, negative ACOR) | every column | Eq. (11) is met to 2e-4 |
| very soft beam, light ball, free tips, one node from a clamp, pinned racket | every column | |
| double and triple impacts near a free end | every column | each contact located; counts match the exact solution |
| long windows (1 s after the impact) | every column | energy drift over 1 s in the table above: cn/theta conserve the linear system's energy to round-off; bdf 2, arkimex, rosw lose ~3e-5 to 5e-5 of it; alpha2 ~1e-6 |
| explicit steps at the limit | RK4 at 0.98 dt_max is correct; above dt_max it is refused; adaptive RK 5dp started above its limit recovers | |
| the racket: a held string bed, the free strung racket struck 5 cm off its axis, the tennis ball on it | every column | every column keeps the free racket's momentum, angular momentum and roll momentum to 1e-11; a held bed's cell takes ~20 s, nearly all of it the exact free flight's 1245 dense modes after the separation |
| a bed 1e3 times tighter (250 kN a string) | every column | its grid modes set the explicit limit (RK4's dt_max 2.5e-7 s; 3.9e-6 s, the frame's, at 250 N): RK4 takes 20,100 steps (11 s), RK 5dp 30,600 (30 s), the implicit types 375 (3-5 s); a fixed RK step above dt_max is refused |

**Defects this study found, now fixed** (their diagnoses remain as safety nets; no cell needs them):

* `newton-stall` — alpha2 (second-order form): the Newton residual, in acceleration units, has a round-off
  floor eps·omega_max²·|y| (1e-7 at N = 201, 1e-2 at N = 2001, growing with |y| as a free beam flies away)
  above -snes_rtol × the initial residual, so Newton stalled on fine grids, stiff beams and long runs.
  Fixed by a convergence test that accepts a residual within 100× that floor (`TSConvergedWithRoundoffFloor`
  in src/solvers/ts_diagnostics.cpp); every alpha2 cell is now verified correct.
* `reload-missed` — hysteretic law: a reload located on its pre-event side (dc/dt slightly < 0) hid the
  maximum compression right after it, so the ball could leave in the loading branch without its loss
  (baseball case: ACOR -0.300 or -0.193 instead of -0.2147 depending on the step). Fixed in
  `ContactCrossedEvent`: a step starting within the event tolerance of zero counts as before the crossing;
  the baseball case now gives -0.214664 at every step."""


def write_h5(path, table, refs, all_cases, integ, counts, elapsed, exe):
    tmp = path + ".tmp"
    str_t = h5py.string_dtype()
    with h5py.File(tmp, "w") as f:
        for k, v in TOL.items():
            f.attrs["tol_" + k] = v
        f.attrs["executable"] = exe
        f.attrs["elapsed_s"] = elapsed
        for k, v in counts.items():
            f.attrs["count_" + k.replace(" ", "_")] = v
        f.attrs["integrators"] = ",".join(i[0] for i in integ)
        f.attrs["cases"] = ",".join(c.id for c in all_cases)
        g = f.create_group("cells")
        keys = sorted(table, key=lambda k: ([c.id for c in all_cases].index(k[0]), [i[0] for i in integ].index(k[1])))
        g.create_dataset("case", data=[k[0] for k in keys], dtype=str_t)
        g.create_dataset("integrator", data=[k[1] for k in keys], dtype=str_t)
        g.create_dataset("status", data=[table[k][0] for k in keys], dtype=str_t)
        g.create_dataset("reason", data=[table[k][1] for k in keys], dtype=str_t)
        g.create_dataset("message", data=[table[k][2].get("message", "") for k in keys], dtype=str_t)
        g.create_dataset("warnings", data=[" / ".join(table[k][2].get("warnings", [])) for k in keys], dtype=str_t)
        g.create_dataset("command", data=[" ".join(shlex.quote(a) for a in table[k][3]) for k in keys], dtype=str_t)
        for col in ("acor", "acor_ref", "acor_error", "contacts", "contact_time", "contact_time_ref", "peak_force",
                    "peak_force_ref", "max_compression", "max_compression_ref", "energy_error", "steps", "rejected_steps",
                    "failed_solves", "wall_time", "dt_nominal", "dt_stable", "elapsed", "rigid_acor",
                    "linear_momentum_error", "angular_momentum_error", "roll_momentum_error"):
            d = g.create_dataset(col, data=np.array([table[k][2].get(col, np.nan) for k in keys], dtype=float))
            d.attrs["note"] = "NaN: not applicable or no result"
        r = f.create_group("references")
        r.create_dataset("case", data=[c.id for c in all_cases], dtype=str_t)
        r.create_dataset("method", data=[refs[c.id]["method"] or "none" for c in all_cases], dtype=str_t)
        r.create_dataset("note", data=[refs[c.id]["note"] for c in all_cases], dtype=str_t)
        r.create_dataset("command", data=[" ".join(shlex.quote(a) for a in refs[c.id].get("cmd") or []) for c in all_cases], dtype=str_t)
        for col in ("acor", "contacts", "contact_time", "peak_force", "max_compression", "energy_error"):
            r.create_dataset(col, data=np.array([refs[c.id]["res"][col] if refs[c.id]["res"] else np.nan for c in all_cases]))
    os.replace(tmp, path)


def find_exe(given):
    if given:
        return os.path.abspath(given)
    for c in [os.path.join(ROOT, "build", "release", "beamimpact")] + sorted(
            os.path.join(ROOT, "build", d, "beamimpact") for d in (os.listdir(os.path.join(ROOT, "build")) if os.path.isdir(os.path.join(ROOT, "build")) else [])):
        if os.access(c, os.X_OK):
            return c
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", help="beamimpact executable (default: build/release/beamimpact, else build/*/beamimpact)")
    ap.add_argument("--jobs", type=int, default=2, help="cells run at once (default 2)")
    ap.add_argument("--h5", default="out/stability.h5", help="HDF5 file of all cells (default out/stability.h5)")
    ap.add_argument("--md", default="docs/stability.md", help="Markdown report (default docs/stability.md; 'none': no report)")
    ap.add_argument("--workdir", help="scratch directory for the per-cell files (default: a temporary one)")
    ap.add_argument("--cases", help="comma-separated case ids (default: all)")
    ap.add_argument("--integrators", help="comma-separated integrator ids (default: all)")
    ap.add_argument("--mpiexec", default=shutil.which("mpiexec") or "mpiexec", help="launcher for the 2-rank case")
    ap.add_argument("--list", action="store_true", help="list the cases and integrators and exit")
    ap.add_argument("--quiet", action="store_true", help="no line per cell")
    a = ap.parse_args()

    all_cases, integ = cases(), list(INTEGRATORS)
    if a.list:
        for c in all_cases:
            print("%-18s %s" % (c.id, c.title))
        for i in integ:
            print("%-18s %s: %s" % (i[0], i[1], i[2]))
        return 0
    if a.cases:
        want = a.cases.split(",")
        unknown = [w for w in want if w not in {c.id for c in all_cases}]
        if unknown:
            sys.stderr.write("stability_matrix.py: unknown case(s) %s; --list shows them\n" % ", ".join(unknown))
            return 2
        all_cases = [c for c in all_cases if c.id in want]
    if a.integrators:
        want = a.integrators.split(",")
        unknown = [w for w in want if w not in {i[0] for i in integ}]
        if unknown:
            sys.stderr.write("stability_matrix.py: unknown integrator(s) %s; --list shows them\n" % ", ".join(unknown))
            return 2
        integ = [i for i in integ if i[0] in want]
    exe = find_exe(a.exe)
    if not exe or not os.access(exe, os.X_OK):
        sys.stderr.write("stability_matrix.py: no beamimpact executable (%s); build it (cmake --preset release && "
                         "cmake --build --preset release) or pass --exe\n" % (a.exe or "looked in build/"))
        return 2
    if any(c.ranks > 1 for c in all_cases) and not shutil.which(a.mpiexec):
        sys.stderr.write("stability_matrix.py: %s not found (needed by the 2-rank case); pass --mpiexec\n" % a.mpiexec)
        return 2
    workdir = a.workdir or tempfile.mkdtemp(prefix="beamimpact-stability-")
    os.makedirs(workdir, exist_ok=True)
    study = Study(exe, workdir, a.jobs, a.mpiexec)
    t0 = time.time()

    # Longest first (the stiff grids and the long windows), so the pool finishes together.
    def cost(c):
        return (float(c.nodes()) ** 2) * (1 + 50 * float(c.params.get("-impact_window", 0.08))) * c.ranks

    table, refs = {}, {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        # The program's scales of every case first (they set the steps): a program that does not
        # record them stops the study here, before any cell.
        try:
            for f in [pool.submit(study.probe_scales, c) for c in all_cases]:
                f.result()
        except (derived.Missing, RuntimeError) as err:
            pool.shutdown(wait=False, cancel_futures=True)
            sys.stderr.write("stability_matrix.py: %s\n" % err)
            return 2
        ref_f = {pool.submit(study.reference, c): c for c in sorted(all_cases, key=cost, reverse=True)}
        cell_f = {}
        for c in sorted(all_cases, key=cost, reverse=True):
            for i in integ:
                cell_f[pool.submit(study.cell, c, i)] = (c, i)
        for f in concurrent.futures.as_completed(ref_f):
            refs[ref_f[f].id] = f.result()
        for f in concurrent.futures.as_completed(cell_f):
            c, i = cell_f[f]
            cell = f.result()
            try:
                status, reason, m = classify(c, cell, refs[c.id])
            except derived.Missing as err:  # a check's quantity the program does not record
                pool.shutdown(wait=False, cancel_futures=True)
                sys.stderr.write("stability_matrix.py: %s\n" % err)
                return 2
            if cell.get("run"):
                m["elapsed"] = cell["run"]["elapsed"]
            table[(c.id, i[0])] = (status, reason, m, cell["cmd"])
            if not a.quiet:
                print("%-18s %-8s %-12s %6.1fs  %s" % (c.id, i[0], status, m.get("elapsed", 0), reason[:160]), flush=True)
    elapsed = time.time() - t0
    counts = {k: 0 for k in ("correct", "clear error", "wrong", "unverified")}
    for v in table.values():
        counts[v[0]] += 1
    h5 = os.path.join(ROOT, a.h5) if not os.path.isabs(a.h5) else a.h5
    os.makedirs(os.path.dirname(h5), exist_ok=True)
    write_h5(h5, table, refs, all_cases, integ, counts, elapsed, exe)
    if a.md != "none":
        md = os.path.join(ROOT, a.md) if not os.path.isabs(a.md) else a.md
        os.makedirs(os.path.dirname(md), exist_ok=True)
        write_markdown(md, a, table, refs, integ, all_cases, counts, elapsed, exe)
    print("stability: %d cells: %d correct, %d clear error, %d wrong, %d unverified (%.0f s); wrote %s%s"
          % (len(table), counts["correct"], counts["clear error"], counts["wrong"], counts["unverified"], elapsed, h5,
             "" if a.md == "none" else " and " + a.md))
    if not a.workdir:
        shutil.rmtree(workdir, ignore_errors=True)
    return 0 if counts["wrong"] == 0 and counts["unverified"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
