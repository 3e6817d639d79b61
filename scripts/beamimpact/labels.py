"""Words for figures, from the file: axis labels with the units of the file's unit attributes,
and the run's configuration (beam, supports, ball, integrator) in one line.

    labels.axis_label(f["results"], "impact_x")      # 'impact point x (m)'
    labels.config_label(f)                           # 'N = 41, L = 1.1 m, free-free, linear 42 g ball at 1 m/s, ...'
"""
import os

from .files import attr, sweep_axes, unit

NICE = {"impact_x": "impact point x", "x": "impact point x"}


def unit_text(u):
    """The unit as shown after a number or a name: '' for none and for '1' (dimensionless)."""
    return "" if u in ("", "1", None) else u


def axis_label(group, name):
    """'name (unit)' with the unit of dataset group/name (none when it has none or is '1'); the
    impact point is 'impact point x'."""
    u = unit_text(unit(group[name])) if name in group else ""
    nice = NICE.get(name, name)
    return "%s (%s)" % (nice, u) if u else nice


def value_label(name, value, u=""):
    """'ts_type = cn' or 'beam_thickness = 0.006 m' (a legend entry for one value of an axis)."""
    if isinstance(value, str):
        return "%s = %s" % (name, value)
    u = unit_text(u)
    return "%s = %g%s" % (name, value, " " + u if u else "")


def supports(f):
    """'free-free', 'clamped-free, clamped 0-0.2 m'."""
    left, right = attr(f, "beam_left", "?"), attr(f, "beam_right", "?")
    s = "%s-%s" % (left, right)
    x0, x1 = attr(f, "beam_clamp_x0", -1), attr(f, "beam_clamp_x1", -1)
    if x0 is not None and x0 >= 0:
        s += ", clamped %g-%g m" % (x0, x1)
    return s


def config_label(f, impact=True):
    """The configuration as one line: N, L, supports, and for an impact the ball's mass and
    speed, the impact point and the integrator (all read from the file)."""
    from .files import impact_point
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


def sweep_label(f, path):
    """A sweep file's legend: length, supports, thickness, grid and ball, each left out when it
    is an axis (it varies), and 'partial d/n' while the file is being written."""
    axes = [a.name for a in sweep_axes(f)]
    parts = []
    L = attr(f, "beam_length")
    if L is not None:
        parts.append("L = %g m" % L)
    left, right = attr(f, "beam_left"), attr(f, "beam_right")
    if left and right and "beam_left" not in axes and "beam_right" not in axes:
        parts.append("%s-%s" % (left, right))
    x0, x1 = attr(f, "beam_clamp_x0", -1), attr(f, "beam_clamp_x1", -1)
    if x0 is not None and x0 >= 0:
        parts.append("clamped %g-%g m" % (x0, x1))
    a = attr(f, "beam_thickness", 0)
    if a and "beam_thickness" not in axes:
        parts.append("a = %g mm" % (a * 1e3))
    n = attr(f, "beam_nodes")
    if n and "beam_nodes" not in axes:
        parts.append("N = %d" % n)
    law, mb, vb = attr(f, "ball_law"), attr(f, "ball_mass"), attr(f, "ball_speed")
    if law and "ball_law" not in axes:
        ball = law + " ball"
        if mb and vb and "ball_speed" not in axes:
            ball += " %g g at %g m/s" % (mb * 1e3, vb)
        parts.append(ball)
    done, total = attr(f, "sweep_cases_done"), attr(f, "sweep_cases_total")
    if done is not None and total is not None and done < total:
        parts.append("partial %d/%d" % (done, total))
    return ", ".join(parts) if parts else os.path.basename(path)


def scene_title(f):
    """A convergence study's scene: 'N = 161, L = 1.1 m, x = 0.55 m, linear ball'."""
    law = attr(f, "ball_law", "?")
    return "N = %d, L = %g m, x = %g m, %s ball" % (int(attr(f, "beam_nodes", 0)), attr(f, "beam_length", 0), attr(f, "impact_x", 0), law)
