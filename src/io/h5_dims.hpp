// netCDF-4 dimensions and CF units on the results files' datasets (HDF5 dimension scales, hdf5_hl),
// so that netCDF readers and xarray (xarray.open_dataset(file, group=..., engine="h5netcdf")) open
// every group with named dimensions, coordinate values and units, without guessing.
//
// A dimension is either a coordinate, a 1-D dataset of the group made a dimension scale named as
// itself (/series/time, /snapshots/x), or, where no dataset holds the index's values (a table's
// row, a flattened grid), a dimension without values: a dataset at the file's root with netCDF's
// marker NAME ("This is a netCDF dimension but not a netCDF variable."), no data stored, which
// netCDF readers show as a dimension only. Being at the root, it is visible to every group (as
// netCDF's dimensions are) and adds no member to the groups that readers iterate as tables.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// The CF units of a unit text as the datasets' attribute unit holds it: the text up to " (" or
// ", " ("m/s, [point][step]" -> "m/s"); of that, the leading unit symbols when words follow
// ("1 for a rigid mode" -> "1"; "m or m/s" stays as written), and "1" for a list of codes
// ("0 contact, 1 max_compression, ..."). Empty for an empty text.
std::string H5UnitsOf(const std::string &unit);

// Axis k of the dataset loc/name on the dimension dims[k] (one name per axis): the coordinate
// dims[k] when loc holds a dataset of that name (it must be 1-D of the axis's length; it becomes a
// dimension scale), else the dimension without values dims[k] at the file's root (created at its
// first use; the same name with another length is an error). A 1-D dataset on its own name is
// made a coordinate.
PetscErrorCode H5DimsAttach(long long loc, const char *name, const std::vector<std::string> &dims);

// A table: every dataset of loc not yet on a dimension (nor a coordinate) put on dim, which it
// must be 1-D of the length of (H5DimsAttach the other datasets first).
PetscErrorCode H5DimsTable(long long loc, const char *dim);

} // namespace beamimpact
