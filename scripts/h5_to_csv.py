#!/usr/bin/env python3
"""A table of a beamimpact HDF5 file as CSV (for a spreadsheet, R, pandas, ...).

    scripts/h5_to_csv.py FILE.h5 [GROUP] [-o out.csv] [--units header|row|none]

GROUP (default results; the leading / is optional) is one of the file's groups:
  results    one row per impact (-task impact: one row) or per sweep point (-task sweep: in the
             order of the points, with case_index, one column per sweep axis, status and the
             error text reason of a failed point; its numbers are nan);
  events     one row per located event (kind 0 contact, 1 maximum compression, 2 reload,
             3 separation);
  series     one row per recorded step (-monitor_*); velocity_at [point][step] gives one column
             per point, velocity_at[x=0.3];
  snapshots  one row per node: x and y at each snapshot time, y[t=0.001];
  modes      one row per mode (-task modes): frequency, period, omega and the shape at each
             node, shapes[x=0.0275];
  statistics a sampled sweep's statistics (docs/uncertainty.md): one row per results column (and
             per point of its grid axes): count, mean, std, sem, q05, q50, q95 and the
             quantiles' standard errors, in the column's unit;
  exceedance one row per -sweep_exceedance condition (and grid point): probability, its
             Wilson 95 % interval, count and n;
  sobol      one row per results column and sampled input (and grid point): first, its
             interval first_low, first_high, total, total_low, total_high;
  or any other group (beam, sweep, spatial, configs/rk4, ...), or one dataset (modes/nodes_1:
  its values; a 2-D dataset: one row per first index).
Datasets of another length than the table's rows are left out, with a note on stderr.

The header row names each column with its unit from the dataset's unit attribute,
`contact_time (s)` (--units row: the units in a second row; none: names only). Numbers are
written exactly (the shortest text that reads back as the same double); counts as integers
(integer datasets; a sweep's counts, float64 for its failed rows' NaN, carry the attribute
integer = 1; a sweep axis with whole values); NaN as nan. Written to stdout unless -o is given. Examples, from the repository root:

    mkdir -p out
    build/release/beamimpact -options_file options/scenes/animation.opts -output out/animation.h5
    scripts/h5_to_csv.py out/animation.h5                           # its /results row, to stdout
    scripts/h5_to_csv.py out/animation.h5 events                    # the events of the impact
    scripts/h5_to_csv.py out/animation.h5 series -o out/series.csv  # the time series
    build/release/beamimpact -options_file options/default.opts -output out/default.h5    # the default sweep
    scripts/h5_to_csv.py out/default.h5 -o out/default.csv                            # its 111 rows
"""
import argparse
import csv
import re
import sys

from beamimpact import files

import h5py
import numpy as np

PROG = "h5_to_csv.py"
# The dataset that sets a group's rows, and the columns that come first.
ROW_KEY = {"series": "time", "events": "time", "snapshots": "x", "modes": "frequency", "beam": "x"}
FIRST = ["case_index", "time", "kind", "x", "frequency", "period", "omega"]
# /results in the program's order: the file's own list (results_columns of an impact file, from the
# results table src/run/results_table.cpp; sweep_columns of a sweep), else (older impact files) this one
RESULTS = ("x acor acor_corrected contact_time contact_time_total peak_force max_compression contacts ended_in_contact "
           "compression_beyond_radius ball_final_velocity final_time energy_error linear_momentum_error angular_momentum_error "
           "beam_kinetic_end beam_strain_end ball_dissipated_end ball_loss_fraction translation_fraction rotation_fraction "
           "vibration_fraction bbs collision_efficiency bat_speed_end bat_angular_velocity_end recoil_factor bbcor "
           "grip_force_peak grip_force_peak_time grip_stored_end hand_work_end segment_kinetic_peak segment_kinetic_peak_time "
           "failed_solves steps rejected_steps event_steps function_evals jacobian_evals jacobian_assemblies nonlinear_its "
           "linear_its wall_time dt_nominal dt_stable beam_dissipated_end damping_fraction").split()
# 2-D datasets: which index is the row, and the 1-D dataset naming the other index.
LAYOUT = {"velocity_at": ("columns_first", "velocity_at_x", "x"), "y": ("columns_first", "time", "t"),
          "shapes": ("rows_first", "/beam/x", "x")}


def fmt_float(v):
    v = float(v)
    if np.isnan(v):
        return "nan"
    return repr(v)  # shortest round-trip text; inf, -inf as such


