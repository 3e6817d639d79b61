"""Reading a beamimpact HDF5 file for the plotting and export scripts (plot_impact.py,
animate_impact.py, h5_to_csv.py): attributes as Python values, a dataset's unit, the run's
configuration as one legend line, and the option that makes a missing part of the file.

Import it after debian_python.require(__file__, "numpy", "h5py", ...).
"""
import os
import sys

import numpy as np

# What each part of an impact file needs on the beamimpact command line (docs/model.md section 9).
MAKES = {
    "force": "-monitor_ball (the ball's position, velocity, compression and force every step, /series)",
    "ball": "-monitor_ball (the ball's position every step, /series/ball_y)",
    "energy": "-monitor_energy (the energies every step, /series)",
    "snapshots": "-snapshot_times t1,t2,... (the beam's displacement y(x) at those times, /snapshots)",
    "modes": "-task modes (the mode shapes, /modes/shapes)",
}


def attr(obj, name, default=None):
    """A scalar attribute as a Python value (strings decoded), or default."""
    v = obj.attrs.get(name, default)
    if isinstance(v, bytes):
        v = v.decode()
    if hasattr(v, "item") and getattr(v, "size", 1) == 1:
        v = v.item()
        if isinstance(v, bytes):
            v = v.decode()
    return v


def unit(ds):
    """The dataset's unit attribute ('' when none)."""
    u = ds.attrs.get("unit", b"")
    if isinstance(u, bytes):
        u = u.decode()
    return str(u)


def open_file(prog, path):
    import h5py
    try:
        return h5py.File(path, "r")
    except OSError as err:
        sys.stderr.write("%s: cannot read %s: %s\n" % (prog, path, err))
        sys.exit(1)


def impact_point(f):
    """x_imp (m): /results/x of an impact file, else the -impact_x of the options string, else None."""
    if "results" in f and "x" in f["results"] and f["results/x"].shape[0] >= 1:
        return float(f["results/x"][0])
    opts = (attr(f, "options", "") or "").split()
    if "-impact_x" in opts:
        k = opts.index("-impact_x")
        try:
            return float(opts[k + 1])
        except (IndexError, ValueError):
            return None
    return None


def supports(f):
    left, right = attr(f, "beam_left", "?"), attr(f, "beam_right", "?")
    s = "%s-%s" % (left, right)
    x0, x1 = attr(f, "beam_clamp_x0", -1), attr(f, "beam_clamp_x1", -1)
    if x0 is not None and x0 >= 0:
        s += ", clamped %g-%g m" % (x0, x1)
    return s


def config_label(f, impact=True):
    """The configuration as one line: N, L, supports, and for an impact the ball's mass and
    speed, the impact point and the integrator (all read from the file)."""
    parts = []
    n = attr(f, "beam_nodes")
    if n is not None:
        parts.append("N = %d" % int(n))
    L = attr(f, "beam_length")
    if L is not None:
        parts.append("L = %g m" % L)
    parts.append(supports(f))
    th = attr(f, "beam_theory")
    if th and th != "euler":
        parts.append(th)
    if impact:
        mb, vb, law = attr(f, "ball_mass"), attr(f, "ball_speed"), attr(f, "ball_law")
        if mb is not None and vb is not None:
            parts.append("%s%g g ball at %g m/s" % ((law + " ") if law else "", mb * 1e3, vb))
        x = impact_point(f)
        if x is not None:
            parts.append("impact at x = %g m" % x)
        ts = attr(f, "ts_type")
        if ts:
            parts.append("ts_type %s" % ts)
    return ", ".join(parts)


def missing(prog, path, what, extra=""):
    """Exit 1 saying which option writes the missing part."""
    sys.stderr.write("%s: %s has no %s: run beamimpact with %s%s\n" % (prog, path, what_name(what), MAKES[what], extra))
    sys.exit(1)


def what_name(what):
    return {"force": "contact force series (/series/force)", "ball": "ball position series (/series/ball_y)",
            "energy": "energy series (/series/total_energy)", "snapshots": "snapshots (/snapshots/y)",
            "modes": "mode shapes (/modes/shapes)"}[what]


def has(f, what):
    """Whether the file holds what plot_impact.py draws as `what`."""
    s = f["series"] if "series" in f else {}
    if what == "force":
        return "force" in s
    if what == "ball":
        return "ball_y" in s
    if what == "energy":
        return "total_energy" in s
    if what == "snapshots":
        return "snapshots" in f and "y" in f["snapshots"] and f["snapshots/y"].shape[0] > 0
    if what == "modes":
        return "modes" in f and "shapes" in f["modes"]
    raise KeyError(what)


def default_prefix(path):
    return os.path.splitext(path)[0]


def finite_max(v, default=0.0):
    v = np.asarray(v, dtype=float)
    v = v[np.isfinite(v)]
    return float(v.max()) if v.size else default
