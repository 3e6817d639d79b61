"""Reading a beamimpact HDF5 file: open it, its attributes as Python values, its datasets as
numbers, counts or text with their units, a sweep's axes, and what an impact file holds (with
the option that makes a missing part).

    f = files.open_file(PROG, "out/default.h5")      # exits 1 with a message when unreadable
    files.check_output(PROG, "out/default.png")       # exits 1 when that is a file the script read
    L = files.attr(f, "beam_length")                  # 1.1 (float); strings decoded; None if absent
    x = files.numbers(f["results"], "x")             # float64 array
    axes = files.sweep_axes(f)                        # [Axis(name="ts_type", text=True, ...), ...]
"""
from .interpreter import require

require("numpy", "h5py")

import collections  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

import h5py  # noqa: E402
import numpy as np  # noqa: E402

# What each part of an impact file needs on the beamimpact command line (docs/model.md section 9).
MAKES = {
    "force": "-monitor_ball (the ball's position, velocity, compression and force every step, /series)",
    "ball": "-monitor_ball (the ball's position every step, /series/ball_y)",
    "energy": "-monitor_energy (the energies every step, /series)",
    "snapshots": "-snapshot_times t1,t2,... (the beam's displacement y(x) at those times, /snapshots)",
    "modes": "-task modes (the mode shapes, /modes/shapes)",
    "mode_energies": "-impact_after modal (the default where the beam allows it) and a window after the separation (-impact_window > 0): "
                     "the energy per mode at the end, /modes_energy",
}


def _text(v):
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else v


def attr(obj, name, default=None):
    """Attribute `name` of a file, group or dataset as a Python value: a number, a string
    (decoded), a list for an array of more than one value (strings decoded); default if absent."""
    v = obj.attrs.get(name, default)
    v = _text(v)
    if hasattr(v, "item") and getattr(v, "size", 1) == 1:
        v = _text(v.item())
    elif isinstance(v, np.ndarray):
        v = [_text(x.item() if hasattr(x, "item") else x) for x in v.ravel()]
    return v


def attrs(obj):
    """Every attribute of obj, as attr() reads it."""
    return {k: attr(obj, k) for k in obj.attrs}


def unit(ds):
    """The dataset's unit attribute ('' when none)."""
    return str(attr(ds, "unit", "") or "")


def numbers(group, name):
    """A dataset as a float64 array (counts too; text is not numbers: use text())."""
    return np.asarray(group[name][()], dtype=float)


def is_count(ds):
    """Whether a dataset holds counts: an integer dataset, or a float64 one the program tagged
    (attribute integer = 1: a sweep's counts, NaN in its failed rows)."""
    return ds.dtype.kind in "iu" or (ds.dtype.kind == "f" and int(attr(ds, "integer", 0) or 0) == 1)


def counts(group, name, missing=-1):
    """A count column as integers (a NaN of a failed row as `missing`)."""
    v = group[name][()]
    if v.dtype.kind in "iu":
        return v.astype(int)
    v = np.asarray(v, dtype=float)
    return np.where(np.isfinite(v), v, missing).astype(int)


def is_text(ds):
    return ds.dtype.kind in "OSU"


def text(group, name):
    """A dataset of strings as a list of str."""
    return [_text(v) if isinstance(v, bytes) else str(v) for v in group[name][()]]


# Every file open_file read, as given: no output of the script may be one of them.
_READ = []


def open_file(prog, path):
    """The HDF5 file, read-only; exits 1 naming it when it cannot be read."""
    try:
        f = h5py.File(path, "r")
    except OSError as err:
        sys.stderr.write("%s: cannot read %s: %s\n" % (prog, path, err))
        sys.exit(1)
    _READ.append(path)
    return f


def check_output(prog, path, suffix=".png"):
    """Exits 1 before anything is written when `path`, an output of the script (its -o), is a file
    it read (open_file; the same file by any name): the output would overwrite its own input
    (an HDF5 results file lost for a picture)."""
    if not path or not os.path.exists(path):
        return
    for read in _READ:
        if os.path.exists(read) and os.path.samefile(read, path):
            sys.exit("%s: -o %s is not allowed: it is the input file %s, which the output would overwrite; give another -o (e.g. %s)"
                     % (prog, path, read, os.path.splitext(read)[0] + suffix))


# A sweep axis as the file records it: the option's name (its /results column), whether its
# values are text (categorical), its unit, and its planned values in order (numbers, sorted and
# unique, for a numeric axis; the labels as given for a text axis).
Axis = collections.namedtuple("Axis", "name text unit values")


def sweep_axes(f):
    """The axes of a sweep file in the order of the sweep (attribute sweep_axes); for a -task
    impact file or an old sweep, the one axis 'x' (the impact point)."""
    r = f["results"]
    names = [a for a in str(attr(f, "sweep_axes", "") or "").split(",") if a]
    out = []
    for a in names:
        col = a if a in r else ("x" if a == "impact_x" and "x" in r else a)
        plan = f["sweep"][a] if "sweep" in f and a in f["sweep"] else (r[col] if col in r else None)
        if plan is not None and is_text(plan):
            order = attr(plan, "values")
            order = [order] if isinstance(order, str) else order
            values = list(order) if order else sorted(set(text(f["sweep"] if "sweep" in f and a in f["sweep"] else r, a)))
            out.append(Axis(col, True, "", values))
        else:
            v = np.unique(np.asarray(plan[()], dtype=float)) if plan is not None else np.array([])
            out.append(Axis(col, False, unit(r[col]) if col in r else "", v))
    return out or [Axis("x", False, unit(r["x"]) if "x" in r else "m", np.unique(r["x"][()]) if "x" in r else np.array([]))]


def open_map(prog, path, axes):
    """A sweep over exactly the two AXES (in either order), read-only: the file and its /results;
    exits naming the file and its axes otherwise (a map script given another map's file)."""
    f = open_file(prog, path)
    if "results" not in f:
        sys.exit("%s: %s has no /results" % (prog, path))
    names = [a.name for a in sweep_axes(f)]
    if sorted(names) != sorted(axes):
        sys.exit("%s: %s is not a sweep over %s (its axes: %s)" % (prog, path, " and ".join(axes), ", ".join(names)))
    return f, f["results"]


def status(group, n):
    """/results/status as integers (0 for a file without it)."""
    return counts(group, "status", missing=1) if "status" in group else np.zeros(n, dtype=int)


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


def what_name(what):
    return {"force": "contact force series (/series/force)", "ball": "ball position series (/series/ball_y)",
            "energy": "energy series (/series/total_energy)", "snapshots": "snapshots (/snapshots/y)",
            "modes": "mode shapes (/modes/shapes)", "mode_energies": "energies per mode (/modes_energy)"}[what]


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
    if what == "mode_energies":
        return "modes_energy" in f and "fraction" in f["modes_energy"]
    raise KeyError(what)


def missing(prog, path, what, extra=""):
    """Exit 1 saying which option writes the missing part."""
    sys.stderr.write("%s: %s has no %s: run beamimpact with %s%s\n" % (prog, path, what_name(what), MAKES[what], extra))
    sys.exit(1)


def default_prefix(path):
    return os.path.splitext(path)[0]