def is_count(name, values, axes, tagged=False):
    """A column of whole numbers: an integer dataset, a float64 one the program tagged
    (attribute integer = 1: a sweep's counts, NaN in failed rows), or a sweep axis whose values
    are all whole (beam_nodes)."""
    if values.dtype.kind in "iu":
        return True
    if values.dtype.kind != "f" or not (tagged or name in axes):
        return False
    v = values[np.isfinite(values)]
    return bool(np.all(v == np.round(v)) and np.all(np.abs(v) < 2 ** 53))


def column(name, unit_text, values, axes, tagged=False):
    """(header, unit, list of cells)."""
    values = np.asarray(values)
    if values.dtype.kind in "OSU":
        cells = [v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v) for v in values]
    elif is_count(name, values, axes, tagged):
        cells = ["nan" if not np.isfinite(v) else str(int(v)) for v in values.astype(float)] if values.dtype.kind == "f" \
            else [str(int(v)) for v in values]
    elif values.dtype.kind == "b":
        cells = [str(int(v)) for v in values]
    else:
        cells = [fmt_float(v) for v in values]
    return name, unit_text, cells


def short_unit(name, u):
    """The unit without its explanation ('1, wall COR used ...' -> '1'); an event kind keeps its legend."""
    if name == "kind":
        return u
    return re.split(r" \(|, ", u, maxsplit=1)[0]


def labels_for(f, g, source, n):
    if source.startswith("/"):
        ds = f[source] if source in f else None
    else:
        ds = g[source] if source in g else None
    if ds is not None and ds.ndim == 1 and ds.shape[0] == n:
        return ["%.6g" % v for v in ds[()]]
    return None


def table_of_group(f, g, gname):
    names = list(g.keys())
    data = {k: g[k] for k in names if isinstance(g[k], h5py.Dataset)}
    if not data:
        sys.stderr.write("%s: /%s holds no datasets (groups in it: %s)\n" % (PROG, gname, ", ".join(names) or "none"))
        sys.exit(1)
    base = gname.split("/")[-1]
    one_d = {k: d for k, d in data.items() if d.ndim == 1}
    key = ROW_KEY.get(base)
    if key in one_d:
        n = one_d[key].shape[0]
    elif one_d:
        lengths = [d.shape[0] for d in one_d.values()]
        n = max(set(lengths), key=lambda L: (lengths.count(L), L))
    else:
        n = next(iter(data.values())).shape[0]
    axes = [a for a in str(files.attr(f, "sweep_axes", "") or "").split(",") if a]
    # column order: a sweep's own order, else the usual first columns, then by name
    listed = files.attr(f, "sweep_columns", "") or files.attr(f, "results_columns", "") or ""
    order = [c for c in str(listed).split(",") if c] if base == "results" else []
    if base == "results" and not order:
        order = list(RESULTS)
    if "status" in order and "reason" in data:
        order.insert(order.index("status") + 1, "reason")
    order += [c for c in FIRST if c not in order]
    ranked = [c for c in order if c in data] + sorted(c for c in data if c not in order)
    cols, left_out = [], []
    used_as_labels = {LAYOUT[k][1] for k in data if k in LAYOUT and data[k].ndim == 2}
    for name in ranked:
        d = data[name]
        u = short_unit(name, files.unit(d))
        if d.ndim == 1 and d.shape[0] == n:
            cols.append(column(name, u, d[()], axes, int(d.attrs.get("integer", 0)) == 1))
        elif d.ndim == 2 and n in d.shape:
            lay = LAYOUT.get(name)
            rows_first = d.shape[0] == n if lay is None else (lay[0] == "rows_first" and d.shape[0] == n) or d.shape[1] != n
            v = d[()] if rows_first else d[()].T  # [row][k]
            k = v.shape[1]
            labs = labels_for(f, g, lay[1], k) if lay else None
            tag = lay[2] if lay else ""
            for j in range(k):
                head = "%s[%s=%s]" % (name, tag, labs[j]) if labs else "%s[%d]" % (name, j)
                cols.append(column(head, u, v[:, j], axes))
        else:
            if name not in used_as_labels:
                left_out.append("%s %s" % (name, "x".join(map(str, d.shape)) or "scalar"))
    if left_out:
        sys.stderr.write("%s: /%s: %d rows; not columns of this table (another length): %s; export one with "
                         "scripts/h5_to_csv.py FILE %s/NAME\n" % (PROG, gname, n, ", ".join(left_out), gname))
    return cols


