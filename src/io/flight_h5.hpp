// The results file of -task flight (docs/flight.md, "Output"): the run record as root
// attributes (program, provenance, options, every -flight_* and -air_* value used, the air
// density and the constant K, the integrator), /results (one row: distance, apex, hang_time,
// landing speed and angle, landing point and bearing, the integrator's counts), and /series
// (the sampled trajectory), each dataset with its unit attribute. Written by rank 0.
#pragma once

#include "io/run_record.hpp"
#include "model/flight.hpp"
#include "solvers/flight_ts.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// A column of the flight's /results (one row), defined once: the file and the results
// reference (docs/results.md, beamimpact -help_markdown results) follow this table.
struct FlightResultColumn {
  const char *name;
  const char *unit;        // "1": dimensionless
  const char *description; // one line
  bool        integer;     // a count: an integer dataset
  double (*get)(const FlightResult &r);
};
const std::vector<FlightResultColumn> &FlightResultColumns();

// Program and provenance, the parameters of the flight as used and what the run derived.
PetscErrorCode FlightRunRecordBuild(const FlightParams &p, const FlightModel &m, const FlightSolveParams &s,
                                    const FlightResult &r, RunRecord *rec);

// Writes a new file (replacing any) on rank 0 of comm.
PetscErrorCode ResultsWriteFlightFile(MPI_Comm comm, const std::string &path, const RunRecord &record,
                                      const FlightResult &r);

} // namespace beamimpact
