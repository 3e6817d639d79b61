// netCDF-4 dimensions and CF units of the results files' datasets. See h5_dims.hpp.
#include "io/h5_dims.hpp"

#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cstdio>
#include <regex>
#include <sstream>

namespace beamimpact {

namespace {

// An HDF5 identifier closed when it goes out of scope (every return path of a PetscCheck).
struct H5Id {
  hid_t id;
  herr_t (*close)(hid_t);
  H5Id(hid_t i, herr_t (*c)(hid_t)) : id(i), close(c) { }
  ~H5Id()
  {
    if (id >= 0) close(id);
  }
  H5Id(const H5Id &)            = delete;
  H5Id &operator=(const H5Id &) = delete;
};

// netCDF-4's marker of a dimension that is not a variable (its NAME attribute starts with it).
const char *const kNotAVariable = "This is a netCDF dimension but not a netCDF variable.";

// The axes' lengths of the dataset ds (empty on failure).
std::vector<hsize_t> Shape(hid_t ds)
{
  H5Id                 space(H5Dget_space(ds), H5Sclose);
  const int            rank = space.id >= 0 ? H5Sget_simple_extent_ndims(space.id) : -1;
  std::vector<hsize_t> dims(rank > 0 ? (size_t)rank : 0);
  if (rank > 0 && H5Sget_simple_extent_dims(space.id, dims.data(), NULL) != rank) dims.clear();
  return dims;
}

// The root's dimension without values dim of length n, created at its first use; *scale open.
PetscErrorCode RootDimension(hid_t loc, const char *of, const std::string &dim, hsize_t n, hid_t *scale)
{
  PetscFunctionBeginUser;
  H5Id file(H5Iget_file_id(loc), H5Fclose);
  PetscCheck(file.id >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot find the file of dimension %s",
             dim.c_str());
  if (H5Lexists(file.id, dim.c_str(), H5P_DEFAULT) > 0) {
    *scale = H5Dopen2(file.id, dim.c_str(), H5P_DEFAULT);
    PetscCheck(*scale >= 0 && H5DSis_scale(*scale) > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "HDF5: /%s is not a dimension",
               dim.c_str());
    const std::vector<hsize_t> shape = Shape(*scale);
    PetscCheck(shape.size() == 1 && shape[0] == n, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "HDF5: the dimension %s has length %llu, not %llu as an axis of %s", dim.c_str(),
               shape.empty() ? 0ULL : (unsigned long long)shape[0], (unsigned long long)n, of);
    PetscFunctionReturn(0);
  }
  H5Id space(H5Screate_simple(1, &n, NULL), H5Sclose);
  *scale = space.id >= 0
           ? H5Dcreate2(file.id, dim.c_str(), H5T_IEEE_F32LE, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)
           : -1; // no data written: none stored
  char name[96];
  std::snprintf(name, sizeof name, "%s%10llu", kNotAVariable, (unsigned long long)n); // as netCDF-4 writes it
  PetscCheck(*scale >= 0 && H5DSset_scale(*scale, name) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "HDF5: cannot create the dimension %s", dim.c_str());
  PetscFunctionReturn(0);
}

// The dimension dim of length n for an axis of the dataset `of` in loc (H5DimsAttach); *scale open.
PetscErrorCode DimensionScale(hid_t loc, const char *of, const std::string &dim, hsize_t n, hid_t *scale)
{
  PetscFunctionBeginUser;
  if (H5Lexists(loc, dim.c_str(), H5P_DEFAULT) <= 0) {
    PetscCall(RootDimension(loc, of, dim, n, scale));
    PetscFunctionReturn(0);
  }
  *scale = H5Dopen2(loc, dim.c_str(), H5P_DEFAULT);
  PetscCheck(*scale >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot open the coordinate %s", dim.c_str());
  const std::vector<hsize_t> shape = Shape(*scale);
  PetscCheck(shape.size() == 1 && shape[0] == n, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "HDF5: the coordinate %s is not 1-D of length %llu as an axis of %s", dim.c_str(), (unsigned long long)n,
             of);
  PetscCheck(H5DSis_scale(*scale) > 0 || H5DSset_scale(*scale, dim.c_str()) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "HDF5: cannot make %s a coordinate", dim.c_str());
  PetscFunctionReturn(0);
}

// Whether the unit text's token is a unit: "1", or SI symbols with powers (m^2, kg^-1/2), m/s.
bool UnitToken(const std::string &t)
{
  static const std::string sym = "(m|s|kg|g|N|J|W|Pa|Hz|rad|deg|K)(\\^-?[0-9]+(/[0-9]+)?)?";
  static const std::regex  unit("1|" + sym + "(/" + sym + ")*");
  return std::regex_match(t, unit);
}

} // namespace

std::string H5UnitsOf(const std::string &unit)
{
  const std::string        s = unit.substr(0, std::min(unit.find(" ("), unit.find(", ")));
  std::istringstream       in(s);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  size_t p = 0;
  while (p < words.size() && UnitToken(words[p])) ++p;
  if (p == words.size() || (p > 0 && words[p] == "or")) return s; // a unit, or several as written
  if (p == 0) return words[0].find_first_not_of("0123456789") == std::string::npos ? "1" : s; // a code list: a number
  std::string lead = words[0];
  for (size_t k = 1; k < p; ++k) lead += " " + words[k];
  return lead; // "1 for a rigid mode ..."
}

PetscErrorCode H5DimsAttach(long long loc_in, const char *name, const std::vector<std::string> &dims)
{
  const hid_t loc = (hid_t)loc_in;
  PetscFunctionBeginUser;
  H5Id ds(H5Dopen2(loc, name, H5P_DEFAULT), H5Dclose);
  PetscCheck(ds.id >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot open dataset %s", name);
  const std::vector<hsize_t> shape = Shape(ds.id);
  PetscCheck(shape.size() == dims.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "HDF5: dataset %s has %zu axes, %zu dimensions given", name, shape.size(), dims.size());
  if (dims.size() == 1 && dims[0] == name) { // a coordinate
    PetscCheck(H5DSis_scale(ds.id) > 0 || H5DSset_scale(ds.id, name) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
               "HDF5: cannot make %s a coordinate", name);
    PetscFunctionReturn(0);
  }
  for (size_t k = 0; k < dims.size(); ++k) {
    hid_t s = -1;
    PetscCall(DimensionScale(loc, name, dims[k], shape[k], &s));
    H5Id scale(s, H5Dclose);
    PetscCheck(H5DSattach_scale(ds.id, scale.id, (unsigned)k) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
               "HDF5: cannot put axis %zu of %s on %s", k, name, dims[k].c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode H5DimsTable(long long loc_in, const char *dim)
{
  const hid_t loc = (hid_t)loc_in;
  H5G_info_t  info;
  PetscFunctionBeginUser;
  PetscCheck(H5Gget_info(loc, &info) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "HDF5: cannot list the group of dimension %s", dim);
  if (H5Lexists(loc, dim, H5P_DEFAULT) > 0) PetscCall(H5DimsAttach(loc, dim, {dim})); // the rows' coordinate first
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    PetscCheck(H5Lget_name_by_idx(loc, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) > 0,
               PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot list the group of dimension %s", dim);
    H5Id obj(H5Oopen(loc, name, H5P_DEFAULT), H5Oclose);
    if (obj.id < 0 || H5Iget_type(obj.id) != H5I_DATASET) continue;
    if (H5DSis_scale(obj.id) > 0 || H5Aexists(obj.id, "DIMENSION_LIST") > 0)
      continue; // a coordinate, or on its dimensions
    PetscCheck(Shape(obj.id).size() == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "HDF5: dataset %s of table %s has no dimensions", name, dim);
    PetscCall(H5DimsAttach(loc, name, {dim}));
  }
  PetscFunctionReturn(0);
}

} // namespace beamimpact
