"""A Python that has the modules a script needs.

The first python3 on PATH may be a venv or another build without Debian's python3-numpy,
python3-h5py and python3-matplotlib. require() imports the modules; if one is missing it
re-executes the running script once with Debian's /usr/bin/python3, and failing that exits with
status 2 saying which Debian packages to install. With matplotlib it selects the Agg backend
(files, no display).
"""
import importlib
import os
import sys

DEBIAN_PACKAGE = {"numpy": "python3-numpy", "h5py": "python3-h5py", "matplotlib": "python3-matplotlib"}
SYSTEM_PYTHON = "/usr/bin/python3"
REEXEC_FLAG = "BEAMIMPACT_PYTHON_REEXEC"


def require(*modules):
    """Imports `modules` or re-executes the script (sys.argv[0]) with Debian's python3."""
    script = sys.argv[0] if sys.argv and sys.argv[0] else "beamimpact"
    try:
        for m in modules:
            importlib.import_module(m)
    except ImportError as err:
        if (os.environ.get(REEXEC_FLAG) != "1" and os.path.exists(SYSTEM_PYTHON) and os.path.isfile(script)
                and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON)):
            os.environ[REEXEC_FLAG] = "1"
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, os.path.abspath(script)] + sys.argv[1:])
        sys.stderr.write("%s: needs %s (%s).\nOn Debian/Ubuntu: sudo apt-get install %s\n"
                         % (os.path.basename(script), ", ".join(modules), err,
                            " ".join(DEBIAN_PACKAGE[m] for m in modules)))
        sys.exit(2)
    if "matplotlib" in modules:
        import matplotlib
        matplotlib.use("Agg")
