// HDF5 writing of impact results. See results_h5.hpp.
#include "io/results_h5.hpp"

#include <hdf5.h>

#include <limits>
#include <unistd.h>

namespace beamimpact {

static PetscErrorCode WriteStringAttr(hid_t loc, const char *name, const std::string &value)
{
  PetscFunctionBeginUser;
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size() > 0 ? value.size() : 1);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(loc, name) > 0) H5Adelete(loc, name);
  hid_t attr = H5Acreate2(loc, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(attr >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create attribute %s", name);
  H5Awrite(attr, type, value.size() > 0 ? value.c_str() : "");
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  PetscFunctionReturn(0);
}

// A scalar attribute (replaced if present) of memory type `mem`, stored as `file_type`.
static PetscErrorCode WriteScalarAttr(hid_t loc, const char *name, hid_t file_type, hid_t mem, const void *value)
{
  PetscFunctionBeginUser;
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(loc, name) > 0) H5Adelete(loc, name);
  hid_t attr = H5Acreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(attr >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create attribute %s", name);
  H5Awrite(attr, mem, value);
  H5Aclose(attr);
  H5Sclose(space);
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

PetscErrorCode ResultsFileTask(const std::string &path, std::string *task)
{
  PetscFunctionBeginUser;
  task->clear();
  if (access(path.c_str(), F_OK) != 0) PetscFunctionReturn(0);
  H5E_auto2_t func;
  void       *data;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); // not HDF5, or no attribute: no message
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file >= 0) {
    hid_t a = H5Aopen(file, "task", H5P_DEFAULT);
    if (a >= 0) {
      hid_t type = H5Aget_type(a);
      if (H5Tis_variable_str(type) > 0) {
        char *s = nullptr;
        if (H5Aread(a, type, &s) >= 0 && s) *task = s;
        if (s) H5free_memory(s);
      } else {
        std::vector<char> buf(H5Tget_size(type) + 1, 0);
        if (H5Aread(a, type, buf.data()) >= 0) *task = buf.data();
      }
      H5Tclose(type);
      H5Aclose(a);
    }
    H5Fclose(file);
  }
  H5Eset_auto2(H5E_DEFAULT, func, data);
  PetscFunctionReturn(0);
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

// A 1-D dataset of n values in memory type `mem`, stored as `file_type`, with its unit.
static PetscErrorCode WriteDataset1D(hid_t loc, const char *name, hid_t file_type, hid_t mem, const void *data, size_t n, const char *unit)
{
  PetscFunctionBeginUser;
  hsize_t dims[1] = {n};
  hid_t   space   = H5Screate_simple(1, dims, NULL);
  hid_t   ds      = H5Dcreate2(loc, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(ds >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create dataset %s", name);
  if (n > 0) H5Dwrite(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (unit) PetscCall(WriteStringAttr(ds, "unit", unit));
  H5Dclose(ds);
  H5Sclose(space);
  PetscFunctionReturn(0);
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
  PetscCall(WriteIntegerAttr(ds, "integer", 1));
  H5Dclose(ds);
  PetscFunctionReturn(0);
}

PetscErrorCode H5WriteDatasetInt1D(long long loc, const char *name, const std::vector<long long> &v, const char *unit)
{
  return WriteDataset1D((hid_t)loc, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, v.data(), v.size(), unit);
}

PetscErrorCode H5WriteDataset2D(long long loc, const char *name, const std::vector<std::vector<double>> &rows, const char *unit)
{
  PetscFunctionBeginUser;
  const size_t        nr = rows.size(), nc = nr ? rows[0].size() : 0;
  std::vector<double> flat;
  flat.reserve(nr * nc);
  for (auto &r : rows) {
    PetscCheck(r.size() == nc, PETSC_COMM_SELF, PETSC_ERR_PLIB, "ragged rows for dataset %s", name);
    flat.insert(flat.end(), r.begin(), r.end());
  }
  hsize_t dims[2] = {nr, nc};
  hid_t   space   = H5Screate_simple(2, dims, NULL);
  hid_t   ds      = H5Dcreate2((hid_t)loc, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(ds >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create dataset %s", name);
  if (!flat.empty()) H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, flat.data());
  if (unit) PetscCall(WriteStringAttr(ds, "unit", unit));
  H5Dclose(ds);
  H5Sclose(space);
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
    a.add("applies", col.applies(sc) ? 1 : 0);
    a.add("applies_when", col.applies_text);
    hid_t ds = H5Dopen2(g, col.name, H5P_DEFAULT);
    PetscCheck(ds >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot open dataset %s", col.name);
    PetscCall(H5WriteAttributes(ds, a));
    H5Dclose(ds);
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

// Root attributes of an impact file beside the run record: the table's column order and the
// impact's scales (for studies that judge a run against them).
static PetscErrorCode H5WriteImpactAttributes(hid_t file, const ImpactResult &r)
{
  RunRecord a;

  PetscFunctionBeginUser;
  a.add("results_columns", ImpactResultColumnNames());
  a.add("contact_time_scale", r.scales.contact_time_scale);
  a.add("compression_scale", r.scales.compression_scale);
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
  PetscCall(H5WriteDataset1D(ge, "cor", cor, "1, wall COR used for this contact (contact starts of the hysteretic law; NaN otherwise)"));
  PetscCall(H5WriteDataset1D(ge, "n", n, "1, unloading exponent used for this contact (contact starts of the hysteretic law; NaN otherwise)"));
  H5Gclose(ge);
  PetscFunctionReturn(0);
}

// /series (the requested ones only) and /snapshots of one run.
static PetscErrorCode H5WriteSeries(hid_t file, const ImpactSeries &S, const BeamParams &beam)
{
  PetscFunctionBeginUser;
  if (!S.time.empty()) {
    hid_t gs = H5Gcreate2(file, "series", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCall(H5WriteDataset1D(gs, "time", S.time, "s"));
    auto opt = [&](const char *name, const std::vector<double> &v, const char *unit) -> PetscErrorCode {
      PetscFunctionBeginUser;
      if (!v.empty()) PetscCall(H5WriteDataset1D(gs, name, v, unit));
      PetscFunctionReturn(0);
    };
    PetscCall(opt("ball_y", S.ball_y, "m"));
    PetscCall(opt("ball_v", S.ball_v, "m/s"));
    PetscCall(opt("compression", S.compression, "m"));
    PetscCall(opt("force", S.force, "N"));
    PetscCall(opt("ball_kinetic", S.ball_kinetic, "J"));
    PetscCall(opt("ball_stored", S.ball_stored, "J"));
    PetscCall(opt("ball_dissipated", S.ball_dissipated, "J"));
    PetscCall(opt("beam_kinetic", S.beam_kinetic, "J"));
    PetscCall(opt("beam_strain", S.beam_strain, "J"));
    PetscCall(opt("beam_dissipated", S.beam_dissipated, "J"));
    PetscCall(opt("total_energy", S.total_energy, "J"));
    if (!S.velocity_at.empty()) {
      PetscCall(H5WriteDataset2D(gs, "velocity_at", S.velocity_at, "m/s, [point][step]"));
      PetscCall(H5WriteDataset1D(gs, "velocity_at_x", S.velocity_at_x, "m"));
    }
    PetscCall(opt("segment_kinetic", S.segment_kinetic, "J"));
    PetscCall(opt("grip_force", S.grip_force, "N"));
    PetscCall(opt("grip_moment", S.grip_moment, "N m"));
    PetscCall(opt("grip_stored", S.grip_stored, "J"));
    PetscCall(opt("hand_work", S.hand_work, "J"));
    H5Gclose(gs);
  }
  if (!S.snapshot_time.empty()) {
    hid_t               gn = H5Gcreate2(file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> x(beam.nodes);
    for (PetscInt i = 0; i < beam.nodes; ++i) x[i] = beam.length * i / (beam.nodes - 1);
    PetscCall(H5WriteDataset1D(gn, "x", x, "m"));
    PetscCall(H5WriteDataset1D(gn, "time", S.snapshot_time, "s"));
    PetscCall(H5WriteDataset2D(gn, "y", S.snapshot_y, "m, [time][node]"));
    H5Gclose(gn);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode H5ResultsFileCreate(MPI_Comm comm, const std::string &path, const RunRecord &record, long long *file)
{
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  *file = -1;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  *file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(*file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-output %s: cannot create the HDF5 file (directory missing or not writable?)", path.c_str());
  PetscCall(H5WriteAttributes(*file, record));
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteImpactFile(MPI_Comm comm, const std::string &path, const RunRecord &record, const std::vector<ImpactResult> &results, const Scenario &sc)
{
  long long file;

  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileCreate(comm, path, record, &file));
  if (file < 0) PetscFunctionReturn(0);
  PetscCall(H5WriteResults(file, results, sc));
  if (!results.empty()) {
    PetscCall(H5WriteImpactAttributes(file, results[0]));
    PetscCall(H5WriteEvents(file, results[0]));
    PetscCall(H5WriteSeries(file, results[0].series, sc.beam));
  }
  H5Fclose(file);
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
  }
  H5Gclose(g);
  PetscFunctionReturn(0);
}

PetscErrorCode ResultsWriteModesFile(MPI_Comm comm, const std::string &path, const RunRecord &record, const ModesResult &modes, const std::vector<std::vector<PetscReal>> &shapes,
                                     const BeamParams &beam)
{
  long long file;

  PetscFunctionBeginUser;
  PetscCall(H5ResultsFileCreate(comm, path, record, &file));
  if (file < 0) PetscFunctionReturn(0);
  hid_t g = H5Gcreate2(file, "modes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCall(H5WriteDataset1D(g, "frequency", modes.frequency, "Hz"));
  PetscCall(H5WriteDataset1D(g, "period", modes.period, "s"));
  PetscCall(H5WriteDataset1D(g, "omega", modes.omega, "rad/s"));
  PetscCall(H5WriteDataset2D(g, "shapes", shapes, "1 (deflection, normalised over all dofs)"));
  const PetscReal h = beam.length / (beam.nodes - 1);
  for (size_t m = modes.rigid_count, k = 1; m < shapes.size() && k <= 2; ++m, ++k)
    PetscCall(H5WriteDataset1D(g, k == 1 ? "nodes_1" : "nodes_2", ModeNodes(shapes[m], h), "m"));
  H5Gclose(g);
  PetscCall(H5WriteBeamSection(file, beam));
  H5Fclose(file);
  PetscFunctionReturn(0);
}

} // namespace beamimpact
