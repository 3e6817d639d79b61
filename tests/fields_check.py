#!/usr/bin/env python3
"""Checks of the fields for ParaView and xarray (tests/fields.sh): the XDMF descriptions against
the HDF5 files they point to, and every group of the results files through xarray + h5netcdf.

    fields_check.py CHECK...   each CHECK one argument, its words separated by spaces:
      "xdmf FILE.xmf FILE.h5 FIELD..."  each collection named, every DataItem against the file
      "xarray FILE.h5 KIND [ARG...]"    every group opened with named dimensions and units;
                                        KIND impact|sweep|flight|modes|other: its coordinates
      "wall FILE.h5 X"                  the wall's W_n under the ball (x = X) against
                                        /results/wall_deflection_peak
(one Python for all: importing xarray takes seconds)

Prints one line per check ("ok: ..." or "FAIL: ..."); exits 1 on a failure, 77 when a package it
needs (h5py, numpy, xarray, h5netcdf) is missing (a skip CTest counts).
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
    import xarray as xr
    import h5netcdf  # noqa: F401  (xarray's engine)
except ImportError as e:
    print("SKIP: %s (Debian: apt-get install python3-h5py python3-numpy python3-xarray python3-h5netcdf)" % e)
    sys.exit(77)

fails = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what)
    if not ok:
        fails.append(what)


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


# ---------------------------------------------------------------------------------------------
# XDMF
# ---------------------------------------------------------------------------------------------
def hdf_item(item, xmf_dir, h5name, f):
    """An HDF DataItem against the file: its relative name, path, dimensions and type. Returns the
    dataset and the part read (start, stride, count: Xdmf 3's "path|start:stride:count:dataspace";
    the whole dataset without one), or None."""
    ref = item.text.strip()
    name, _, path = ref.partition(":")
    path, _, part = path.partition("|")
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    where = "DataItem %s" % ref
    if name != h5name or not os.path.exists(os.path.join(xmf_dir, name)):
        check(False, "%s: names %s, not %s beside the .xmf" % (where, name, h5name))
        return None
    if path not in f:
        check(False, "%s: no such dataset" % where)
        return None
    ds = f[path]
    kind = {("Float", "8"): "f8", ("Float", "4"): "f4", ("Int", "8"): "i8", ("Int", "4"): "i4"}.get(
        (item.get("NumberType", "Float"), item.get("Precision", "4")))
    if part:
        start, stride, count, space = ([int(v) for v in p.split()] for p in part.split(":"))
    else:
        start, stride, count, space = [0] * ds.ndim, [1] * ds.ndim, list(ds.shape), list(ds.shape)
    ok = tuple(space) == ds.shape and len(start) == len(stride) == len(count) == ds.ndim and all(
        0 <= a and a + (c - 1) * t < n for a, t, c, n in zip(start, stride, count, ds.shape))
    if not ok or ds.dtype.str[1:] != kind or np.prod(count) != np.prod(dims):
        check(False, "%s: declared %s %s, part %s, the file has %s %s" % (where, dims, kind, part, ds.shape, ds.dtype))
        return None
    return ds, start, stride, count


def xml_values(item):
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    return np.array([float(v) for v in item.text.split()]).reshape(dims)


def check_grid(grid, k, time, xmf_dir, h5name, f):
    """One grid of a temporal collection: its time, geometry, and the values of snapshot k."""
    name = grid.get("Name")
    bad = []
    t = float(grid.find("Time").get("Value"))
    if t != time[k]:
        bad.append("Time %r is not /snapshots/time[%d] = %r" % (t, k, time[k]))
    topo = grid.find("Topology")
    ny, nx = (int(d) for d in topo.get("Dimensions").split())
    if topo.get("TopologyType") != "2DRectMesh":
        bad.append("topology %s" % topo.get("TopologyType"))
    geo = grid.find("Geometry")
    axes = geo.findall("DataItem")
    if geo.get("GeometryType") != "VXVY" or len(axes) != 2:
        bad.append("geometry %s with %d items" % (geo.get("GeometryType"), len(axes)))
    else:
        for item, n in zip(axes, (nx, ny)):
            read = hdf_item(item, xmf_dir, h5name, f) if item.get("Format") == "HDF" else (xml_values(item),)
            if read is None or read[0].shape != (n,):
                bad.append("axis %s: not %d values" % (item.text.strip(), n))
    attr = grid.find("Attribute")
    items = attr.findall("DataItem")
    read = hdf_item(items[0], xmf_dir, h5name, f) if len(items) == 1 and items[0].get("Format") == "HDF" else None
    if read is None:
        bad.append("no HDF5 values for attribute %s" % attr.get("Name"))
    else:
        ds, start, stride, count = read
        if list(start) != [k] + [0] * (ds.ndim - 1) or list(stride) != [1] * ds.ndim or tuple(count) != (1,) + ds.shape[1:]:
            bad.append("reads start %s stride %s count %s: not row %d of %s" % (start, stride, count, k, ds.shape))
        if np.prod(count) != nx * ny:
            bad.append("%d values read for %d nodes" % (np.prod(count), nx * ny))
    if attr.get("Center") != "Node":
        bad.append("attribute centred on %s" % attr.get("Center"))
    for b in bad:
        check(False, "%s: %s" % (name, b))
    return not bad


def cmd_xdmf(xmf, h5, fields):
    xmf_dir, h5name = os.path.dirname(xmf) or ".", os.path.basename(h5)
    root = ET.parse(xmf).getroot()
    check(root.tag == "Xdmf" and root.get("Version") == "3.0", "%s: an XDMF 3 document" % xmf)
    with h5py.File(h5, "r") as f:
        time = f["snapshots/time"][()]
        colls = root.find("Domain").findall("Grid")
        check([c.get("Name") for c in colls] == fields, "%s: collections %s (want %s)" % (
            os.path.basename(xmf), [c.get("Name") for c in colls], fields))
        for c in colls:
            grids = c.findall("Grid")
            temporal = c.get("GridType") == "Collection" and c.get("CollectionType") == "Temporal"
            check(temporal and len(grids) == len(time), "%s: a temporal collection of %d grids, one per snapshot time"
                  % (c.get("Name"), len(time)))
            good = all([check_grid(g, k, time, xmf_dir, h5name, f) for k, g in enumerate(grids)])
            if good:
                print("ok:   %s: every grid's time is /snapshots/time's, every DataItem names a dataset of %s with its "
                      "dimensions and type, each grid's values are its snapshot's row" % (c.get("Name"), h5name))


# ---------------------------------------------------------------------------------------------
# xarray
# ---------------------------------------------------------------------------------------------
def groups_with_data(f):
    out = []
    f.visit(lambda n: out.append(n) if isinstance(f[n], h5py.Group) and any(
        isinstance(v, h5py.Dataset) for v in f[n].values()) else None)
    return out


def open_all(path):
    """Every group with datasets opened by xarray (no phony dimensions): {group: Dataset}."""
    opened = {}
    with h5py.File(path, "r") as f:
        groups = groups_with_data(f)
    for g in groups:
        try:
            ds = xr.open_dataset(path, group=g, engine="h5netcdf")
        except Exception as e:  # a dataset without dimensions, or sizes that disagree
            check(False, "%s: /%s does not open in xarray: %s" % (path, g, e))
            continue
        nounit = [v for v in ds.variables if ds[v].dtype.kind not in "OSU" and not ds[v].attrs.get("units")]
        check(not nounit, "%s /%s: dims %s, coordinates %s; units on every numeric variable%s" % (
            os.path.basename(path), g, dict(ds.sizes), list(ds.coords), (": missing on %s" % nounit) if nounit else ""))
        opened[g] = ds
    return opened


def expect(ds, var, dims=None, units=None, values=None, what=""):
    if var not in ds.variables:
        check(False, "%s: no variable %s" % (what, var))
        return
    v = ds[var]
    ok = (dims is None or v.dims == tuple(dims)) and (units is None or v.attrs.get("units") == units)
    if values is not None:
        ok = ok and v.shape == np.shape(values) and np.allclose(v.values, values, rtol=1e-14, atol=0)
    check(ok, "%s: %s dims %s units %r%s" % (what, var, v.dims, v.attrs.get("units"),
                                             "" if values is None else " values as expected"))


def cmd_xarray(path, kind, args):
    ds = open_all(path)
    w = os.path.basename(path)
    with h5py.File(path, "r") as f:
        attrs = {k: f.attrs[k] for k in f.attrs}
        # the dimensions without values: at the root, marked as netCDF-4 marks them, never a variable
        root_dims = [k for k, v in f.items() if isinstance(v, h5py.Dataset)]
        marked = all(b"This is a netCDF dimension but not a netCDF variable" in f[k].attrs.get("NAME", b"")
                     for k in root_dims)
        check(marked, "%s: the dimensions without values %s are netCDF's (NAME marker)" % (w, root_dims))
    top = xr.open_dataset(path, engine="h5netcdf")
    check(not top.data_vars and text(top.attrs.get("program", "")).startswith("beamimpact"),
          "%s /: no variables, the run record as attributes" % w)
    if kind == "impact":
        N, L = int(attrs["beam_nodes"]), float(attrs["beam_length"])
        times = [float(t) for t in args[0].split(",")]
        expect(ds["results"], "contact_time", ("impact",), "s", what=w + " /results")
        expect(ds["results"], "peak_force", ("impact",), "N", what=w + " /results")
        expect(ds["events"], "kind", ("event",), "1", what=w + " /events")
        expect(ds["series"], "time", ("time",), "s", what=w + " /series")
        expect(ds["series"], "force", ("time",), "N", what=w + " /series")
        expect(ds["series"], "velocity_at", ("velocity_at_x", "time"), "m/s", what=w + " /series")
        expect(ds["series"], "velocity_at_x", ("velocity_at_x",), "m", [float(x) for x in args[1].split(",")],
               what=w + " /series")
        expect(ds["snapshots"], "time", ("time",), "s", times, what=w + " /snapshots")
        expect(ds["snapshots"], "x", ("x",), "m", np.linspace(0, L, N), what=w + " /snapshots")
        expect(ds["snapshots"], "y", ("time", "x"), "m", what=w + " /snapshots")
        sel = ds["snapshots"].y.sel(time=times[-1], x=L).item()  # by coordinate: the free end at the last time
        check(sel == ds["snapshots"].y.values[-1, -1], "%s: y.sel(time=%g, x=%g) is the last row's last node" % (
            w, times[-1], L))
    elif kind == "sweep":
        n = len(ds["sweep"]["impact_x"])
        expect(ds["results"], "case_index", ("case_index",), "1", np.arange(n), what=w + " /results")
        expect(ds["results"], "acor", ("case_index",), "1", what=w + " /results")
        expect(ds["results"], "impact_x", ("case_index",), "m", what=w + " /results")
        expect(ds["sweep"], "impact_x", ("case",), "m", [float(x) for x in args[0].split(",")], what=w + " /sweep")
    elif kind == "flight":
        dt = float(attrs["flight_series_dt"])
        t = ds["series"].time.values
        check(np.allclose(t[:-1], dt * np.arange(len(t) - 1), rtol=0, atol=1e-12) and t[-1] - t[-2] <= dt,
              "%s /series: time every flight_series_dt = %g s to the landing" % (w, dt))
        expect(ds["series"], "z", ("time",), "m", what=w + " /series")
        expect(ds["series"], "vx", ("time",), "m/s", what=w + " /series")
        expect(ds["results"], "distance", ("flight",), "m", what=w + " /results")
        expect(ds["results"], "landing_angle", ("flight",), "deg", what=w + " /results")
    elif kind == "modes":
        N, L = int(attrs["beam_nodes"]), float(attrs["beam_length"])
        expect(ds["beam"], "x", ("x",), "m", np.linspace(0, L, N), what=w + " /beam")
        expect(ds["beam"], "EI", ("x",), "N m^2", what=w + " /beam")
        expect(ds["modes"], "frequency", ("mode",), "Hz", what=w + " /modes")
        expect(ds["modes"], "shapes", ("mode", "node"), "1", what=w + " /modes")


def cmd_wall(path, x_c):
    with h5py.File(path, "r") as f:
        s = f["snapshots"]
        W, x, n = s["wall"][()], s["x"][()], s["wall_n"][()]
        peak = float(f["results/wall_deflection_peak"][0])
    j = int(np.argmin(np.abs(x - x_c)))
    check(abs(x[j] - x_c) < 1e-12 and W.shape[1:] == (len(n), len(x)),
          "/snapshots/wall [time][wall_n][x] = %s, the ball at node %d" % (W.shape, j))
    check(np.all(W[0] == 0), "the wall at rest at t = 0: W_n = 0 at every node")
    under = np.abs(W[:, :, j].sum(axis=1))  # a point load at a node: the displacement under the ball
    check(under.max() <= peak * (1 + 1e-12) and under.max() >= 0.99 * peak,
          "|sum_n W_n(x_c)| over the snapshots, largest %.6e m, within 1%% below wall_deflection_peak %.6e m "
          "(the measure over every step)" % (under.max(), peak))


if __name__ == "__main__":
    for spec in sys.argv[1:]:  # one check per argument, its words split at spaces
        cmd, *rest = spec.split()
        if cmd == "xdmf":
            cmd_xdmf(rest[0], rest[1], rest[2:])
        elif cmd == "xarray":
            cmd_xarray(rest[0], rest[1], rest[2:])
        elif cmd == "wall":
            cmd_wall(rest[0], float(rest[1]))
        else:
            sys.exit("unknown check %s" % cmd)
    sys.exit(1 if fails else 0)
