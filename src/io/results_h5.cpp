// HDF5 writing of impact results. See results_h5.hpp.
#include "io/results_h5.hpp"

#include <hdf5.h>

#include "io/h5_dims.hpp"
#include "io/text.hpp"
#include "io/xdmf.hpp"
#include "model/string_bed.hpp"
#include "system/structure_part.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace beamimpact {

// An attribute of loc (replaced if present): one value of memory type `mem` stored as
// `file_type`. Every HDF5 call checked, every handle closed on the way out.
static PetscErrorCode WriteScalarAttr(hid_t loc, const char *name, hid_t file_type, hid_t mem, const void *value)
{
  PetscFunctionBeginUser;
  const hid_t space = H5Screate(H5S_SCALAR);
  bool        ok    = space >= 0 && (H5Aexists(loc, name) <= 0 || H5Adelete(loc, name) >= 0);
  const hid_t attr  = ok ? H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
  ok                = attr >= 0 && H5Awrite(attr, mem, value) >= 0;
  if (attr >= 0) ok = H5Aclose(attr) >= 0 && ok;
  if (space >= 0) H5Sclose(space);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write the attribute %s", name);
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteStringAttr(hid_t loc, const char *name, const std::string &value)
{
  PetscFunctionBeginUser;
  const hid_t type = H5Tcopy(H5T_C_S1);
  PetscCheck(type >= 0 && H5Tset_size(type, value.size() > 0 ? value.size() : 1) >= 0 &&
               H5Tset_strpad(type, H5T_STR_NULLTERM) >= 0,
             PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot make the string type of attribute %s", name);
  const PetscErrorCode ierr = WriteScalarAttr(loc, name, type, type, value.size() > 0 ? value.c_str() : "");
  H5Tclose(type);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteNumberAttr(hid_t loc, const char *name, double value)
{
  return WriteScalarAttr(loc, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, &value);
}

static PetscErrorCode WriteIntegerAttr(hid_t loc, const char *name, long long value)
{
  return WriteScalarAttr(loc, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
}

// A string attribute of loc ("" when absent or not a string).
static std::string ReadStringAttr(hid_t loc, const char *name)
{
  std::string value;
  if (H5Aexists(loc, name) <= 0) return value;
  const hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
  if (a < 0) return value;
  const hid_t type = H5Aget_type(a);
  if (type >= 0 && H5Tget_class(type) == H5T_STRING) {
    if (H5Tis_variable_str(type) > 0) {
      char *p = nullptr;
      if (H5Aread(a, type, &p) >= 0 && p) value = p;
      if (p) H5free_memory(p);
    } else {
      std::vector<char> buf(H5Tget_size(type) + 1, 0);
      if (H5Aread(a, type, buf.data()) >= 0) value = buf.data();
    }
  }
  if (type >= 0) H5Tclose(type);
  H5Aclose(a);
  return value;
}

PetscErrorCode ResultsFileInspect(const std::string &path, ResultsFileInfo *info)
{
  struct stat st;

  PetscFunctionBeginUser;
  *info = ResultsFileInfo();
  if (::stat(path.c_str(), &st) != 0) PetscFunctionReturn(0);
  info->exists = true;
  info->size   = (long long)st.st_size;
  H5E_auto2_t func;
  void       *data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); // not HDF5, or no attribute: no message
  if (S_ISREG(st.st_mode) && H5Fis_hdf5(path.c_str()) > 0) {
    info->hdf5       = true;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file >= 0) {
      info->program = ReadStringAttr(file, "program");
      info->task    = ReadStringAttr(file, "task");
      H5Fclose(file);
    }
  }
  H5Eset_auto2(H5E_DEFAULT, func, data);
  PetscFunctionReturn(0);
}

const char *FileKind(unsigned mode)
{
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}
PetscErrorCode H5WriteAttributes(long long loc, const RunRecord &record)
{
  PetscFunctionBeginUser;
  for (auto &kv : record.numbers) PetscCall(WriteNumberAttr((hid_t)loc, kv.first.c_str(), kv.second));
  for (auto &kv : record.integers) PetscCall(WriteIntegerAttr((hid_t)loc, kv.first.c_str(), kv.second));
  for (auto &kv : record.strings) PetscCall(WriteStringAttr((hid_t)loc, kv.first.c_str(), kv.second));
  PetscCall(RunRecordWriteOptionsUsed(loc, record)); // the options read, with units (io/run_record.hpp)
  PetscFunctionReturn(0);
}

// A dataset of `dims` (rank 1 to 3) in memory type `mem`, stored as `file_type`, with its unit (the
// text, attribute unit) and its CF units (attribute units: H5UnitsOf the text).
static PetscErrorCode WriteDataset(hid_t loc, const char *name, hid_t file_type, hid_t mem, const void *data, int rank,
                                   const hsize_t *dims, const char *unit)
{
  PetscFunctionBeginUser;
  const hid_t space = H5Screate_simple(rank, dims, NULL);
  const hid_t ds    = space >= 0 ? H5Dcreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
  bool        empty = false;
  for (int k = 0; k < rank; ++k) empty = empty || dims[k] == 0;
  bool           ok   = ds >= 0 && (empty || H5Dwrite(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  PetscErrorCode ierr = 0;
  if (ok && unit) ierr = WriteStringAttr(ds, "unit", unit);
  if (ok && unit && !ierr) ierr = WriteStringAttr(ds, "units", H5UnitsOf(unit));
  if (ds >= 0) ok = H5Dclose(ds) >= 0 && ok;
  if (space >= 0) H5Sclose(space);
  PetscCall(ierr);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write the dataset %s", name);
  PetscFunctionReturn(0);
}

// A 1-D dataset of n values in memory type `mem`, stored as `file_type`, with its unit.
static PetscErrorCode WriteDataset1D(hid_t loc, const char *name, hid_t file_type, hid_t mem, const void *data,
                                     size_t n, const char *unit)
{
  const hsize_t dims[1] = {n};
  return WriteDataset(loc, name, file_type, mem, data, 1, dims, unit);
}

PetscErrorCode H5WriteDataset1D(long long loc, const char *name, const std::vector<double> &v, const char *unit)
{
  return WriteDataset1D((hid_t)loc, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, v.data(), v.size(), unit);
}

PetscErrorCode H5WriteCounts1D(long long loc, const char *name, const std::vector<double> &v, const char *unit)
{
  PetscFunctionBeginUser;
  PetscCall(H5WriteDataset1D(loc, name, v, unit));
  hid_t ds = H5Dopen2((hid_t)loc, name, H5P_DEFAULT);
  PetscCheck(ds >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot open dataset %s", name);
  const PetscErrorCode ierr = WriteIntegerAttr(ds, "integer", 1);
  H5Dclose(ds);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode H5WriteDatasetInt1D(long long loc, const char *name, const std::vector<long long> &v, const char *unit)
{
  return WriteDataset1D((hid_t)loc, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, v.data(), v.size(), unit);
}

PetscErrorCode H5WriteText1D(long long loc, const char *name, const std::vector<std::string> &v, const char *unit)
{
  std::vector<const char *> p;
  for (const std::string &s : v) p.push_back(s.c_str());
  PetscFunctionBeginUser;
  const hid_t t = H5Tcopy(H5T_C_S1);
  PetscCheck(t >= 0 && H5Tset_size(t, H5T_VARIABLE) >= 0 && H5Tset_cset(t, H5T_CSET_UTF8) >= 0, PETSC_COMM_SELF,
             PETSC_ERR_LIB, "HDF5: cannot make the string type of dataset %s", name);
  const PetscErrorCode ierr = WriteDataset1D((hid_t)loc, name, t, t, p.data(), p.size(), unit);
  H5Tclose(t);
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

// rows (each of nc values) one after the other, for a dataset [row][...].
static PetscErrorCode FlattenRows(const char *name, const std::vector<std::vector<double>> &rows, size_t nc,
                                  std::vector<double> *flat)
{
  PetscFunctionBeginUser;
  flat->reserve(rows.size() * nc);
  for (auto &r : rows) {
    PetscCheck(r.size() == nc, PETSC_COMM_SELF, PETSC_ERR_PLIB, "ragged rows for dataset %s", name);
    flat->insert(flat->end(), r.begin(), r.end());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode H5WriteDataset2D(long long loc, const char *name, const std::vector<std::vector<double>> &rows,
                                const char *unit)
{
  std::vector<double> flat;
  PetscFunctionBeginUser;
  const hsize_t dims[2] = {rows.size(), rows.empty() ? 0 : rows[0].size()};
  PetscCall(FlattenRows(name, rows, dims[1], &flat));
  PetscCall(WriteDataset((hid_t)loc, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, flat.data(), 2, dims, unit));
  PetscFunctionReturn(0);
}

PetscErrorCode H5WriteDataset3D(long long loc, const char *name, const std::vector<std::vector<double>> &rows,
                                size_t n1, size_t n2, const char *unit)
{
  std::vector<double> flat;
  PetscFunctionBeginUser;
  const hsize_t dims[3] = {rows.size(), n1, n2};
  PetscCall(FlattenRows(name, rows, n1 * n2, &flat));
  PetscCall(WriteDataset((hid_t)loc, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, flat.data(), 3, dims, unit));
  PetscFunctionReturn(0);
}

// /results: one row per result, one dataset per column of the table (the counts as integer
// datasets: every row has a number; NaN where a column does not apply), each with the table's
// description and whether it applies to the scenario.
static PetscErrorCode H5WriteResults(hid_t file, const std::vector<ImpactResult> &results, const Scenario &sc)
{
  PetscFunctionBeginUser;
  hid_t g = H5Gcreate2(file, "results", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  for (const ResultColumn &col : ImpactResultColumns()) {
    if (col.integer) {
      std::vector<long long> v;
      for (auto &r : results) v.push_back((long long)col.Get(r));
      PetscCall(H5WriteDatasetInt1D(g, col.name, v, col.unit));
    } else {
      std::vector<double> v;
      for (auto &r : results) v.push_back(col.Get(r));
      PetscCall(H5WriteDataset1D(g, col.name, v, col.unit));
    }
    RunRecord a;
    a.add("description", col.description);
    a.add("applies", col.Applies(sc) ? 1 : 0);
    a.add("applies_when", col.applies_text);
    hid_t ds = H5Dopen2(g, col.name, H5P_DEFAULT);
    PetscCheck(ds >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot open dataset %s", col.name);
    PetscCall(H5WriteAttributes(ds, a));
    H5Dclose(ds);
  }
  PetscCall(H5DimsTable(g, "impact")); // one row per impact
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// Root attributes of an impact file beside the run record (which holds the impact's scales):
// the table's column order.
static PetscErrorCode H5WriteImpactAttributes(hid_t file)
{
  RunRecord a;

  PetscFunctionBeginUser;
  a.add("results_columns", ImpactResultColumnNames());
  PetscCall(H5WriteAttributes(file, a));
  PetscFunctionReturn(0);
}

// /events of one run. A quantity that does not apply to an event is NaN, not a number a reader
// could take for a value: the approach speed except at contact starts, the wall COR and the
// unloading exponent except at contact starts of the hysteretic law (n > 0).
static PetscErrorCode H5WriteEvents(hid_t file, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  const double           nan = std::numeric_limits<double>::quiet_NaN();
  hid_t                  ge  = H5Gcreate2(file, "events", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double>    t, c, f, va, cor, n;
  std::vector<long long> kind;
  for (auto &e : r.events) {
    const bool start = (int)e.kind == 0, law = start && e.n > 0;
    t.push_back(e.time);
    kind.push_back((long long)e.kind);
    c.push_back(e.compression);
    f.push_back(e.force);
    va.push_back(start ? e.approach_speed : nan);
    cor.push_back(law ? e.cor : nan);
    n.push_back(law ? e.n : nan);
  }
  PetscCall(H5WriteDataset1D(ge, "time", t, "s"));
  PetscCall(H5WriteDatasetInt1D(ge, "kind", kind, "0 contact, 1 max_compression, 2 reload, 3 separation"));
  PetscCall(H5WriteDataset1D(ge, "compression", c, "m"));
  PetscCall(H5WriteDataset1D(ge, "force", f, "N"));
  PetscCall(H5WriteDataset1D(ge, "approach_speed", va, "m/s (contact starts; NaN on other events)"));
  PetscCall(
    H5WriteDataset1D(ge, "cor", cor,
                     "1, wall COR used for this contact (contact starts of the hysteretic law; NaN otherwise)"));
  PetscCall(H5WriteDataset1D(ge, "n", n,
                             "1, unloading exponent used for this contact (contact starts of the hysteretic law; NaN "
                             "otherwise)"));
  PetscCall(H5DimsTable(ge, "event"));
  H5Gclose(ge);
  PetscFunctionReturn(0);
}

// /modes_energy of one run whose free flight was modal (none otherwise): one row per kept mode,
// the energy it carries at the end, its fraction of the incident kinetic energy, its frequency
// and whether it is rigid (a free beam's two: translation, then rotation about the centre of mass).
static PetscErrorCode H5WriteModeEnergies(hid_t file, const ImpactResult &r)
{
  PetscFunctionBeginUser;
  if (r.mode_energies.empty()) PetscFunctionReturn(0);
  hid_t                    g = H5Gcreate2(file, "modes_energy", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double>      f, e, x;
  std::vector<long long>   rigid;
  std::vector<std::string> part;
  for (const ModeEnergy &m : r.mode_energies) {
    f.push_back(m.frequency);
    e.push_back(m.energy);
    x.push_back(m.fraction);
    rigid.push_back(m.rigid ? 1 : 0);
    part.push_back(m.part);
  }
  PetscCall(H5WriteDataset1D(g, "frequency", f, "Hz (0 for a rigid mode)"));
  PetscCall(H5WriteDataset1D(g, "energy", e, "J, 1/2 (zd^2 + w^2 z^2) in mass-normalised coordinates at the end"));
  PetscCall(H5WriteDataset1D(g, "fraction", x,
                             "1 (of the energy brought in, E_in: the ball's and a swinging bat's kinetic energy)"));
  PetscCall(H5WriteDatasetInt1D(g, "rigid", rigid,
                                "1 for a rigid mode (a free beam: translation, then rotation about the centre of mass, "
                                "then the roll), else 0"));
  PetscCall(H5WriteText1D(g, "part", part,
                          "text: a rigid mode's motion (translation, rotation, roll), a flexible one's part (bending, "
                          "roll, wall, strings); each label's modes add up to "
                          "translation_, rotation_, roll_, vibration_, twist_, wall_ and bed_fraction"));
  RunRecord a;
  a.add("time", (double)r.final_time);
  a.add("description", "the energy each kept mode carries at the end of the run (time, s), after the ball has left "
                       "(docs/model.md section 12)");
  PetscCall(H5WriteAttributes(g, a));
  PetscCall(H5DimsTable(g, "mode"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// /series of one run (the requested ones only): each on the steps' time (coordinate time), the
// flight's on flight_time, velocity_at on (velocity_at_x, time).
static PetscErrorCode H5WriteSeries(hid_t file, const ImpactSeries &S)
{
  PetscFunctionBeginUser;
  bool any = !S.time.empty(); // a flight's series may come without the steps'
  for (const ImpactSeries::Keyed &k : S.keyed) any = any || !k.values.empty();
  if (!any) PetscFunctionReturn(0);
  hid_t gs  = H5Gcreate2(file, "series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  auto  opt = [&](const char *name, const std::vector<double> &v, const char *unit) -> PetscErrorCode {
    PetscFunctionBeginUser;
    if (!v.empty()) PetscCall(H5WriteDataset1D(gs, name, v, unit));
    PetscFunctionReturn(0);
  };
  PetscCall(opt("time", S.time, "s"));
  PetscCall(opt("ball_y", S.ball_y, "m"));
  PetscCall(opt("ball_v", S.ball_v, "m/s"));
  PetscCall(opt("compression", S.compression, "m"));
  PetscCall(opt("force", S.force, "N"));
  PetscCall(opt("ball_kinetic", S.ball_kinetic, "J"));
  PetscCall(opt("ball_stored", S.ball_stored, "J"));
  PetscCall(opt("ball_dissipated", S.ball_dissipated, "J"));
  PetscCall(opt("beam_kinetic", S.beam_kinetic, "J"));
  PetscCall(opt("beam_strain", S.beam_strain, "J"));
  for (size_t a = 0; a < S.account_energy.size(); ++a) // a part's account's (StructurePart::AccountSeries)
    if (const StructurePart *p = StructureAccountPart((PetscInt)a))
      PetscCall(opt(p->AccountSeries(), S.account_energy[a], "J"));
  PetscCall(opt("beam_dissipated", S.beam_dissipated, "J"));
  PetscCall(opt("total_energy", S.total_energy, "J"));
  if (!S.velocity_at.empty()) {
    PetscCall(H5WriteDataset2D(gs, "velocity_at", S.velocity_at, "m/s, [point][step]"));
    PetscCall(H5WriteDataset1D(gs, "velocity_at_x", S.velocity_at_x, "m"));
    PetscCall(H5DimsAttach(gs, "velocity_at", {"velocity_at_x", "time"}));
  }
  PetscCall(opt("segment_kinetic", S.segment_kinetic, "J"));
  for (const ImpactSeries::Keyed &k : S.keyed) { // the parts' and the stages' (a flight's on its own time axis)
    PetscCall(opt(k.name.c_str(), k.values, k.unit.c_str()));
    if (!k.dim.empty() && !k.values.empty()) PetscCall(H5DimsAttach(gs, k.name.c_str(), {k.dim.c_str()}));
  }
  PetscCall(H5DimsTable(gs, "time"));
  H5Gclose(gs);
  PetscFunctionReturn(0);
}

// The grid of the face a part's snapshot lies on (StructurePart::FaceGrid); false without.
static bool SnapshotFaceGrid(const ImpactSeries::PartSnapshots &p, const BeamParams &beam, BedGrid *g)
{
  const PartParams *q = beam.parts.Find(p.part->Name());
  return q && p.part->FaceGrid(*q, beam, g);
}

// /snapshots of one run: the nodes x, the times and the deflection y [time][x]; each present
// part's own field as its spec lays it out (StructurePart::Snapshot): [time][label][x] with its
// labels' dataset (the barrel wall's W_n, wall_n), or [time][point] on its face's grid (the string
// bed's deflection on bed_x, bed_z, point = z * len(bed_x) + x).
static PetscErrorCode H5WriteSnapshots(hid_t file, const ImpactSeries &S, const BeamParams &beam)
{
  PetscFunctionBeginUser;
  if (S.snapshot_time.empty()) PetscFunctionReturn(0);
  hid_t               gn = H5Gcreate2(file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double> x(beam.nodes);
  for (PetscInt i = 0; i < beam.nodes; ++i) x[i] = beam.length * i / (beam.nodes - 1);
  PetscCall(H5WriteDataset1D(gn, "x", x, "m"));
  PetscCall(H5WriteDataset1D(gn, "time", S.snapshot_time, "s"));
  PetscCall(H5WriteDataset2D(gn, "y", S.snapshot_y, "m, [time][node]"));
  PetscCall(H5DimsAttach(gn, "y", {"time", "x"}));
  for (const ImpactSeries::PartSnapshots &p : S.snapshot_parts) {
    const PartSnapshotSpec &f = p.spec;
    BedGrid                 face;
    if (f.labels && !p.labels.empty()) { // [time][label][node]
      std::vector<double> n(p.labels.begin(), p.labels.end());
      PetscCall(H5WriteDataset1D(gn, f.labels, n, f.labels_description));
      PetscCall(H5WriteDataset3D(gn, f.name, p.values, n.size(), (size_t)beam.nodes, f.description));
      PetscCall(H5DimsAttach(gn, f.name, {"time", f.labels, "x"}));
    } else if (!f.labels && SnapshotFaceGrid(p, beam, &face)) { // [time][point] on its face's grid
      PetscCall(H5WriteBedGrid(gn, face, f.face_x, f.face_z));
      PetscCall(H5WriteDataset2D(gn, f.name, p.values, f.description));
      PetscCall(H5DimsAttach(gn, f.name, {"time", f.face_point}));
      for (const char *axis : {f.face_x, f.face_z}) PetscCall(H5DimsAttach(gn, axis, {axis})); // its coordinates
    }
  }
  PetscCall(H5DimsTable(gn, "time"));
  H5Gclose(gn);
  PetscFunctionReturn(0);
}

// The XDMF description of what H5WriteSnapshots writes ("" without snapshots), for the file at path.
static std::string SnapshotsXdmf(const std::string &path, const ImpactSeries &S, const BeamParams &beam)
{
  if (S.snapshot_time.empty()) return std::string();
  std::vector<XdmfField> fields;
  XdmfField              f;
  f.name = "beam", f.attribute = "y", f.x = "/snapshots/x", f.nx = beam.nodes, f.values = "/snapshots/y";
  fields.push_back(f);
  for (const ImpactSeries::PartSnapshots &p : S.snapshot_parts) {
    const std::string at = std::string("/snapshots/") + p.spec.name;
    BedGrid           g;
    f      = XdmfField();
    f.name = p.spec.name, f.attribute = p.spec.attribute, f.values = at;
    if (p.spec.labels && !p.labels.empty()) { // on the nodes x, one row a label
      f.x = "/snapshots/x", f.y = std::string("/snapshots/") + p.spec.labels, f.nx = beam.nodes;
      f.ny = (PetscInt)p.labels.size(), f.flat = false;
    } else if (!p.spec.labels && SnapshotFaceGrid(p, beam, &g)) { // on its face's grid
      f.x = std::string("/snapshots/") + p.spec.face_x, f.y = std::string("/snapshots/") + p.spec.face_z;
      f.nx = g.nx, f.ny = g.nz;
    } else continue;
    fields.push_back(f);
  }
  const size_t slash = path.find_last_of('/');
  return XdmfTimeSeries(slash == std::string::npos ? path : path.substr(slash + 1), S.snapshot_time, fields);
}

namespace {

bool FsyncDirectoryOf(const std::string &path)
{
  const size_t      s   = path.find_last_of('/');
  const std::string dir = s == std::string::npos ? std::string(".") : s == 0 ? std::string("/") : path.substr(0, s);
  const int         fd  = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;
  ::close(fd);
  return ok;
}

// Bytes written to path (created or truncated) with checked write(2) calls and an fsync: "" on
// success, else what went wrong.
std::string SaveBytes(const std::string &path, const char *data, size_t size)
{
  std::string error;
  // Not through a link, not blocking on a FIFO; and only into a regular file (a device opens)
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
  if (fd < 0) return "cannot open " + path + " (" + std::strerror(errno) + ")";
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return path + " is not a regular file; nothing was written into it";
  }
  for (size_t done = 0; done < size && error.empty();) {
    const ssize_t w = ::write(fd, data + done, size - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) error = "writing " + path + " failed (" + std::strerror(w < 0 ? errno : ENOSPC) + ")";
    else done += (size_t)w;
  }
  if (error.empty() && ::fsync(fd) != 0) error = "fsync of " + path + " failed (" + std::strerror(errno) + ")";
  if (::close(fd) != 0 && error.empty()) error = "closing " + path + " failed (" + std::strerror(errno) + ")";
  return error;
}

// A new unique temporary file beside path, path.XXXXXX.tmp (the rename onto path stays on one
// file system), with the permissions a plain create gives, in *tmp: "" on success, else what
// went wrong.
std::string MakeTemporaryBeside(const std::string &path, std::string *tmp)
{
  std::string name = path + ".XXXXXX.tmp";
  const int   fd   = ::mkstemps(name.data(), 4);
  if (fd < 0) return "cannot create a temporary file " + name + " beside it (" + std::strerror(errno) + ")";
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask); // as a plain create would (mkstemp makes 0600)
  ::close(fd);
  *tmp = name;
  return "";
}

// Rank 0's part of H5ResultsFileWrite: "" on success, else what went wrong.
std::string WriteWholeFile(const std::string &path, const RunRecord &record,
                           const std::function<PetscErrorCode(long long)> &write, const std::string &xdmf)
{
  H5ErrorsQuiet quiet;
  std::string   error;
  const hid_t   file = (hid_t)H5MemoryFileCreate();
  if (file < 0) return "HDF5 cannot create a file in memory";
  PetscErrorCode ierr = H5WriteAttributes(file, record);
  if (!ierr) ierr = write(file);
  if (ierr) error = LastErrorMessage(ierr);
  return H5MemoryFileInstall(file, path, "", error, xdmf);
}

} // namespace

long long H5MemoryFileCreate()
{
  const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl < 0) return -1;
  // The core driver without a backing store: nothing reaches the disk but H5MemoryFileSave's
  // checked writes, so a full disk is never a close that fails inside HDF5 (which left a file
  // open that crashed the program at exit).
  // The close degree strong: closing the file also closes what an error path left open.
  static int        count = 0;
  const std::string name  = "beamimpact-memory-" + std::to_string(++count) + ".h5"; // a name, never a path on disk
  const bool        ok   = H5Pset_fapl_core(fapl, 1 << 16, 0) >= 0 && H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) >= 0;
  const hid_t       file = ok ? H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl) : -1;
  H5Pclose(fapl);
  return file;
}

std::string H5MemoryFileSave(long long file_in, const std::string &path)
{
  const hid_t       file = (hid_t)file_in;
  std::vector<char> image;
  std::string       error;
  if (!path.empty()) {
    const ssize_t n = H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0 ? H5Fget_file_image(file, NULL, 0) : -1;
    if (n > 0) image.resize((size_t)n);
    if (n <= 0 || H5Fget_file_image(file, image.data(), image.size()) != n) error = "HDF5 cannot make the file's image";
  }
  if (H5Fclose(file) < 0 && error.empty() && !path.empty()) error = "HDF5 cannot close the file in memory";
  if (path.empty() || !error.empty()) return error;
  return SaveBytes(path, image.data(), image.size());
}

std::string H5MemoryFileInstall(long long file, const std::string &path, const std::string &tmp_in,
                                const std::string &error_in, const std::string &xdmf)
{
  std::string       error = error_in, tmp = tmp_in, xtmp;
  const std::string xpath = XdmfPathFor(path);
  if (error.empty() && !xdmf.empty()) { // the description first: a full disk shows before the file is replaced
    error = MakeTemporaryBeside(xpath, &xtmp);
    if (error.empty()) error = SaveBytes(xtmp, xdmf.data(), xdmf.size());
  }
  if (error.empty() && tmp_in.empty()) error = MakeTemporaryBeside(path, &tmp);
  const std::string saved = H5MemoryFileSave(file, error.empty() ? tmp : std::string()); // closes the file in any case
  const bool        made  = error.empty();
  if (error.empty()) error = saved;
  struct stat st; // what path (and its description) names now (-output was checked at the start: a sweep may have run
                  // for hours since)
  if (error.empty() && ::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    error = std::string("it is now ") + FileKind(st.st_mode) + ", not a regular file, and is not replaced";
  if (error.empty() && !xtmp.empty() && ::lstat(xpath.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    error = xpath + " is now " + FileKind(st.st_mode) + ", not a regular file, and is not replaced";
  if (error.empty() && std::rename(tmp.c_str(), path.c_str()) != 0)
    error = "cannot rename " + tmp + " onto it (" + std::strerror(errno) + ")";
  if (made && !error.empty()) ::unlink(tmp.c_str());
  if (!xtmp.empty()) { // the file's description onto its place after the file
    if (error.empty() && std::rename(xtmp.c_str(), xpath.c_str()) != 0)
      error = "cannot rename " + xtmp + " onto " + xpath + " (" + std::strerror(errno) + ")";
    if (!error.empty()) ::unlink(xtmp.c_str());
  } else if (error.empty() && XdmfFileOurs(xpath)) ::unlink(xpath.c_str()); // it described the file replaced
  if (error.empty()) FsyncDirectoryOf(path);
  return error;
}

std::string WriteFailureCause(const std::string &error)
{
  const bool full = error.find(std::strerror(ENOSPC)) != std::string::npos ||
                    error.find(std::strerror(EDQUOT)) != std::string::npos;
  return (full ? "disk full: " : "") + error;
}

H5ErrorsQuiet::H5ErrorsQuiet()
{
  H5E_auto2_t f;
  H5Eget_auto2(H5E_DEFAULT, &f, &data_);
  func_ = reinterpret_cast<void (*)()>(f);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

H5ErrorsQuiet::~H5ErrorsQuiet() { H5Eset_auto2(H5E_DEFAULT, reinterpret_cast<H5E_auto2_t>(func_), data_); }

PetscErrorCode H5ResultsFileWrite(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                  const std::function<PetscErrorCode(long long file)> &write, const std::string &xdmf)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  const std::string error = WriteWholeFile(path, record, write, xdmf);
  PetscCheck(error.empty(), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE,
             "-output %s could not be written (%s); nothing was written there, a file it held before is unchanged",
             path.c_str(), WriteFailureCause(error).c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteImpactFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                      const std::vector<ImpactResult> &results, const Scenario &sc)
{
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(
    comm, path, record,
    [&](long long file) -> PetscErrorCode {
      PetscFunctionBeginUser;
      PetscCall(H5WriteResults(file, results, sc));
      if (!results.empty()) {
        PetscCall(H5WriteImpactAttributes(file));
        PetscCall(H5WriteEvents(file, results[0]));
        PetscCall(H5WriteSeries(file, results[0].series));
        PetscCall(H5WriteSnapshots(file, results[0].series, sc.beam));
        PetscCall(H5WriteModeEnergies(file, results[0]));
      }
      PetscFunctionReturn(0);
    },
    results.empty() ? std::string() : SnapshotsXdmf(path, results[0].series, sc.beam)));
  PetscFunctionReturn(0);
}

// /beam: node positions and the section there (EI, mu; D and d of a profile).
static PetscErrorCode H5WriteBeamSection(hid_t file, const BeamParams &beam)
{
  const PetscInt         N = beam.nodes;
  const PetscReal        h = beam.length / (N - 1);
  std::vector<PetscReal> x(N), EI(N), mu(N), D, d;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < N; ++i) {
    const SectionProperties s = BeamSectionAt(beam, i * h);
    x[i] = i * h, EI[i] = s.EI, mu[i] = s.mu;
  }
  hid_t g = H5Gcreate2(file, "beam", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCall(H5WriteDataset1D(g, "x", x, "m"));
  PetscCall(H5WriteDataset1D(g, "EI", EI, "N m^2"));
  PetscCall(H5WriteDataset1D(g, "mu", mu, "kg/m"));
  if (beam.section.source == SectionSource::Profile) {
    x.clear();
    for (const ProfileRow &r : beam.section.profile) x.push_back(r.x), D.push_back(r.D), d.push_back(r.d);
    PetscCall(H5WriteDataset1D(g, "profile_x", x, "m"));
    PetscCall(H5WriteDataset1D(g, "profile_D", D, "m"));
    PetscCall(H5WriteDataset1D(g, "profile_d", d, "m"));
    for (const char *name : {"profile_D", "profile_d"}) PetscCall(H5DimsAttach(g, name, {"profile_x"}));
  }
  PetscCall(H5DimsTable(g, "x"));
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode H5WriteBedGrid(long long loc, const BedGrid &g, const char *x_name, const char *z_name)
{
  std::vector<double> x(g.nx), z(g.nz);
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < g.nx; ++i) x[i] = g.X(i);
  for (PetscInt j = 0; j < g.nz; ++j) z[j] = g.Z(j);
  PetscCall(H5WriteDataset1D(loc, x_name, x, "m (along the frame's axis, from the head's centre)"));
  PetscCall(H5WriteDataset1D(loc, z_name, z, "m (across the face, from the head's centre)"));
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteModesFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                     const ModesResult &modes, const std::vector<std::vector<PetscReal>> &shapes,
                                     const BeamParams &beam)
{
  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileWrite(comm, path, record, [&](long long file) -> PetscErrorCode {
    PetscFunctionBeginUser;
    hid_t g = H5Gcreate2(file, "modes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCall(H5WriteDataset1D(g, "frequency", modes.frequency, "Hz"));
    PetscCall(H5WriteDataset1D(g, "period", modes.period, "s"));
    PetscCall(H5WriteDataset1D(g, "omega", modes.omega, "rad/s"));
    PetscCall(H5WriteDataset2D(g, "shapes", shapes, "1 (deflection, normalised over all dofs)"));
    if (!modes.shell_n.empty()) { // a barrel wall: each mode's family (0 bending, n a shell harmonic)
      std::vector<PetscReal> fam(modes.shell_n.begin(), modes.shell_n.end());
      PetscCall(
        H5WriteDataset1D(g, "shell_n", fam,
                         "1 (0: the beam's bending; n: the wall's harmonic cos n theta; 2: the hoop oscillator)"));
    }
    if (!modes.part.empty()) { // a roll field or a string bed: each mode's part and its share of the kinetic energy
      std::vector<PetscReal> part(modes.part.begin(), modes.part.end());
      PetscCall(H5WriteDataset1D(g, "part", part,
                                 "1 (the part with most of the mode's kinetic energy: 0 the frame's bending, 1 its "
                                 "roll, 3 the string bed)"));
      PetscCall(
        H5WriteDataset1D(g, "part_share", modes.part_share, "1 (that part's share of the mode's kinetic energy)"));
    }
    BedGrid g2; // the string bed's deflection of each mode on its grid, [z][x], as the held bed's /modes/shape_k
    if (!modes.bed_shape.empty() && StructurePartsFaceGrid(beam, &g2)) {
      PetscCall(H5WriteBedGrid(g, g2, "bed_x", "bed_z"));
      for (size_t m = 0; m < modes.bed_shape.size(); ++m) {
        std::vector<std::vector<PetscReal>> rows(g2.nz, std::vector<PetscReal>(g2.nx));
        for (PetscInt j = 0; j < g2.nz; ++j)
          for (PetscInt i = 0; i < g2.nx; ++i) rows[j][i] = modes.bed_shape[m][j * g2.nx + i];
        const std::string name = "bed_shape_" + std::to_string(m + 1);
        PetscCall(H5WriteDataset2D(g, name.c_str(), rows, "1 (the bed's deflection, [z][x], normalised as shapes)"));
        PetscCall(H5DimsAttach(g, name.c_str(), {"bed_z", "bed_x"}));
      }
    }
    const PetscReal h = beam.length / (beam.nodes - 1);
    for (size_t m = modes.rigid_count, k = 1; m < shapes.size() && k <= 2; ++m) // the first two bending modes
      if ((modes.shell_n.empty() || modes.shell_n[m] == 0) && (modes.part.empty() || modes.part[m] == 0))
        PetscCall(H5WriteDataset1D(g, k++ == 1 ? "nodes_1" : "nodes_2", ModeNodes(shapes[m], h), "m"));
    for (const char *name : {"nodes_1", "nodes_2"}) // positions of a mode's nodes: each its own coordinate
      if (H5Lexists(g, name, H5P_DEFAULT) > 0) PetscCall(H5DimsAttach(g, name, {name}));
    PetscCall(H5DimsAttach(g, "shapes", {"mode", "node"})); // node: the nodes of /beam/x
    PetscCall(H5DimsTable(g, "mode"));
    H5Gclose(g);
    PetscCall(H5WriteBeamSection(file, beam));
    PetscFunctionReturn(0);
  }));
  PetscFunctionReturn(0);
}

} // namespace beamimpact
