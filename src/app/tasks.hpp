// The tasks the executable runs (-task impact|modes|sweep|convergence): each reads its
// modules' options, runs on the communicator it is given, prints a summary on its rank 0
// and writes one HDF5 file. The sweep and the convergence study live in src/studies.
#pragma once

#include "run/impact.hpp"
#include "run/scenario.hpp"

#include <petscsys.h>

#include <string>

namespace beamimpact {

// Reads -task and -output (default <task>.h5; "none": no file) and runs the task.
PetscErrorCode RunTask(MPI_Comm comm);

PetscErrorCode TaskImpact(MPI_Comm comm, const std::string &output);
PetscErrorCode TaskModes(MPI_Comm comm, const std::string &output);

// One summary line of an impact.
PetscErrorCode ImpactPrintSummary(MPI_Comm comm, const Scenario &sc, const ImpactResult &r);

} // namespace beamimpact
