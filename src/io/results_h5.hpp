// HDF5 output of impacts: the columns of the result table (shared by the
// summary line, the file and later sweeps), run attributes, time series and
// snapshots. Files are written by rank 0 of the task's communicator with the
// HDF5 C API (the data are small: one row per impact, 1-D beam snapshots).
#pragma once

#include "io/run_record.hpp"
#include "run/impact.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace beamimpact {

// One quantity of ImpactResult: /results/<name>, one row per impact.
struct ResultColumn {
  const char                              *name;
  const char                              *unit;
  bool                                     integer;
  std::function<double(const ImpactResult &)> get;
};
const std::vector<ResultColumn> &ImpactResultColumns();

// Writes a new file (replacing any): root attributes, /results, and for the
// first result its /events, /series and /snapshots when they hold data.
PetscErrorCode ResultsWriteImpactFile(MPI_Comm comm, const std::string &path, const RunRecord &record, const std::vector<ImpactResult> &results, const BeamParams &beam);

// Small HDF5 helpers (rank 0 only; return negative hid_t/herr_t on failure).
PetscErrorCode H5WriteAttributes(long long loc, const RunRecord &record);
PetscErrorCode H5WriteDataset1D(long long loc, const char *name, const std::vector<double> &v, const char *unit);
PetscErrorCode H5WriteDataset2D(long long loc, const char *name, const std::vector<std::vector<double>> &rows, const char *unit);

} // namespace beamimpact
