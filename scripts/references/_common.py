"""Small helpers shared by the reference scripts of scripts/references/.

Each script runs as `/usr/bin/python3 scripts/references/NAME.py` and needs numpy and scipy
(Debian's python3-numpy, python3-scipy). If the Python that started it lacks them, need()
re-executes the script once with /usr/bin/python3; failing that it exits with status 2 and
names the packages. table() prints a fixed-width table.
"""
import importlib
import os
import sys

SYSTEM_PYTHON = "/usr/bin/python3"
REEXEC_FLAG = "BEAMIMPACT_REFERENCES_REEXEC"
DEBIAN_PACKAGE = {"numpy": "python3-numpy", "scipy": "python3-scipy"}


def need(script, *modules):
    """Import `modules` or re-run `script` under Debian's Python that has them."""
    try:
        for m in modules:
            importlib.import_module(m)
    except ImportError as err:
        if (os.environ.get(REEXEC_FLAG) != "1" and os.path.exists(SYSTEM_PYTHON)
                and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON)):
            os.environ[REEXEC_FLAG] = "1"
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, os.path.abspath(script)] + sys.argv[1:])
        sys.stderr.write("%s: needs %s (%s). On Debian/Ubuntu: apt-get install %s\n"
                         % (os.path.basename(script), ", ".join(modules), err,
                            " ".join(DEBIAN_PACKAGE.get(m, m) for m in modules)))
        sys.exit(2)


def table(title, header, rows, fmt=None):
    """Print rows (lists of values) under a header; fmt is one format per column."""
    if fmt is None:
        fmt = ["%s"] * len(header)
    cells = [[(f % v) if not isinstance(v, str) else v for f, v in zip(fmt, r)] for r in rows]
    width = [max([len(h)] + [len(c[i]) for c in cells]) for i, h in enumerate(header)]
    print()
    print(title)
    print("  ".join(h.rjust(w) for h, w in zip(header, width)))
    print("  ".join("-" * w for w in width))
    for c in cells:
        print("  ".join(s.rjust(w) for s, w in zip(c, width)))


def percent(a, b):
    """Relative difference of a from b, in per cent."""
    return 100.0 * (a - b) / b
