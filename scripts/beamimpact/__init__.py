"""Reading and drawing beamimpact's HDF5 files: the package every script in scripts/ is a thin
command-line wrapper over.

    interpreter  a Python that has numpy, h5py and matplotlib: Debian's /usr/bin/python3 when the
                 first python3 on PATH lacks them (the calling script is re-executed with it)
    files        open a file, attributes as Python values, datasets as numbers, counts or text,
                 a dataset's unit, a sweep's axes (numeric or text, in order), what an impact
                 file holds and the option that makes the rest
    derived      the program's derived scales of an impact (contact time, compression, wall
                 contact, masses, Eq. (11)), read from its file, never recomputed here
    labels       axis labels with their units from the file, the run's configuration in one line
    checks       what a script is given: two files of the same beam, a swinging bat; counts
                 for argparse (--modes 0 refused naming the option)
    style        matplotlib (Agg, no display) and figure saving (never onto a file the script
                 read, files.check_output; only to an image format)

A script in scripts/ imports it with one line, because Python puts the script's directory on
sys.path:

    from beamimpact import files, labels, style

(each module checks the interpreter for what it needs before importing it). A new plot script is
that line, argparse, the reading of its columns through files.* and the drawing.
"""
