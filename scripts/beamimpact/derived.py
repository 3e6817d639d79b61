"""The program's derived scales of one impact, read from its -task impact file (root attributes
and /results), never recomputed here: one function per quantity. A file that lacks one (written
by a beamimpact that predates it) raises Missing naming the attribute, so that a study stops
with a clear message instead of guessing.

    T_r = derived.contact_time_scale(f)    # s: the contact against the free beam, T_c sqrt(M/(M+m_b))
"""
from .files import attr


class Missing(Exception):
    """A derived quantity the file does not hold."""


def _root(f, name, what):
    v = attr(f, name)
    if v is None:
        raise Missing("%s has no attribute %s (%s): it was written by a beamimpact that does not record it; "
                      "use a build with the results table (issue 20)" % (f.filename, name, what))
    return float(v)


def contact_time_scale(f):
    """T_r (s): the contact time of the ball against the beam's free mass, the program's scale
    for its resolution warnings and default steps (T_c sqrt(M / (M + m_b)))."""
    return _root(f, "contact_time_scale", "s, the contact time against the free beam")


def compression_scale(f):
    """The compression scale (m) of the contact at the incident speed."""
    return _root(f, "compression_scale", "m, the compression scale")


def ball_wall_contact_time(f):
    """The ball's contact time (s) on a rigid wall at the incident speed, from its law."""
    return _root(f, "ball_wall_contact_time", "s, the contact time on a rigid wall")


def ball_wall_cor(f):
    """The ball's coefficient of restitution on a rigid wall at the incident speed (1)."""
    return _root(f, "ball_wall_cor", "the coefficient of restitution on a rigid wall")


def beam_mass(f):
    """The beam's mass (kg), from its section."""
    return _root(f, "beam_mass", "kg, the beam's mass")


def rigid_acor(f):
    """Eq. (11) with f = 0 (1): the ACOR of the beam as a rigid body (/results/rigid_acor; NaN
    where it does not apply: a held, pivoted, gripped or swinging beam)."""
    r = f["results"] if "results" in f else {}
    if "rigid_acor" not in r:
        raise Missing("%s has no /results/rigid_acor (Eq. 11): it was written by a beamimpact that does not record it "
                      "in an impact file; use a build with the results table (issue 20)" % f.filename)
    return float(r["rigid_acor"][0])
