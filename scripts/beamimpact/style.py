"""matplotlib for the scripts: the Agg backend (files, no display), the colour cycle, and one
way to write a figure.

    fig, ax = style.plt.subplots()
    style.check_image_output("out.png")             # exits 1 if it is an input or no image format
    style.save(fig, "out.png", dpi=130)             # tight layout, written, closed; returns the path
"""
import os
import sys

from .interpreter import require

require("matplotlib")

import matplotlib.pyplot as plt  # noqa: E402,F401  (style.plt: the scripts' pyplot)


def colours():
    """The colours of matplotlib's property cycle, in order."""
    return plt.rcParams["axes.prop_cycle"].by_key()["color"]


def check_image_output(path):
    """Exits 1, before anything is drawn or written, when path (a script's -o) is a file the script
    read (files.check_output: an input overwritten by a picture) or its extension is no image
    format matplotlib writes (-o out.h5). save() checks it again; a script calls it early, once
    its inputs are open, so that a refusal comes before its drawing and its printed summary."""
    from . import files  # the files the script read

    prog = os.path.basename(sys.argv[0]) or "beamimpact"
    files.check_output(prog, path)
    ext = os.path.splitext(path)[1][1:].lower()
    formats = plt.figure().canvas.get_supported_filetypes()
    plt.close("all")
    if ext and ext not in formats:
        sys.exit("%s: -o %s is not allowed: .%s is not an image format (matplotlib writes %s); give -o NAME.png, .pdf or .svg"
                 % (prog, path, ext, ", ".join("." + k for k in sorted(formats))))


def save(fig, path, dpi=120, layout=True, tight_box=False, extra_artists=None):
    """Writes fig to path and closes it: layout tightens the subplots first (fig.tight_layout),
    tight_box crops the image to what is drawn (bbox_inches="tight", with extra_artists such as
    a legend outside the axes). Returns the path. Exits 1, writing nothing, when path is a file
    the script read or no image format (check_image_output)."""
    check_image_output(path)
    if layout:
        fig.tight_layout()
    kw = {}
    if tight_box:
        kw["bbox_inches"] = "tight"
        if extra_artists:
            kw["bbox_extra_artists"] = extra_artists
    fig.savefig(path, dpi=dpi, **kw)
    plt.close(fig)
    return path
