// The fields for xarray and ParaView, as plain functions: the CF units taken from the datasets'
// unit texts, the netCDF dimensions put on a memory file (read back through HDF5's dimension-scale
// API: names, lengths, the marker of a dimension without values, a length that disagrees refused),
// and the XDMF description's path and text (its times exact, its marker recognised, a foreign
// file not). tests/fields.sh checks the same through the executable, xarray and the XML.
#include "io/h5_dims.hpp"
#include "io/results_h5.hpp"
#include "io/xdmf.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <hdf5_hl.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

using namespace beamimpact;

TEST(H5Units, FromTheUnitTexts)
{
  const std::pair<const char *, const char *> cases[] = {
    {"m", "m"},
    {"m/s, [point][step]", "m/s"},
    {"N m^2", "N m^2"},
    {"kg^-1/2 (deflection, mass-normalised), [z][x]", "kg^-1/2"},
    {"Hz (0 for a rigid mode)", "Hz"},
    {"J, 1/2 (zd^2 + w^2 z^2) in mass-normalised coordinates at the end", "J"},
    {"1 for a rigid mode (a free beam: translation, then rotation), else 0", "1"},
    {"0 contact, 1 max_compression, 2 reload, 3 separation", "1"},
    {"m or m/s (the state's displacements and velocities)", "m or m/s"},
    {"s, minimum of the repeats", "s"},
    {"rpm", "rpm"},
    {"", ""},
  };
  for (const auto &c : cases) EXPECT_EQ(c.second, H5UnitsOf(c.first)) << "unit text: " << c.first;
}

// The name of the dimension scale on axis k of loc/name ("" without one).
static std::string AxisDimension(hid_t loc, const char *name, unsigned k)
{
  const hid_t ds = H5Dopen2(loc, name, H5P_DEFAULT);
  struct Found {
    std::string name;
  } found;
  H5DSiterate_scales(
    ds, k, NULL,
    [](hid_t, unsigned, hid_t scale, void *data) -> herr_t {
      char buf[256] = "";
      H5Iget_name(scale, buf, sizeof buf);
      static_cast<Found *>(data)->name = buf;
      return 1;
    },
    &found);
  H5Dclose(ds);
  return found.name;
}

TEST(H5Dims, CoordinatesAndDimensionsWithoutValues)
{
  const hid_t f = (hid_t)H5MemoryFileCreate();
  ASSERT_GE(f, 0);
  const hid_t g = H5Gcreate2(f, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_EQ(0, H5WriteDataset1D(g, "time", {0.0, 1e-3}, "s"));
  ASSERT_EQ(0, H5WriteDataset1D(g, "x", {0.0, 0.5, 1.0}, "m"));
  ASSERT_EQ(0, H5WriteDataset2D(g, "y", {{1, 2, 3}, {4, 5, 6}}, "m, [time][node]"));
  ASSERT_EQ(0, H5WriteDataset2D(g, "bed", {{1, 2, 3, 4}, {5, 6, 7, 8}}, "m"));
  ASSERT_EQ(0, H5DimsAttach(g, "y", {"time", "x"}));
  ASSERT_EQ(0, H5DimsAttach(g, "bed", {"time", "bed_point"}));
  ASSERT_EQ(0, H5DimsTable(g, "time"));
  EXPECT_EQ("/snapshots/time", AxisDimension(g, "y", 0));
  EXPECT_EQ("/snapshots/x", AxisDimension(g, "y", 1));
  EXPECT_EQ("/bed_point", AxisDimension(g, "bed", 1)); // no values in the group: at the root
  EXPECT_GT(H5DSis_scale(H5Dopen2(g, "x", H5P_DEFAULT)), 0);
  // the root's dimension: netCDF's marker, the axis's length, no data stored
  const hid_t d = H5Dopen2(f, "bed_point", H5P_DEFAULT);
  char        label[128] = "";
  H5DSget_scale_name(d, label, sizeof label);
  EXPECT_EQ(0, std::string(label).find("This is a netCDF dimension but not a netCDF variable."));
  hsize_t n = 0;
  H5Sget_simple_extent_dims(H5Dget_space(d), &n, NULL);
  EXPECT_EQ(4u, n);
  EXPECT_EQ(0u, H5Dget_storage_size(d));
  H5Dclose(d);
  // a dataset whose axis disagrees with the dimension of that name is refused
  ASSERT_EQ(0, H5WriteDataset1D(g, "short", {1.0}, "m"));
  PetscPushErrorHandler(PetscIgnoreErrorHandler, NULL);
  EXPECT_EQ(PETSC_ERR_PLIB, H5DimsAttach(g, "short", {"x"}));       // the coordinate x has 3 values
  EXPECT_EQ(PETSC_ERR_PLIB, H5DimsAttach(g, "short", {"bed_point"})); // the root's has 4
  PetscPopErrorHandler();
  H5Gclose(g);
  H5Fclose(f);
}

TEST(Xdmf, PathBesideTheFile)
{
  EXPECT_EQ("out.xmf", XdmfPathFor("out.h5"));
  EXPECT_EQ("a/b.xmf", XdmfPathFor("a/b.hdf5"));
  EXPECT_EQ("run.v2/out.xmf", XdmfPathFor("run.v2/out")); // a dot in a directory is no extension
  EXPECT_EQ("out.dat.xmf", XdmfPathFor("out.dat"));
}

TEST(Xdmf, TimesExactAndItsMarker)
{
  XdmfField f;
  f.name = "beam", f.attribute = "y", f.x = "/snapshots/x", f.nx = 3, f.values = "/snapshots/y";
  const std::vector<double> times = {0.001, 0.1 + 0.2};
  const std::string         text  = XdmfTimeSeries("a&b.h5", times, {f});
  EXPECT_NE(std::string::npos, text.find("<Time Value=\"0.001\"/>"));
  EXPECT_NE(std::string::npos, text.find("<Time Value=\"0.30000000000000004\"/>")); // reads back as 0.1 + 0.2
  EXPECT_NE(std::string::npos, text.find("a&amp;b.h5:/snapshots/y|1 0:1 1:1 3:2 3")); // row 1 of [2][3]
  const std::string ours = "test_fields_ours.xmf", other = "test_fields_other.xmf";
  std::ofstream(ours) << text;
  std::ofstream(other) << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\"><Domain/></Xdmf>\n";
  EXPECT_TRUE(XdmfFileOurs(ours));
  EXPECT_FALSE(XdmfFileOurs(other));
  EXPECT_FALSE(XdmfFileOurs("test_fields_absent.xmf"));
  std::remove(ours.c_str());
  std::remove(other.c_str());
}