def text_of(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def cell(d, p):
    """Value p of a 1-D dataset: a count (attribute integer = 1) as a whole number."""
    v = d[p]
    return str(int(v)) if int(d.attrs.get("integer", 0)) == 1 and np.isfinite(v) else fmt_float(v)


def uq_table(f, path):
    """/statistics, /exceedance or /sobol as one long table: a row per column (condition), grid
    point (and input: /sobol), the grid axes' values from /statistics."""
    st = f["statistics"] if "statistics" in f else None
    grid = [k for k, d in st.items() if isinstance(d, h5py.Dataset) and k not in ("points", "failed")] if st else []
    g = f[path]
    inputs = [text_of(x) for x in g.attrs.get("inputs", st.attrs.get("inputs", []) if st else [])]
    rows = []
    for name, sub in g.items():
        if not isinstance(sub, h5py.Group):
            continue
        fields = [k for k in sub.keys() if k not in ("first_ci", "total_ci")]
        n = sub[fields[0]].shape[0]
        for p in range(n):
            head = [("column" if path != "exceedance" else "condition", "", name)]
            head += [(k, files.unit(st[k]), text_of(st[k][p]) if st[k].dtype.kind in "OS" else fmt_float(st[k][p])) for k in grid]
            if path == "sobol":
                for i, inp in enumerate(inputs):
                    row = head + [("input", "", inp)]
                    for k in ("first", "total"):
                        ci = sub[k + "_ci"][p, i]
                        row += [(k, "1", fmt_float(sub[k][p, i])), (k + "_low", "1", fmt_float(ci[0])), (k + "_high", "1", fmt_float(ci[1]))]
                    row += [("groups", "1", cell(sub["groups"], p))]
                    rows.append(row)
            else:
                unit = files.unit(sub["mean"]) if "mean" in sub else "1"
                rows.append(head + [("unit", "", short_unit("", unit))] + [(k, short_unit(k, files.unit(sub[k])), cell(sub[k], p)) for k in fields])
    if not rows:
        return []
    heads = [(h[0], h[1]) for h in rows[0]]
    return [(h, short_unit(h, u), [r[j][2] for r in rows]) for j, (h, u) in enumerate(heads)]


def table_of_dataset(d, path):
    u = files.unit(d)
    if d.ndim == 0:
        return [column(path.split("/")[-1], u, np.atleast_1d(d[()]), [])]
    if d.ndim == 1:
        return [column(path.split("/")[-1], u, d[()], [])]
    if d.ndim == 2:
        v = d[()]
        return [column("%s[%d]" % (path.split("/")[-1], j), u.split(", [")[0], v[:, j], []) for j in range(v.shape[1])]
    sys.stderr.write("%s: %s has %d dimensions; only 1-D and 2-D datasets make a table\n" % (PROG, path, d.ndim))
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0],
                                 epilog=__doc__.split("\n\n", 2)[2], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file", help="HDF5 file written by beamimpact")
    ap.add_argument("group", nargs="?", default="results", help="group or dataset (default results)")
    ap.add_argument("-o", "--output", help="CSV file to write (default: stdout)")
    ap.add_argument("--units", choices=("header", "row", "none"), default="header",
                    help="units in the header 'name (unit)' (default), in a second row, or not at all")
    a = ap.parse_args()
    path = a.group.strip("/") or "results"
    with files.open_file(PROG, a.file) as f:
        if path not in f:
            groups = []
            f.visit(lambda n: groups.append(n) if isinstance(f[n], h5py.Group) else None)
            sys.stderr.write("%s: %s has no /%s; its groups: %s\n" % (PROG, a.file, path, ", ".join(groups) or "none"))
            if path == "series":
                sys.stderr.write("  (/series is written only with -monitor_ball, -monitor_energy, -monitor_velocity_at, ...)\n")
            elif path == "snapshots":
                sys.stderr.write("  (/snapshots is written only with -snapshot_times t1,t2,...)\n")
            return 1
        obj = f[path]
        if path in ("statistics", "exceedance", "sobol"):
            cols = uq_table(f, path)
        else:
            cols = table_of_group(f, obj, path) if isinstance(obj, h5py.Group) else table_of_dataset(obj, path)
    heads = [("%s (%s)" % (c[0], c[1]) if c[1] and a.units == "header" else c[0]) for c in cols]
    files.check_output(PROG, a.output, ".csv")  # not onto the file it reads
    out = open(a.output, "w", newline="") if a.output else sys.stdout
    try:
        w = csv.writer(out, lineterminator="\n")
        w.writerow(heads)
        if a.units == "row":
            w.writerow([c[1] for c in cols])
        for row in zip(*[c[2] for c in cols]):
            w.writerow(row)
    finally:
        if a.output:
            out.close()
    if a.output:
        sys.stderr.write("wrote %s: %d rows, %d columns\n" % (a.output, len(cols[0][2]) if cols else 0, len(cols)))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except BrokenPipeError:  # | head
        sys.exit(0)
