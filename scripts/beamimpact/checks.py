"""What a plot script is given, checked before it draws: whether two files describe the same
beam (a bat's modes file and a sweep over it), and whether a sweep's bat swings (its ACOR is then
not the ACOR of a bat at rest, and Eq. (11) does not apply). Each check returns the reasons as
text, so that the script refuses with a message naming the files, or marks what it draws.

    why = checks.other_beam(modes_file, sweep_file)   # [] for the same bat
    if checks.swinging(f): ...                          # -bat_speed / -bat_angular_velocity given
    ap.add_argument("--modes", type=checks.count(1, "modes to draw"))   # "--modes 0 is not allowed: ..."
"""
from .files import attr

import argparse
import math

# The beam as the run records it: attribute, what it is, relative tolerance (None: equal text).
# The section's contents (SHA-256 of -beam_profile/-beam_properties) decide where both files
# hold them; the length, mass, centre of mass and inertia otherwise (files of older builds).
_BEAM = (
    ("input_sha256_beam_profile", "the -beam_profile contents (SHA-256)", None),
    ("input_sha256_beam_properties", "the -beam_properties contents (SHA-256)", None),
    ("beam_section", "the kind of section", None),
    ("beam_length", "the length (m)", 1e-9),
    ("beam_mass", "the mass (kg)", 1e-3),
    ("beam_center_of_mass", "the centre of mass (m)", 1e-3),
    ("beam_inertia_cm", "the moment of inertia about the centre of mass (kg m^2)", 1e-3),
)


def other_beam(a, b):
    """The ways in which files a and b (open h5py files) describe different beams; [] when they
    describe the same one. A quantity only one of them records is not compared."""
    why = []
    for name, what, rtol in _BEAM:
        u, v = attr(a, name), attr(b, name)
        if u is None or v is None:
            continue
        if rtol is None:
            if str(u) != str(v):
                why.append("%s differs (%s: %s, %s: %s)" % (what, a.filename, str(u)[:16], b.filename, str(v)[:16]))
        elif not math.isclose(float(u), float(v), rel_tol=rtol, abs_tol=1e-12):
            why.append("%s differs (%s: %.6g, %s: %.6g)" % (what, a.filename, float(u), b.filename, float(v)))
    return why


def _given(f, option):
    """Whether the run set `option` (its /options_used/given flag; else its -option in the
    options string of an older file)."""
    if "options_used" in f and "given" in f["options_used"]:
        g = f["options_used/given"].attrs.get(option)
        if g is not None:
            return bool(int(g))
    return ("-" + option) in (attr(f, "options", "") or "").split()


def swinging(f):
    """Whether the bat of this file swings (-bat_speed or -bat_angular_velocity set to a value
    other than 0, or a sweep axis of either)."""
    axes = str(attr(f, "sweep_axes", "") or "").split(",")
    for option in ("bat_speed", "bat_angular_velocity"):
        if option in axes:
            return True
        if _given(f, option):
            v = f["options_used"].attrs.get(option) if "options_used" in f else None
            if v is None or float(v) != 0:
                return True
    return False


def count(least, what):
    """An argparse type: a whole number >= least; anything else refused by argparse with a message
    naming the option, the value and what is allowed ("argument --modes: 0 is not allowed: the
    number of modes to draw must be at least 1")."""
    def parse(text):
        try:
            n = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError("%r is not a whole number (the number of %s)" % (text, what))
        if n < least:
            raise argparse.ArgumentTypeError("%s is not allowed: the number of %s must be at least %d" % (text, what, least))
        return n
    return parse
